// Central differences of an element's nodal forces with respect to every DOF of its nodes
// (translations and spins), from a given configuration: the reference for the tangents of
// the casing's contact links.
#pragma once

#include "brb/element/element.hpp"

#include "support/finite_difference.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace brb::test {

inline Eigen::MatrixXd
numeric_element_tangent(element::Element& element,
                        const std::vector<element::NodeConfiguration>& configuration,
                        double step = 1e-8) {
  const auto force_of = [&](const Eigen::VectorXd& u) {
    auto moved = configuration;
    for (std::size_t n = 0; n < moved.size(); ++n)
      moved[n].position += u.segment<3>(6 * static_cast<Eigen::Index>(n));
    Eigen::VectorXd f;
    Eigen::MatrixXd unused;
    std::string why;
    EXPECT_TRUE(element.evaluate(moved, f, unused, why)) << why;
    return f;
  };
  const auto dofs = 6 * static_cast<Eigen::Index>(configuration.size());
  return central_difference_jacobian(force_of, Eigen::VectorXd::Zero(dofs).eval(), step);
}

} // namespace brb::test
