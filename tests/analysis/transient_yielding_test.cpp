// A yielding oscillator: a BraceTruss (closed-form uniaxial steel, linear kinematic hardening)
// carrying a mass under a strong half-sine ground pulse. References: the energy balance of
// the relative formulation (Uang and Bertero 1990), input = kinetic + damping + stored +
// dissipated, whose misfit for average acceleration comes only from the trapezoidal rule
// across the yield kinks; the dissipated energy of the steel law must be positive and the
// oscillator must yield (peak deformation beyond f_y L / E).
#include "brb/analysis/transient_analysis.hpp"
#include "brb/element/brace_truss.hpp"
#include "brb/model/dof_map.hpp"
#include "support/oscillator_models.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(TransientYielding, BraceTrussOscillatorBalancesItsEnergy) {
  element::BraceTrussParameters brace;
  brace.steel.youngs_modulus = 200000.0;
  brace.steel.yield_stress = 250.0;
  brace.steel.kinematic_hardening = 2000.0;
  brace.core_area = 1000.0;
  brace.yielding_length = 3000.0;
  const double stiffness = brace.steel.youngs_modulus * brace.core_area / brace.yielding_length;
  const double yield_deformation =
      brace.steel.yield_stress * brace.yielding_length / brace.steel.youngs_modulus; // 3.75 mm
  const double period = 0.5, w = 2.0 * kPi / period, mass = stiffness / (w * w);

  model::Model model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = test::add_x_oscillator_node(model, brace.yielding_length, 0.0, mass);
  model.add_element(std::make_unique<element::BraceTruss>(
      std::array<int, 2>{ground, node}, model.coordinates(ground), model.coordinates(node), brace));
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  DampingSpec damping;
  damping.mass_factor = 2.0 * 0.02 * w;
  analysis.set_damping(damping);
  GroundAcceleration pulse;
  pulse.dt = 0.01;
  for (int i = 0; i <= 30; ++i)
    pulse.acceleration.push_back(800.0 * std::sin(kPi * i / 30.0)); // 0.08 g over 0.3 s
  analysis.add_ground_acceleration(pulse);

  const int ux = model::Model::global_dof(node, model::ux);
  double peak = 0.0, largest_input = 0.0, largest_error = 0.0;
  for (int n = 0; n < 400; ++n) { // 2 s
    const TransientStepReport report = analysis.step(0.005);
    ASSERT_TRUE(report.converged) << report.failure;
    peak = std::max(peak, std::abs(analysis.displacement()[ux]));
    const TransientEnergy& energy = analysis.energy();
    largest_input = std::max(largest_input, std::abs(energy.input));
    largest_error = std::max(largest_error, std::abs(energy.absolute_error()));
  }
  const TransientEnergy& energy = analysis.energy();
  EXPECT_GT(peak, 2.0 * yield_deformation); // it yields (measured: see the report)
  EXPECT_GT(energy.dissipated, 0.0);
  EXPECT_GT(energy.dissipated, 0.2 * energy.input); // hysteresis takes a real share
  EXPECT_LT(largest_error, 1e-3 * largest_input);
  EXPECT_LT(energy.relative_error(), 1e-3);
  EXPECT_GE(energy.gross_input, energy.input);
  std::cout << "[ measured ] peak " << peak << " mm (" << peak / yield_deformation << " dy), input "
            << energy.input << " N mm, dissipated " << energy.dissipated << ", damping "
            << energy.damping << ", balance error " << largest_error / largest_input
            << " of the input\n";
}

} // namespace
} // namespace brb::analysis
