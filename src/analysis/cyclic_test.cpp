#include "brb/analysis/cyclic_test.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace brb::analysis {
namespace {

constexpr double kFractureDamage = 0.9;      // a core fiber this damaged has fractured
constexpr double kCrushedDamage = 0.9;       // a bearing face this damaged has crushed through
constexpr double kGlobalBucklingRatio = 250; // lateral deflection beyond L_y / 250

/// Updates the indicators with the converged state of the step.
void observe(const model::BraceModel& brace, const StaticAnalysis& analysis,
             const std::vector<element::Vector3>& initial_positions, double yielding_length,
             bool compression, BraceIndicators& indicators) {
  for (const auto* beam : brace.beams) {
    for (const auto& section : beam->local_beam().sections()) {
      indicators.max_steel_damage = std::max(indicators.max_steel_damage, section.max_damage());
    }
  }
  const auto lateral_of = [&](int node, const element::Vector3& initial) {
    const element::Vector3 motion = analysis.node(node).position - initial;
    return Eigen::Vector2d(motion.y(), motion.z());
  };
  for (std::size_t n = 0; n < brace.nodes.size(); ++n) {
    indicators.max_core_lateral_displacement =
        std::max(indicators.max_core_lateral_displacement,
                 lateral_of(brace.nodes[n], initial_positions[n]).norm());
  }
  // Lateral displacement of the yielding core's stations, relative to the casing if any.
  std::vector<Eigen::Vector2d> relative;
  double casing_lateral = 0.0;
  if (brace.casing) {
    const auto& casing = *brace.casing;
    for (const auto* contact : casing.contacts) {
      indicators.max_mortar_damage =
          std::max(indicators.max_mortar_damage, contact->max_mortar_damage());
    }
    for (const auto* beam : casing.beams) {
      for (const auto& section : beam->local_beam().sections()) {
        indicators.max_mortar_damage = std::max(indicators.max_mortar_damage, section.max_damage());
      }
    }
    for (std::size_t s = 0; s < casing.nodes.size(); ++s) {
      const int casing_node = casing.nodes[s];
      const Eigen::Vector2d casing_motion =
          lateral_of(casing_node, brace.model.coordinates(casing_node));
      casing_lateral = std::max(casing_lateral, casing_motion.norm());
      const int core_node = casing.core_nodes[s];
      relative.push_back(lateral_of(core_node, brace.model.coordinates(core_node)) - casing_motion);
    }
    indicators.max_casing_lateral_displacement =
        std::max(indicators.max_casing_lateral_displacement, casing_lateral);
    if (indicators.max_mortar_damage >= kCrushedDamage)
      indicators.casing_failure = true;
  } else {
    for (std::size_t e = 0; e < brace.beams.size(); ++e) {
      if (!brace.in_yielding_zone[e])
        continue;
      if (relative.empty())
        relative.push_back(lateral_of(brace.nodes[e], initial_positions[e]));
      relative.push_back(lateral_of(brace.nodes[e + 1], initial_positions[e + 1]));
    }
  }
  // half-waves in the direction of the largest motion
  int direction = 0;
  double largest = 0.0;
  for (const auto& u : relative) {
    for (int k = 0; k < 2; ++k) {
      if (std::abs(u[k]) > largest) {
        largest = std::abs(u[k]);
        direction = k;
      }
    }
  }
  // buckling happens in compression: count the half-waves there only
  if (compression && largest > 1e-3) {
    int half_waves = 0;
    double previous_sign = 0.0;
    for (const auto& u : relative) {
      if (std::abs(u[direction]) < 0.1 * largest)
        continue;
      const double sign = u[direction] > 0.0 ? 1.0 : -1.0;
      if (sign != previous_sign)
        ++half_waves;
      previous_sign = sign;
    }
    indicators.max_buckling_half_waves = std::max(indicators.max_buckling_half_waves, half_waves);
  }
  if (indicators.max_steel_damage >= kFractureDamage)
    indicators.core_fracture = true;
  const double global_lateral =
      brace.casing ? casing_lateral : indicators.max_core_lateral_displacement;
  if (global_lateral > yielding_length / kGlobalBucklingRatio)
    indicators.global_buckling = true;
}

} // namespace

CyclicTestResult run_cyclic_test(model::BraceModel& brace, std::span<const double> deformation,
                                 std::span<const int> cycle,
                                 std::span<const double> cycle_amplitude, NewtonSettings settings) {
  CyclicTestResult result;
  StaticAnalysis analysis(brace.model, settings);
  analysis.use_displacement_control(brace.end_node, model::ux);
  std::vector<element::Vector3> initial_positions;
  for (const int node : brace.nodes)
    initial_positions.push_back(brace.model.coordinates(node));

  const auto lateral = [&] {
    double largest = 0.0;
    for (std::size_t n = 0; n < brace.nodes.size(); ++n) {
      const element::Vector3 motion = analysis.node(brace.nodes[n]).position - initial_positions[n];
      largest = std::max(largest, std::hypot(motion.y(), motion.z()));
    }
    return largest;
  };

  result.steps.push_back({0, cycle.empty() ? 0 : cycle[0], 0.0, 0.0, 0.0, 0});
  double yielding_length = 0.0;
  for (std::size_t e = 0; e < brace.beams.size(); ++e) {
    if (brace.in_yielding_zone[e])
      yielding_length += brace.beams[e]->local_beam().length();
  }
  CycleMetrics current;
  for (std::size_t k = 1; k < deformation.size(); ++k) {
    const StepReport report = analysis.step_to(deformation[k]);
    if (!report.converged) {
      std::ostringstream reason;
      reason << "step " << k << " (deformation " << std::setprecision(6) << deformation[k]
             << " mm): " << report.failure;
      result.stop_reason = reason.str();
      break;
    }
    CyclicStep step{static_cast<int>(k),      cycle[k],  analysis.control_value(),
                    analysis.control_force(), lateral(), report.substeps};
    const CyclicStep& previous = result.steps.back();
    observe(brace, analysis, initial_positions, yielding_length, step.force < 0.0,
            result.indicators);
    const double elastic_stiffness = brace.yield_force / brace.yield_deformation;
    result.indicators.cumulative_inelastic_deformation +=
        std::abs((step.deformation - previous.deformation) -
                 (step.force - previous.force) / elastic_stiffness) /
        brace.yield_deformation;
    const double work =
        0.5 * (step.force + previous.force) * (step.deformation - previous.deformation);
    result.energy_total += work;
    result.max_tension = std::max(result.max_tension, step.force);
    result.max_compression = std::min(result.max_compression, step.force);

    if (step.cycle != current.index) {
      current = CycleMetrics{};
      current.index = step.cycle;
      if (step.cycle >= 1 && static_cast<std::size_t>(step.cycle) <= cycle_amplitude.size()) {
        current.amplitude = cycle_amplitude[step.cycle - 1];
      }
    }
    current.energy += work;
    current.max_tension = std::max(current.max_tension, step.force);
    current.max_compression = std::min(current.max_compression, step.force);
    const bool cycle_ends = k + 1 == deformation.size() || cycle[k + 1] != step.cycle;
    if (cycle_ends && step.cycle >= 1)
      result.cycles.push_back(current);
    result.steps.push_back(step);
  }
  result.completed = result.stop_reason.empty();
  result.energy_balance = analysis.energy();
  result.iterations = analysis.total_iterations();
  result.substeps = analysis.total_substeps();
  result.regularised_steps = analysis.regularised_steps();
  result.unstable_accepted = analysis.unstable_accepted();
  result.energy_cuts = analysis.energy_cuts();
  result.energy_tolerance_missed = analysis.energy_tolerance_missed();
  return result;
}

} // namespace brb::analysis
