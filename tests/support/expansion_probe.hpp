// A casing contact link at an interior station with its core chord (the core expansion's and
// the sub-element waves' tests).
#pragma once

#include "brb/element/casing_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
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

  /// What a walk along a closed loading path saw (walk_energy_path).
  struct PathWalk {
    double work = 0.0;             ///< nodal forces' trapezoidal work (N mm)
    double largest_mismatch = 0.0; ///< max over the path of |work - stored - dissipated|
    int both_faces = 0;            ///< points where both faces of a direction bear
    int open = 0;                  ///< points with no face in contact
    double max_damage = 0.0;       ///< largest max_mortar_damage()
  };
  /// The energy tests' path (t = 2 pi k / steps, k = 0..steps): the core node at
  /// (0.5 sin t, 0.05 sin 2t, lateral_z sin 3t) from the casing (axial sliding, lateral
  /// motion in and out of contact), the chord at axial strain
  /// -peak_strain sin^2(t / 2) + 0.01 sin 5t and its first end bowed by 0.1 sin t along y.
  /// Each point is evaluated and committed.
  PathWalk walk_energy_path(int steps, double lateral_z, double peak_strain) {
    PathWalk walk;
    Eigen::VectorXd previous_force;
    std::vector<NodeConfiguration> previous_nodes;
    for (int k = 0; k <= steps; ++k) {
      const double t = 2.0 * std::numbers::pi * k / steps;
      const Vector3 core(0.5 * std::sin(t), 0.05 * std::sin(2.0 * t),
                         lateral_z * std::sin(3.0 * t));
      const double strain =
          -peak_strain * std::sin(0.5 * t) * std::sin(0.5 * t) + 0.01 * std::sin(5.0 * t);
      place(core, strain, Vector3(0.0, 0.1 * std::sin(t), 0.0), Vector3::Zero());
      evaluate();
      if (k > 0) {
        for (std::size_t n = 0; n < nodes.size(); ++n) {
          const auto i = 6 * static_cast<Eigen::Index>(n);
          walk.work += 0.5 * (previous_force.segment<3>(i) + force.segment<3>(i))
                                 .dot(nodes[n].position - previous_nodes[n].position);
        }
      }
      contact.commit();
      const element::ElementEnergy now = contact.energy();
      walk.largest_mismatch =
          std::max(walk.largest_mismatch, std::abs(walk.work - now.stored - now.dissipated));
      previous_force = force;
      previous_nodes = nodes;
      const auto& faces = contact.face_forces();
      walk.both_faces += (faces[0] > 0.0 && faces[1] > 0.0) || (faces[2] > 0.0 && faces[3] > 0.0);
      walk.open += !contact.in_contact();
      walk.max_damage = std::max(walk.max_damage, contact.max_mortar_damage());
    }
    return walk;
  }
};

} // namespace brb::test
