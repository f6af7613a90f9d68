// Virtual cyclic tests of a bare BRB core (no casing): tension follows the material law,
// compression is limited by buckling.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include "support/brace_fixtures.hpp"
#include "support/specimen_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace brb::analysis {
namespace {

struct GironaRun {
  model::BraceModel brace;
  io::LoadingProtocol protocol;
  CyclicTestResult result;
};

GironaRun run_girona(const model::BraceSpec& spec, int final_cycles) {
  GironaRun run{model::build_brace_model(spec), {}, {}};
  run.protocol = io::girona_protocol(run.brace.yield_deformation, final_cycles,
                                     run.brace.yield_deformation / 10.0);
  run.result = run_cyclic_test(run.brace, run.protocol.deformation, run.protocol.cycle,
                               run.protocol.cycle_amplitude);
  return run;
}

TEST(BareCore, TensionFollowsTheUniaxialLawTimesArea) {
  // Reference: before the core has buckled, tension is uniform: the force is A sigma(eps)
  // of the closed-form uniaxial law, with the core strain eps found from the deformation by
  // compatibility, delta = eps L_y + F (sum over the end zones of L / E A). The first
  // excursion of a tension-first protocol (to 3 dy) is compared. The bow is L/10000 here:
  // pulling a bow of amplitude a straight adds pi^2 a^2 / 4L of deformation (0.007 mm,
  // 1 % of the force at 0.25 Py, for L/1000), which this comparison is not about.
  model::BraceSpec spec = test::girona_d3_bare_core();
  spec.imperfection.amplitude = spec.total_length() / 10000.0;
  model::BraceModel brace = model::build_brace_model(spec);
  const io::LoadingProtocol protocol = io::cyclic_protocol(
      "tension first", {{3.0 * brace.yield_deformation, 1}}, brace.yield_deformation / 10.0);
  const CyclicTestResult result =
      run_cyclic_test(brace, protocol.deformation, protocol.cycle, protocol.cycle_amplitude);
  ASSERT_TRUE(result.completed) << result.stop_reason;

  const double zone_flexibility =
      brace.yield_deformation / brace.yield_force -
      spec.yielding_length / (spec.steel.youngs_modulus * brace.core_area);
  const material::SteelUniaxial law(spec.steel, 1.0);
  auto state = law.initial_state();
  double strain = 0.0;
  int compared = 0;
  double worst = 0.0;
  for (const CyclicStep& step : result.steps) {
    if (step.step == 0)
      continue;
    if (step.deformation < result.steps[step.step - 1].deformation)
      break; // first branch only
    // Newton on eps: delta - eps L_y - A sigma(eps) f_zones = 0
    for (int iteration = 0; iteration < 50; ++iteration) {
      const auto trial = law.evaluate(state, strain);
      const double residual = step.deformation - strain * spec.yielding_length -
                              brace.core_area * trial.stress * zone_flexibility;
      const double slope =
          spec.yielding_length + brace.core_area * trial.tangent * zone_flexibility;
      strain += residual / slope;
      if (std::abs(residual) < 1e-12)
        break;
    }
    const auto response = law.evaluate(state, strain);
    state = response.state;
    const double reference = brace.core_area * response.stress;
    worst = std::max(worst, std::abs(step.force - reference) / reference);
    ++compared;
  }
  EXPECT_GT(compared, 25);
  EXPECT_GT(state.equivalent_plastic_strain, 0.0); // the branch did yield
  EXPECT_LT(worst, 0.005);
}

TEST(BareCore, CompressionIsLimitedByBucklingAndTheForceDrops) {
  // Reference: Euler, P_E = pi^2 E I / L^2 for the pinned core without end zones. The
  // elastic cycles (< dy) carry at most about P_E in compression (the bow of L/1000 keeps
  // it a little below); once the core has yielded, it buckles into a plastic hinge whose
  // moment capacity falls as the lateral deflection grows, so the compression force drops.
  const model::BraceSpec spec = test::girona_d3_bare_core(16, false);
  const GironaRun run = run_girona(spec, 2);
  ASSERT_TRUE(run.result.completed) << run.result.stop_reason;
  const double inertia = std::numbers::pi * std::pow(22.0, 4) / 64.0;
  const double euler = std::numbers::pi * std::numbers::pi * spec.steel.youngs_modulus * inertia /
                       (spec.yielding_length * spec.yielding_length);
  for (const CycleMetrics& cycle : run.result.cycles) {
    EXPECT_LT(-cycle.max_compression, 1.02 * euler) << "cycle " << cycle.index;
    if (cycle.index == 4) {
      EXPECT_GT(-cycle.max_compression, 0.9 * euler);
    }
  }
  EXPECT_GT(run.result.max_tension, run.brace.yield_force); // tension yields and hardens
  // the last 5 dy cycle: force at the largest shortening well below the cycle's peak
  const int last = run.result.cycles.back().index;
  double peak = 0.0, at_extreme = 0.0, extreme = 0.0, lateral_at_extreme = 0.0;
  for (const CyclicStep& step : run.result.steps) {
    if (step.cycle != last)
      continue;
    peak = std::min(peak, step.force);
    if (step.deformation < extreme) {
      extreme = step.deformation;
      at_extreme = step.force;
      lateral_at_extreme = step.max_lateral_displacement;
    }
  }
  EXPECT_LT(std::abs(at_extreme), 0.8 * std::abs(peak));
  // and the core has bowed out far beyond its imperfection (global buckling, no casing)
  EXPECT_GT(lateral_at_extreme, 20.0 * spec.imperfection.amplitude);
  // the indicators say so: global buckling in one half-wave, no casing, no damage law
  const BraceIndicators& indicators = run.result.indicators;
  EXPECT_TRUE(indicators.global_buckling);
  EXPECT_EQ(indicators.max_buckling_half_waves, 1);
  EXPECT_FALSE(indicators.casing_failure);
  EXPECT_FALSE(indicators.core_fracture);
  EXPECT_EQ(indicators.max_steel_damage, 0.0);
  EXPECT_NEAR(indicators.max_core_lateral_displacement,
              std::max_element(run.result.steps.begin(), run.result.steps.end(),
                               [](const CyclicStep& a, const CyclicStep& b) {
                                 return a.max_lateral_displacement < b.max_lateral_displacement;
                               })
                  ->max_lateral_displacement,
              1e-9);
  // cumulative inelastic deformation: at least the plastic strokes of the two 5 dy cycles in
  // tension (each pulls the core about 2 x 5 dy beyond its elastic range)
  EXPECT_GT(indicators.cumulative_inelastic_deformation, 10.0);
}

TEST(BareCore, ABuckledHardeningCoreCarriesAtLeastTheTangentModulusLoad) {
  // The small BRB's core (BRB_SOURCE_FACTS section 6: 10 x 10 mm, 100 mm, fy 275 MPa and a
  // linear kinematic hardening H = 20000 MPa, no damage), bare and pinned, shortened to
  // -60 dy. It yields at Py = 27.5 kN, far below its Euler load (173 kN), and buckles.
  // Reference, theory (Engesser/Shanley, written out here for this law): past the peak every
  // fiber that shortens further follows E_t = E H / (E + H), and one that lengthens unloads
  // at E and reverse-yields at E_t, so the moment about the section's centroid is
  // M = E_t I kappa + (E - E_t) int c(y) y dA with c nondecreasing in y: M >= E_t I kappa.
  // With P v = M along a pinned column, projecting on sin(pi x / L) gives P >= P_t =
  // pi^2 E_t I / L^2 = 15.0 kN. The same c is bounded by 2 fy / E, so the offset moment is
  // at most M_o = 2 fy (1 - E_t / E) Z (Z = b h^2 / 4, the plastic modulus) and, for a
  // half-sine bow of amplitude a, P <= P_t + (4 / pi) M_o / a: the force falls toward P_t as
  // the bow grows and never below it. Small BRB case 1's check (the force below 10 % of its
  // peak of 4.6 Py) asks for less than P_t there (validation/thesis_small_case1).
  // the specimen's own brace file (10 x 10 mm, 100 mm, 10 elements, pinned, bow L/1000),
  // its casing taken away
  model::BraceSpec spec = io::read_brace(test::specimen_brace("thesis_small_case1"));
  spec.casing.reset();
  model::BraceModel brace = model::build_brace_model(spec);
  const double dy = brace.yield_deformation;
  std::vector<double> deformation{0.0};
  std::vector<int> cycle{0};
  for (int k = 1; k <= 600; ++k) {
    deformation.push_back(-k * dy / 10.0);
    cycle.push_back(1);
  }
  const std::vector<double> amplitude{60.0 * dy};
  const CyclicTestResult result = run_cyclic_test(brace, deformation, cycle, amplitude);
  ASSERT_TRUE(result.completed) << result.stop_reason;

  const double E = spec.steel.youngs_modulus, H = spec.steel.kinematic_hardening;
  const double tangent_modulus = E * H / (E + H);
  const double b = spec.core_section.width, h = spec.core_section.depth;
  const double length = spec.yielding_length;
  const double pi_squared = std::numbers::pi * std::numbers::pi;
  const double tangent_load =
      pi_squared * tangent_modulus * (b * h * h * h / 12.0) / (length * length);
  ASSERT_NEAR(tangent_load, 15019.0, 1.0); // the numbers above
  const double offset_moment =
      2.0 * spec.steel.yield_stress * (1.0 - tangent_modulus / E) * b * h * h / 4.0;

  double peak = 0.0;
  int peak_step = 0;
  for (const CyclicStep& step : result.steps) {
    if (step.force < peak) {
      peak = step.force;
      peak_step = step.step;
    }
  }
  EXPECT_GT(-peak, brace.yield_force);       // it yields first
  EXPECT_LT(-peak, 1.2 * brace.yield_force); // and buckles soon after
  int checked = 0;
  for (const CyclicStep& step : result.steps) {
    if (step.step <= peak_step || step.max_lateral_displacement < 1.0)
      continue;
    EXPECT_GT(-step.force, tangent_load) << "step " << step.step;
    EXPECT_LT(-step.force,
              tangent_load + 4.0 / std::numbers::pi * offset_moment / step.max_lateral_displacement)
        << "step " << step.step;
    ++checked;
  }
  EXPECT_GT(checked, 400);
  // and it keeps falling toward P_t (measured 1.33 P_t at -60 dy)
  EXPECT_LT(-result.steps.back().force, -result.steps[300].force);
}

TEST(BareCore, EnergyBalanceHolds) {
  // Reference: first law, external work = stored + dissipated (trapezoidal work over the
  // steps; the error is of the order of the step size).
  const GironaRun run = run_girona(test::girona_d3_bare_core(8), 1);
  ASSERT_TRUE(run.result.completed);
  EXPECT_GT(run.result.energy_balance.dissipated, 0.0);
  EXPECT_LT(run.result.energy_balance.relative_error(), 2e-3);
  // the loop areas (trapezoids over the recorded steps, as a test report would compute them)
  // agree with the solver's work; they differ where a step contains a jump (buckling)
  EXPECT_NEAR(run.result.energy_total, run.result.energy_balance.external_work,
              1e-2 * run.result.energy_balance.external_work);
}

} // namespace
} // namespace brb::analysis
