// Checks shared by the node-to-surface contact tests (solid/node_to_surface_contact.hpp).
#pragma once

#include "brb/solid/node_to_surface_contact.hpp"

#include <Eigen/Core>
#include <gtest/gtest.h>

#include <string>

namespace brb::testing {

/// add_force from zero; fails the test when the contact refuses the state.
inline Eigen::VectorXd contact_force_at(solid::NodeToSurfaceContact& contact,
                                        const Eigen::VectorXd& u) {
  Eigen::VectorXd force = Eigen::VectorXd::Zero(u.size());
  std::string reason;
  EXPECT_TRUE(contact.add_force(u, force, reason)) << reason;
  return force;
}

/// Central differences of the trial stored energy on every DOF against `force` (the force
/// of add_force at u), in stick: step 1e-6 mm, truncation O(1e-12) of the forces; and the
/// interaction's equilibrium (its forces sum to zero).
inline void expect_force_is_the_energy_gradient(solid::NodeToSurfaceContact& contact,
                                                const Eigen::VectorXd& u,
                                                const Eigen::VectorXd& force) {
  const double h = 1e-6;
  Eigen::VectorXd numerical = Eigen::VectorXd::Zero(u.size());
  for (Eigen::Index dof = 0; dof < u.size(); ++dof) {
    Eigen::VectorXd plus = u, minus = u;
    plus[dof] += h;
    minus[dof] -= h;
    contact_force_at(contact, plus);
    ASSERT_EQ(contact.statistics().nodes_slipping, 0);
    const double energy_plus = contact.trial_stored_energy();
    contact_force_at(contact, minus);
    const double energy_minus = contact.trial_stored_energy();
    numerical[dof] = (energy_plus - energy_minus) / (2.0 * h);
  }
  const double largest = force.cwiseAbs().maxCoeff();
  EXPECT_LT((force - numerical).cwiseAbs().maxCoeff(), 1e-7 * largest)
      << "analytic\n"
      << force.transpose() << "\nnumerical\n"
      << numerical.transpose();
  EXPECT_NEAR(force.sum(), 0.0, 1e-9 * largest);
}

} // namespace brb::testing
