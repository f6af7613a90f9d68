// A casing contact link at an interior station with its core chord (the core expansion's and
// the sub-element waves' tests).
#pragma once

#include "brb/element/casing_contact.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace brb::test {

using element::CasingContact;
using element::CasingContactParameters;
using element::CoreExpansion;
using element::HighModeWaves;
using element::Matrix3;
using element::NodeConfiguration;
using element::Vector3;

/// A link at an interior station: core node 0 and casing node 1 at the origin, the core
/// nodes before and after it (2, 3) at -/+ half_chord along the brace axis.
struct ExpansionProbe {
  static constexpr double half_chord = 50.0;
  CasingContactParameters parameters;
  CasingContact contact;
  std::vector<NodeConfiguration> nodes;
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;

  /// `ratio`: the expansion's nu_c (0: the chord only, e.g. for the sub-element waves).
  ExpansionProbe(const CasingContactParameters& link, double extent_y, double extent_z,
                 bool skip_open_links = true, double ratio = 0.5,
                 const std::optional<HighModeWaves>& waves = std::nullopt)
      : parameters(link), contact({0, 1}, Vector3::Zero(), Vector3::Zero(), link, skip_open_links,
                                  expansion(link.axes, extent_y, extent_z, ratio), waves),
        nodes{{Vector3::Zero(), Matrix3::Identity()},
              {Vector3::Zero(), Matrix3::Identity()},
              {link.axes.col(0) * -half_chord, Matrix3::Identity()},
              {link.axes.col(0) * half_chord, Matrix3::Identity()}} {}

  static CoreExpansion expansion(const Matrix3& axes, double extent_y, double extent_z,
                                 double ratio = 0.5) {
    CoreExpansion core;
    core.previous_node = 2;
    core.next_node = 3;
    core.previous_position = axes.col(0) * -half_chord;
    core.next_position = axes.col(0) * half_chord;
    core.extent_y = extent_y;
    core.extent_z = extent_z;
    core.ratio = ratio;
    return core;
  }
  /// Local (axis, y, z) positions: the core node relative to the casing (at the origin), and
  /// the chord's ends at a uniform axial strain plus lateral offsets of their own.
  void place(const Vector3& core, double strain, const Vector3& previous_offset = Vector3::Zero(),
             const Vector3& next_offset = Vector3::Zero()) {
    const Matrix3& axes = parameters.axes;
    nodes[0].position = axes * core;
    nodes[2].position = axes * (Vector3(-half_chord * (1.0 + strain), 0.0, 0.0) + previous_offset);
    nodes[3].position = axes * (Vector3(half_chord * (1.0 + strain), 0.0, 0.0) + next_offset);
  }
  void evaluate() {
    std::string failure;
    ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure)) << failure;
  }
};

} // namespace brb::test
