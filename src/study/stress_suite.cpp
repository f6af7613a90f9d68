#include "brb/study/stress_suite.hpp"

#include "brb/io/brace_input.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/protocol.hpp"
#include "brb/study/stress_generators.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace brb::study {

namespace {

/// How big each group is: the short suite (ctest -L stress, under 3 minutes on one core)
/// and the long one (brb bench stress --long).
struct SuiteSize {
  int truss_random_seeds;
  int truss_reversals;
  int full_random_seeds;
  int full_reversals;
  int full_core_elements;
  double full_monotonic_step;   ///< multiple of the default step
  double full_monotonic_strain; ///< core strain the full brace is pushed to
  std::vector<double> truss_step_factors;
  std::vector<double> full_step_factors;
  double frame_duration; ///< s of the record (<= 0: all of it)
  int near_singular_cycles_at_3dy;
  int euler_cycles_at_3dy; ///< of the barely stiff casing
};

// The short suite keeps the full brace's histories short (the issue: under 3 minutes on one
// core): measured on the loaded 2-core machine, the full 4-element brace pushed on to 10 %
// stopped at 5.3 % core strain (a pseudo-transient pass that did not come to rest, after
// 350 s), and the barely stiff casing spent 287 s in one step of its 3 dy cycle. Those
// runs are the long suite's.

SuiteSize size_of(bool long_suite) {
  if (long_suite)
    return {24, 24, 3, 8, 8, 1.0, 0.10, {0.01, 0.1, 1.0, 10.0}, {0.1, 1.0, 10.0}, 0.0, 2, 2};
  return {4, 10, 2, 4, 4, 10.0, 0.03, {0.01, 0.1, 1.0, 10.0}, {1.0, 10.0}, 6.0, 1, 0};
}

/// Amplitude limit of the random histories (issue 9): 20 dy.
constexpr double kRandomAmplitudeLimit = 20.0;
/// Monotonic compression to 10 % core strain (issue 9).
constexpr double kMonotonicCoreStrain = 0.10;
/// Near-singular braces (issue 9): gap 1e-6 mm, friction 1.0, casing Euler load just above
/// the core's yield force (1.1 P_y).
constexpr double kTinyGap = 1e-6;
constexpr double kFullFriction = 1.0;
constexpr double kBarelyStiffEulerRatio = 1.1;

/// The energy-error guard of the brace cases (NewtonSettings::energy_tolerance), below the
/// acceptance's 1 %: the solver's default guard, 1e-2 of the gross work, is the acceptance
/// limit itself, and runs came close to it: on a random 20 dy history the
/// full brace with 4 core elements misfit 1.0 % of the net work (0.8 % of the gross) under
/// the default guard and 2.5e-5 under 2e-3, at the same cost (962 steps, 1,028 against
/// 1,038 substeps; README "Numerical stress tests").
constexpr double kStressEnergyGuard = 2e-3;

std::string fidelity_label(const model::BraceSpec& brace) {
  return brace.element.fidelity == model::Fidelity::truss
             ? std::string("truss")
             : "full" + std::to_string(brace.core_elements);
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

StressCase brace_case(StressGroup group, std::string name, std::string generator,
                      std::uint64_t seed, std::string settings, model::BraceSpec brace,
                      std::vector<double> deformation) {
  StressCase stress_case;
  stress_case.name = std::string(group_name(group)) + "/" + fidelity_label(brace) + "/" + name;
  stress_case.group = group;
  stress_case.generator = std::move(generator);
  stress_case.seed = seed;
  stress_case.settings = std::move(settings);
  analysis::NewtonSettings solver;
  solver.energy_tolerance = kStressEnergyGuard;
  stress_case.settings += "; energy guard " + number(kStressEnergyGuard);
  stress_case.subject = BraceStress{std::move(brace), std::move(deformation), solver};
  return stress_case;
}

/// Full cycles 0 -> +A -> -A -> 0 at the amplitudes (mm), in steps of at most max_step.
std::vector<double> cycles(const std::vector<double>& amplitudes, double max_step) {
  std::vector<io::CycleGroup> groups;
  for (const double amplitude : amplitudes)
    groups.push_back({amplitude, 1});
  return io::cyclic_protocol("stress cycles", groups, max_step).deformation;
}

} // namespace

std::vector<double> frame_collapse_scales(bool long_suite) {
  if (long_suite)
    return {0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0};
  return {1.0, 2.0, 4.0};
}

std::vector<double> beyond_collapse_scales(bool long_suite) {
  if (long_suite)
    return {2.0, 4.0, 8.0, 16.0};
  return {4.0};
}

std::vector<StressCase> make_stress_suite(const StressSuiteInputs& inputs,
                                          const StressSuiteSettings& settings) {
  const SuiteSize size = size_of(settings.long_suite);
  const model::BraceSpec reference = io::read_brace(inputs.brace);
  if (!reference.casing || !reference.casing->steel_tube) {
    throw io::InputError(inputs.brace.string(), "/casing",
                         "the stress suite needs a brace with a steel-tube casing");
  }
  const model::BraceSpec truss =
      brace_variant(reference, model::Fidelity::truss, reference.core_elements);
  const model::BraceSpec full =
      brace_variant(reference, model::Fidelity::full, size.full_core_elements);
  const BraceYield yield = brace_yield(reference);
  const double dy = yield.deformation;
  const double default_step = dy / 10.0; // brb cyclic's default max step
  std::vector<StressCase> cases;

  // Random deformation histories: reversals at random, amplitudes up to 20 dy.
  const auto random_cases = [&](const model::BraceSpec& brace, int seeds, int reversals) {
    for (int k = 0; k < seeds; ++k) {
      const std::uint64_t seed = settings.seed + static_cast<std::uint64_t>(k);
      const std::vector<double> turning =
          random_turning_points(seed, reversals, kRandomAmplitudeLimit * dy);
      cases.push_back(
          brace_case(StressGroup::random_history, "seed-" + std::to_string(seed),
                     "random_turning_points: " + std::to_string(reversals) +
                         " reversals, |turning| < " + number(kRandomAmplitudeLimit) + " dy",
                     seed, "max step dy/10", brace, history_points(turning, default_step)));
    }
  };
  random_cases(truss, size.truss_random_seeds, size.truss_reversals);
  random_cases(full, size.full_random_seeds, size.full_reversals);

  // Monotonic compression to 10 % core strain (the short suite's full brace: to 3 %).
  const auto monotonic = [&](const model::BraceSpec& brace, double core_strain,
                             double step_factor) {
    const double target = compression_target(yield, core_strain);
    cases.push_back(brace_case(StressGroup::monotonic_compression,
                               "to-" + number(100.0 * core_strain) + "pct",
                               "monotonic compression to " + number(target) + " mm (" +
                                   number(100.0 * core_strain) + " % core strain)",
                               0, "max step " + number(step_factor) + " x dy/10", brace,
                               history_points({target}, step_factor * default_step)));
  };
  monotonic(truss, kMonotonicCoreStrain, 1.0);
  monotonic(full, size.full_monotonic_strain, size.full_monotonic_step);

  // One protocol (a cycle each at 1, 5 and 10 dy) at step sizes 1/100 .. 10 x the default.
  const std::vector<double> amplitudes{dy, 5.0 * dy, 10.0 * dy};
  const auto step_cases = [&](const model::BraceSpec& brace, const std::vector<double>& factors) {
    for (const double factor : factors) {
      cases.push_back(brace_case(StressGroup::step_size, "step-" + number(factor) + "x",
                                 "one cycle each at 1, 5, 10 dy", 0,
                                 "max step " + number(factor) + " x dy/10", brace,
                                 cycles(amplitudes, factor * default_step)));
    }
  };
  step_cases(truss, size.truss_step_factors);
  step_cases(full, size.full_step_factors);

  // The frame at, below and beyond its collapse intensity.
  const model::FrameSpec frame = io::read_frame(inputs.frame);
  const io::GroundMotion motion = io::load_ground_motion(inputs.record);
  const auto frame_case = [&](double scale, std::optional<double> drift_limit) {
    StressCase stress_case;
    stress_case.name = std::string(group_name(StressGroup::frame_collapse)) + "/truss/" +
                       motion.name + "-x" + number(scale) +
                       (drift_limit ? "-limit-" + number(*drift_limit) : std::string());
    stress_case.group = StressGroup::frame_collapse;
    stress_case.generator = inputs.frame.parent_path().filename().string() + " under " +
                            motion.name + " x " + number(scale);
    stress_case.settings =
        "braces truss; " +
        (size.frame_duration > 0.0 ? "first " + number(size.frame_duration) + " s of the record"
                                   : std::string("the whole record")) +
        (drift_limit ? "; drift limit raised to " + number(*drift_limit) : std::string());
    FrameStress stress = frame_stress(frame, inputs.frame.string(), frame::BraceOverride::truss,
                                      motion, scale, size.frame_duration);
    stress.drift_limit = drift_limit;
    stress_case.subject = std::move(stress);
    cases.push_back(std::move(stress_case));
  };
  for (const double scale : frame_collapse_scales(settings.long_suite))
    frame_case(scale, std::nullopt);
  for (const double scale : beyond_collapse_scales(settings.long_suite))
    frame_case(scale, kBeyondCollapseDriftLimit);

  // Near-singular braces under a cycle at 1 dy and cycles at 3 dy.
  const auto near_protocol = [&](int cycles_at_3dy) {
    std::vector<double> amplitudes{dy};
    for (int k = 0; k < cycles_at_3dy; ++k)
      amplitudes.push_back(3.0 * dy);
    return cycles(amplitudes, default_step);
  };
  const auto near_generator = [](int cycles_at_3dy) {
    return cycles_at_3dy > 0 ? "a cycle at 1 dy, " + std::to_string(cycles_at_3dy) + " at 3 dy"
                             : std::string("a cycle at 1 dy");
  };
  const int at_3dy = size.near_singular_cycles_at_3dy;
  cases.push_back(brace_case(StressGroup::near_singular, "gap-1e-6", near_generator(at_3dy), 0,
                             "gap 1e-6 mm per side", with_gap(full, kTinyGap),
                             near_protocol(at_3dy)));
  cases.push_back(brace_case(StressGroup::near_singular, "friction-1", near_generator(at_3dy), 0,
                             "friction coefficient 1.0", with_friction(full, kFullFriction),
                             near_protocol(at_3dy)));
  const int euler_at_3dy = size.euler_cycles_at_3dy;
  cases.push_back(brace_case(
      StressGroup::near_singular, "euler-1.1", near_generator(euler_at_3dy), 0,
      "casing tube scaled to P_E = " + number(kBarelyStiffEulerRatio) + " P_y",
      with_casing_euler_ratio(full, kBarelyStiffEulerRatio), near_protocol(euler_at_3dy)));
  if (settings.long_suite) {
    cases.push_back(
        brace_case(StressGroup::near_singular, "all-three", near_generator(euler_at_3dy), 0,
                   "gap 1e-6 mm, friction 1.0, P_E = 1.1 P_y together",
                   with_casing_euler_ratio(with_friction(with_gap(full, kTinyGap), kFullFriction),
                                           kBarelyStiffEulerRatio),
                   near_protocol(euler_at_3dy)));
  }
  return cases;
}

StressSummary summarise(const std::vector<StressResult>& results) {
  StressSummary summary;
  std::vector<double> times;
  for (const StressResult& result : results) {
    ++summary.cases;
    if (result.completed)
      ++summary.completed;
    if (result.collapsed)
      ++summary.collapsed;
    if (!result.completed && !result.failure_reason.empty())
      ++summary.failed_with_reason;
    summary.nan_count += result.nan_count;
    // A NaN error is not <= anything: it becomes the maximum and stays (it shows).
    const bool larger = !(result.energy_error <= summary.max_energy_error);
    if (summary.max_energy_error_case.empty() ||
        (larger && !std::isnan(summary.max_energy_error))) {
      summary.max_energy_error = result.energy_error;
      summary.max_energy_error_case = result.name;
    }
    summary.fallbacks.substeps += result.fallbacks.substeps;
    summary.fallbacks.pseudo_transient += result.fallbacks.pseudo_transient;
    summary.fallbacks.unstable_accepted += result.fallbacks.unstable_accepted;
    summary.fallbacks.energy_cuts += result.fallbacks.energy_cuts;
    summary.fallbacks.far_branch_cuts += result.fallbacks.far_branch_cuts;
    summary.fallbacks.modified_newton += result.fallbacks.modified_newton;
    summary.fallbacks.broyden += result.fallbacks.broyden;
    summary.steps += result.steps;
    times.insert(times.end(), result.step_wall_times.begin(), result.step_wall_times.end());
    if (!result.acceptable())
      ++summary.unacceptable;
  }
  summary.step_times = distribution_of(std::move(times));
  return summary;
}

} // namespace brb::study
