// Fidelity against cost of the BRB element: the Girona D3 restrained brace
// (examples/braces/girona_D3_restrained.json) through the Girona protocol
// (examples/protocols/girona.json) as a `truss` and as the `full` model (the expanded brace
// model that `brb cyclic` runs; the condensed element solves the same equations). Reports
// the time per cyclic test and, as counters, the loop energy of the first cycle at 5 dy and
// its error against the test (4,477,444.559 N mm, BRB_SOURCE_FACTS section 7).
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_model.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

namespace {

using namespace brb;

constexpr double kExperimentalLoopEnergy = 4477444.559; // N mm, Girona D3 at 5 dy

const std::filesystem::path kExamples = BRB_SOURCE_DIR "/examples";

void cyclic_test_of(benchmark::State& bench, model::Fidelity fidelity) {
  model::BraceSpec spec = io::read_brace(kExamples / "braces" / "girona_D3_restrained.json");
  spec.element.fidelity = fidelity;
  double loop_energy = 0.0, iterations = 0.0;
  for (auto _ : bench) {
    model::BraceModel brace = fidelity == model::Fidelity::truss
                                  ? model::build_brace_truss_model(spec)
                                  : model::build_brace_model(spec);
    const io::LoadingProtocol protocol =
        io::read_protocol(kExamples / "protocols" / "girona.json", brace.yield_deformation,
                          brace.yield_deformation / 10.0);
    const auto result = analysis::run_cyclic_test(brace, protocol.deformation, protocol.cycle,
                                                  protocol.cycle_amplitude);
    if (!result.completed)
      bench.SkipWithError(result.stop_reason.c_str());
    for (const auto& cycle : result.cycles) {
      if (std::abs(cycle.amplitude - 5.0 * brace.yield_deformation) <
          1e-9 * brace.yield_deformation) {
        loop_energy = cycle.energy; // the first cycle at 5 dy
        break;
      }
    }
    iterations = result.iterations;
  }
  bench.counters["loop_energy_5dy"] = loop_energy;
  bench.counters["loop_energy_error"] = loop_energy / kExperimentalLoopEnergy - 1.0;
  bench.counters["newton_iterations"] = iterations;
}

void TrussGironaD3Restrained(benchmark::State& bench) {
  cyclic_test_of(bench, model::Fidelity::truss);
}
void FullGironaD3Restrained(benchmark::State& bench) {
  cyclic_test_of(bench, model::Fidelity::full);
}
BENCHMARK(TrussGironaD3Restrained)->Unit(benchmark::kMillisecond);
// one run: a full cyclic test takes minutes
BENCHMARK(FullGironaD3Restrained)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
