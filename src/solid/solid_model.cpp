#include "brb/solid/solid_model.hpp"
#include "brb/model/thread_team.hpp"

#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace brb::solid {

namespace {

struct ElasticModuli {
  double youngs = 0.0;
  double poisson = 0.0;
};

ElasticModuli elastic_moduli(const material::IsotropicElastic3D& law) {
  return {law.youngs_modulus(), law.poissons_ratio()};
}

ElasticModuli elastic_moduli(const material::MortarDamage3D& law) {
  return {law.parameters().youngs_modulus, law.parameters().poissons_ratio};
}

ElasticModuli elastic_moduli(const material::SteelDamagePlasticity3D& law) {
  return {law.parameters().youngs_modulus, law.parameters().poissons_ratio};
}

NodeMatrix gather(const HexConnectivity& nodes, const Eigen::Matrix3Xd& field) {
  NodeMatrix local;
  for (int a = 0; a < 8; ++a)
    local.col(a) = field.col(nodes[a]);
  return local;
}

} // namespace

template <class Law>
SolidModel<Law>::SolidModel(HexMesh mesh, const std::function<Law(double)>& law_for, double density,
                            HourglassControl hourglass)
    : mesh_(std::move(mesh)), density_(density), hourglass_control_(hourglass) {
  if (!(density > 0.0) || !std::isfinite(density))
    throw std::invalid_argument("solid model: density must be finite and > 0 tonne/mm^3 (got " +
                                std::to_string(density) + ")");
  if (!(hourglass.min_scale > 0.0 && hourglass.min_scale <= 1.0))
    throw std::invalid_argument("solid model: the hourglass stiffness floor must be in (0, 1] "
                                "(got " +
                                std::to_string(hourglass.min_scale) + ")");
  const std::size_t n = mesh_.elements.size();
  laws_.reserve(n);
  references_.reserve(n);
  hourglass_.reserve(n);
  dilatational_modulus_.reserve(n);
  shear_modulus_.reserve(n);
  for (std::size_t e = 0; e < n; ++e) {
    try {
      references_.push_back(hex8_reference(gather(mesh_.elements[e], mesh_.nodes)));
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument("solid model: element " + std::to_string(e) + ": " +
                                  error.what());
    }
    laws_.push_back(law_for(std::cbrt(references_.back().volume)));
    const ElasticModuli moduli = elastic_moduli(laws_.back());
    const double shear = moduli.youngs / (2.0 * (1.0 + moduli.poisson));
    const double lambda =
        moduli.youngs * moduli.poisson / ((1.0 + moduli.poisson) * (1.0 - 2.0 * moduli.poisson));
    hourglass_.push_back(hex8_hourglass_stiffness(references_.back(), moduli.youngs, shear));
    dilatational_modulus_.push_back(lambda + 2.0 * shear);
    shear_modulus_.push_back(shear);
    committed_states_.push_back(laws_.back().initial_state());
  }
  hourglass_scale_.assign(n, 1.0);
  if (hourglass_control_.follow_tangent) {
    hourglass_moduli_.resize(n);
    for (std::size_t e = 0; e < n; ++e) {
      const Eigen::Matrix3d& axes = references_[e].axes;
      for (int alpha = 0; alpha < 4; ++alpha)
        hourglass_moduli_[e].col(alpha) =
            (axes.transpose() * hourglass_[e][alpha] * axes).diagonal();
    }
    committed_hourglass_q_.assign(n, HourglassMatrix::Zero());
    trial_hourglass_q_ = committed_hourglass_q_;
    committed_hourglass_P_ = committed_hourglass_q_;
    trial_hourglass_P_ = committed_hourglass_q_;
  }
  trial_states_ = committed_states_;
  committed_stress_.assign(n, material::Vector6::Zero());
  trial_stress_ = committed_stress_;
  committed_strain_ = committed_stress_;
  trial_strain_ = committed_stress_;
}

template <class Law> void SolidModel<Law>::set_threads(int threads) {
  team_ = model::ThreadTeam(threads); // throws std::invalid_argument for threads < 1
}

template <class Law>
bool SolidModel<Law>::evaluate_element(std::size_t e, const Eigen::Matrix3Xd& u,
                                       bool with_tangent) {
  const HexConnectivity& nodes = mesh_.elements[e];
  const Hex8Reference& reference = references_[e];
  const NodeMatrix element_displacement = gather(nodes, u);
  const Eigen::Matrix3d H = hex8_displacement_gradient(reference, element_displacement);
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + H;
  element_jacobian_[e] = F.determinant();
  if (!(element_jacobian_[e] > 0.0))
    return false;
  const material::Vector6 strain = green_lagrange_strain(H);
  const auto response = laws_[e].evaluate(committed_states_[e], strain);
  if (!response.stress.allFinite())
    return false;
  trial_states_[e] = response.state;
  trial_stress_[e] = response.stress;
  trial_strain_[e] = strain;
  // trapezoidal work of the centre stress over the increment from the committed state
  element_work_[e] = 0.5 * reference.volume *
                     (committed_stress_[e] + response.stress).dot(strain - committed_strain_[e]);
  NodeMatrix& force = element_force_[e];
  force.setZero();
  ElementMatrix* tangent = nullptr;
  if (with_tangent) {
    tangent = &element_tangent_[e];
    tangent->setZero();
  }
  add_hex8_centre_response(reference, F, response.stress, response.tangent, force, tangent);
  if (!hourglass_control_.follow_tangent) {
    element_hourglass_[e] = add_hex8_hourglass_response(reference, hourglass_[e], F,
                                                        element_displacement, force, tangent);
    return true;
  }
  // tangent form (HourglassControl): per component in the element's axes, dP = s_e k dq while
  // loading (committed P dq > 0 or P = 0), k dq while unloading
  const Eigen::Matrix3d& axes = reference.axes;
  const Eigen::Matrix3d F_inverse = F.inverse();
  const HourglassMatrix q =
      hex8_hourglass_displacements(reference, F_inverse, element_displacement);
  const HourglassMatrix dq_local = axes.transpose() * (q - committed_hourglass_q_[e]);
  const HourglassMatrix& committed_P = committed_hourglass_P_[e];
  const HourglassMatrix& moduli = hourglass_moduli_[e];
  HourglassMatrix stiffness_local;
  for (int alpha = 0; alpha < 4; ++alpha)
    for (int m = 0; m < 3; ++m) {
      const bool unloading = committed_P(m, alpha) * dq_local(m, alpha) < 0.0;
      stiffness_local(m, alpha) = (unloading ? 1.0 : hourglass_scale_[e]) * moduli(m, alpha);
    }
  const HourglassMatrix P_local = committed_P + stiffness_local.cwiseProduct(dq_local);
  trial_hourglass_q_[e] = q;
  trial_hourglass_P_[e] = P_local;
  element_hourglass_[e] = 0.5 * (committed_P + P_local).cwiseProduct(dq_local).sum();
  HourglassStiffness stress_stiffness; // dP / dq in reference axes, for Newton's tangent only
  if (with_tangent)
    for (int alpha = 0; alpha < 4; ++alpha)
      stress_stiffness[alpha] = axes * stiffness_local.col(alpha).asDiagonal() * axes.transpose();
  const HourglassMatrix P = axes * P_local;
  add_hex8_hourglass_forces(reference, stress_stiffness, F_inverse, q, P, force, tangent);
  return true;
}

template <class Law>
bool SolidModel<Law>::evaluate(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                               Eigen::SparseMatrix<double>* tangent, std::string& reason) {
  const std::size_t n = mesh_.elements.size();
  const bool with_tangent = tangent != nullptr;
  element_force_.resize(n);
  if (with_tangent)
    element_tangent_.resize(n);
  element_work_.assign(n, 0.0);
  element_hourglass_.assign(n, 0.0);
  element_jacobian_.assign(n, 0.0);
  element_failed_.assign(n, 0);
  const Eigen::Matrix3Xd u =
      Eigen::Map<const Eigen::Matrix3Xd>(displacement.data(), 3, node_count());
  const auto block = [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e)
      element_failed_[e] = evaluate_element(e, u, with_tangent) ? 0 : 1;
  };
  team_.run(n, block);

  // the first failed element, in element order (the same for every thread count)
  for (std::size_t e = 0; e < n; ++e) {
    if (!element_failed_[e])
      continue;
    reason = !(element_jacobian_[e] > 0.0)
                 ? "element " + std::to_string(e) +
                       " inverted (det F = " + std::to_string(element_jacobian_[e]) + ")"
                 : "element " + std::to_string(e) + ": the stress is not finite";
    return false;
  }

  // nodal sums in element order
  const int dofs = dof_count();
  force.setZero(dofs);
  // the elastic form's hourglass energy is stored (a function of the state), the tangent
  // form's is work (added to the committed)
  trial_energy_ = {committed_energy_.internal,
                   hourglass_control_.follow_tangent ? committed_energy_.hourglass : 0.0};
  std::vector<Eigen::Triplet<double>> triplets;
  if (with_tangent)
    triplets.reserve(static_cast<std::size_t>(576) * n);
  for (std::size_t e = 0; e < n; ++e) {
    const HexConnectivity& nodes = mesh_.elements[e];
    trial_energy_.internal += element_work_[e];
    trial_energy_.hourglass += element_hourglass_[e];
    for (int a = 0; a < 8; ++a)
      force.segment<3>(3 * nodes[a]) += element_force_[e].col(a);
    if (with_tangent) {
      const ElementMatrix& k = element_tangent_[e];
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 8; ++c)
            for (int j = 0; j < 3; ++j)
              triplets.emplace_back(3 * nodes[a] + i, 3 * nodes[c] + j, k(3 * a + i, 3 * c + j));
    }
  }
  if (with_tangent) {
    tangent->resize(dofs, dofs);
    tangent->setFromTriplets(triplets.begin(), triplets.end());
  }
  return true;
}

template <class Law> void SolidModel<Law>::commit() {
  if (hourglass_control_.follow_tangent) {
    // s_e = dS : dE / (dE : C_el : dE) over the step being committed (HourglassControl); a
    // step that hardly strains the element (below 1e-12) keeps the scale it had
    for (std::size_t e = 0; e < hourglass_scale_.size(); ++e) {
      const material::Vector6 dE = trial_strain_[e] - committed_strain_[e];
      if (!(dE.squaredNorm() > 1e-24))
        continue;
      const material::Vector6 dS = trial_stress_[e] - committed_stress_[e];
      const double lambda = dilatational_modulus_[e] - 2.0 * shear_modulus_[e];
      const double trace = dE[0] + dE[1] + dE[2];
      const double elastic =
          lambda * trace * trace + 2.0 * shear_modulus_[e] * dE.head<3>().squaredNorm() +
          shear_modulus_[e] * dE.tail<3>().squaredNorm(); // engineering shears: mu gamma^2
      hourglass_scale_[e] = std::clamp(dS.dot(dE) / elastic, hourglass_control_.min_scale, 1.0);
    }
    committed_hourglass_q_ = trial_hourglass_q_;
    committed_hourglass_P_ = trial_hourglass_P_;
  }
  committed_states_ = trial_states_;
  committed_stress_ = trial_stress_;
  committed_strain_ = trial_strain_;
  committed_energy_ = trial_energy_;
}

template <class Law> Eigen::VectorXd SolidModel<Law>::lumped_mass() const {
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(dof_count());
  for (std::size_t e = 0; e < mesh_.elements.size(); ++e) {
    const double share = density_ * references_[e].volume / 8.0;
    for (int node : mesh_.elements[e])
      mass.segment<3>(3 * node).array() += share;
  }
  return mass;
}

template <class Law> double SolidModel<Law>::stable_time_step(double safety) const {
  double step = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < references_.size(); ++e)
    step = std::min(step,
                    2.0 / hex8_max_frequency(references_[e], dilatational_modulus_[e], density_));
  return safety * step;
}

template <class Law> double SolidModel<Law>::max_frequency() const {
  double frequency = 0.0;
  for (std::size_t e = 0; e < references_.size(); ++e)
    frequency =
        std::max(frequency, hex8_max_frequency(references_[e], dilatational_modulus_[e], density_));
  return frequency;
}

template class SolidModel<material::IsotropicElastic3D>;
template class SolidModel<material::SteelDamagePlasticity3D>;
template class SolidModel<material::MortarDamage3D>;

} // namespace brb::solid
