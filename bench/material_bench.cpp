// Cost of one material update (evaluate + commit) on the fiber hot path, in ns.
// The history is a cyclic strain path with growing amplitude (0.25 .. 5 eps_y, the Girona
// sequence in strain), so most updates are plastic, as in a yielding BRB core.
#include "brb/material/fiber_condensation.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace brb::material;

SteelParameters bench_steel() {
  SteelParameters steel;
  steel.youngs_modulus = 210000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 275.0;
  steel.kinematic_hardening = 2000.0;
  steel.chaboche = {{12000.0, 120.0}, {3000.0, 15.0}};
  steel.voce_saturation = 40.0;
  steel.voce_rate = 12.0;
  steel.damage = SteelDamageParameters{430.0, 300.0};
  return steel;
}

MortarParameters bench_mortar() {
  MortarParameters mortar;
  mortar.youngs_modulus = 17520.0;
  mortar.poissons_ratio = 0.2;
  mortar.compressive_strength = 39.92;
  mortar.tensile_strength = 3.992;
  mortar.fracture_energy = 0.75;
  return mortar;
}

/// Cycles at 0.25, 0.5, 0.75, 1, 2, 2.5, 5, 5, 5 x yield_strain, 40 points per cycle.
std::vector<double> cyclic_history(double yield_strain) {
  std::vector<double> history;
  for (const double multiple : {0.25, 0.5, 0.75, 1.0, 2.0, 2.5, 5.0, 5.0, 5.0}) {
    for (int i = 0; i < 40; ++i) {
      history.push_back(multiple * yield_strain * std::sin(2.0 * M_PI * i / 40.0));
    }
  }
  return history;
}

template <class Law> void run_uniaxial(benchmark::State& bench, const Law& law, double yield) {
  const std::vector<double> history = cyclic_history(yield);
  auto state = law.initial_state();
  std::size_t point = 0;
  for (auto _ : bench) {
    const auto response = law.evaluate(state, history[point]);
    benchmark::DoNotOptimize(response.stress);
    state = response.state;
    if (++point == history.size()) {
      point = 0;
      state = law.initial_state();
    }
  }
  bench.SetItemsProcessed(bench.iterations());
}

template <class Fiber>
void run_condensed(benchmark::State& bench, const Fiber& fiber, double yield) {
  const std::vector<double> history = cyclic_history(yield);
  auto state = fiber.initial_state();
  std::size_t point = 0;
  for (auto _ : bench) {
    const auto response = fiber.evaluate(state, Eigen::Matrix<double, 1, 1>(history[point]));
    benchmark::DoNotOptimize(response.stress);
    state = response.state;
    if (++point == history.size()) {
      point = 0;
      state = fiber.initial_state();
    }
  }
  bench.SetItemsProcessed(bench.iterations());
}

void SteelClosedFormUniaxial(benchmark::State& bench) {
  run_uniaxial(bench, SteelUniaxial(bench_steel(), 50.0), 275.0 / 210000.0);
}
BENCHMARK(SteelClosedFormUniaxial);

void SteelCondensed3D(benchmark::State& bench) {
  using Fiber = FiberCondensation<SteelDamagePlasticity3D, FiberStressState::uniaxial>;
  run_condensed(bench, Fiber(SteelDamagePlasticity3D(bench_steel(), 50.0)), 275.0 / 210000.0);
}
BENCHMARK(SteelCondensed3D);

void MortarUniaxialLaw(benchmark::State& bench) {
  // cycles up to 5 x the compressive peak strain: damage loading in both signs
  run_uniaxial(bench, MortarUniaxial(bench_mortar(), 50.0), 39.92 / 17520.0);
}
BENCHMARK(MortarUniaxialLaw);

void MortarCondensed3D(benchmark::State& bench) {
  using Fiber = FiberCondensation<MortarDamage3D, FiberStressState::uniaxial>;
  run_condensed(bench, Fiber(MortarDamage3D(bench_mortar(), 50.0)), 39.92 / 17520.0);
}
BENCHMARK(MortarCondensed3D);

} // namespace
