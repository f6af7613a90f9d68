// Helpers for driving a condensed BRBElement: outer-node configurations, and the condensed
// brace (analysis/condensed_brace.hpp) compared with the expanded model.
#pragma once

#include "brb/analysis/brb_element.hpp"
#include "brb/analysis/condensed_brace.hpp"
#include "brb/analysis/cyclic_test.hpp"
#include "brb/analysis/static_analysis.hpp"
#include "brb/element/rotation.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <vector>

namespace brb::test {

/// Outer-node configurations of a brace from `start` along the axes `axes` (columns: axis,
/// section y, section z): the start node at rest, the end node moved by `end_motion` and
/// turned by `end_spin` (both in the brace's axes).
inline std::array<element::NodeConfiguration, 2>
outer_configuration(const element::Vector3& start, const element::Matrix3& axes, double length,
                    const element::Vector3& end_motion, const element::Vector3& end_spin) {
  std::array<element::NodeConfiguration, 2> nodes;
  nodes[0].position = start;
  nodes[1].position = start + axes * (element::Vector3(length, 0.0, 0.0) + end_motion);
  nodes[1].rotation = element::rotation_from_vector(axes * end_spin);
  return nodes;
}

/// Force of the condensed element in a global model and of the expanded model, step by step
/// through a protocol at the given multiples of dy (steps of dy / 10).
struct Comparison {
  double largest_difference = 0.0; ///< N, largest |F_condensed - F_expanded|
  double largest_force = 0.0;      ///< N, largest |F_expanded|
  std::size_t steps = 0;
};

inline Comparison compare_condensed_and_expanded(const model::BraceSpec& spec,
                                                 const std::vector<double>& multiples_of_dy) {
  model::BraceModel expanded = model::build_brace_model(spec);
  const double dy = expanded.yield_deformation;
  std::vector<io::CycleGroup> groups;
  for (const double multiple : multiples_of_dy)
    groups.push_back({multiple * dy, 1});
  const io::LoadingProtocol protocol = io::cyclic_protocol("comparison", groups, dy / 10.0);
  // Both converged well below the compared difference: the default residual floor (1e-14
  // of the model's size times the stiffest element) is 0.25 N here.
  analysis::NewtonSettings tight;
  tight.relative_force_tolerance = 1e-12;
  tight.position_round_off = 1e-16;
  const analysis::CyclicTestResult reference = analysis::run_cyclic_test(
      expanded, protocol.deformation, protocol.cycle, protocol.cycle_amplitude, tight);
  EXPECT_TRUE(reference.completed) << reference.stop_reason;

  auto condensed = analysis::build_condensed_brace_model(spec, tight);
  analysis::StaticAnalysis analysis(condensed->model, tight);
  analysis.use_displacement_control(condensed->end_node, model::ux);
  Comparison comparison;
  for (std::size_t k = 1; k < reference.steps.size(); ++k) {
    const analysis::StepReport report = analysis.step_to(protocol.deformation[k]);
    EXPECT_TRUE(report.converged) << "step " << k << ": " << report.failure;
    if (!report.converged)
      break;
    const double expected = reference.steps[k].force;
    comparison.largest_difference =
        std::max(comparison.largest_difference, std::abs(analysis.control_force() - expected));
    comparison.largest_force = std::max(comparison.largest_force, std::abs(expected));
    // the element's own axial force output is the same force (pinned ends, straight chord)
    EXPECT_NEAR(condensed->element->axial_force(), analysis.control_force(),
                1e-9 * expanded.yield_force);
    ++comparison.steps;
  }
  EXPECT_EQ(comparison.steps + 1, reference.steps.size());
  // the element's indicators come from the same code as the cyclic test's
  const analysis::BraceIndicators& inside_indicators = condensed->element->indicators();
  const analysis::BraceIndicators& outside_indicators = reference.indicators;
  EXPECT_NEAR(inside_indicators.max_core_lateral_displacement,
              outside_indicators.max_core_lateral_displacement,
              1e-6 * outside_indicators.max_core_lateral_displacement + 1e-9);
  EXPECT_EQ(inside_indicators.max_buckling_half_waves, outside_indicators.max_buckling_half_waves);
  EXPECT_NEAR(inside_indicators.cumulative_inelastic_deformation,
              outside_indicators.cumulative_inelastic_deformation,
              1e-6 * outside_indicators.cumulative_inelastic_deformation);
  EXPECT_NEAR(inside_indicators.max_mortar_damage, outside_indicators.max_mortar_damage, 1e-6);
  EXPECT_EQ(inside_indicators.global_buckling, outside_indicators.global_buckling);
  // The element's energy (stored + dissipated, its internal jumps counted as dissipated) is
  // the expanded model's stored + dissipated + released in jumps: the same energy, booked
  // inside the element. (Each model's own balance W = S + D + J holds only to the step
  // size's accuracy, a few % here; that error is the trapezoidal work, not the element.)
  const analysis::EnergyBalance& inside = analysis.energy();
  const analysis::EnergyBalance& outside = reference.energy_balance;
  EXPECT_NEAR(inside.stored + inside.dissipated,
              outside.stored + outside.dissipated + outside.released_in_jumps,
              1e-3 * outside.external_work);
  return comparison;
}

} // namespace brb::test
