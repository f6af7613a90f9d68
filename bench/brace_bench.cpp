// Cost of the bare-core cyclic test: a 16-element co-rotational fiber core with 40 fibers
// per section (Girona D3 geometry), through the Girona protocol (two final 5 dy cycles).
// Reports the time per cyclic test and, as counters, Newton iterations per test and the
// time per Newton iteration (assembly of every element with all its fibers, and a solve).
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/protocol.hpp"

#include "support/brace_fixtures.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace brb;

model::BraceSpec bench_core() {
  model::BraceSpec spec = test::girona_d3_bare_core(16);
  spec.core_section.fibers_a = 5; // rings
  spec.core_section.fibers_b = 8; // sectors: 40 fibers
  return spec;
}

void BareCoreGironaCyclicTest(benchmark::State& bench) {
  const model::BraceSpec spec = bench_core();
  double iterations = 0.0, tests = 0.0;
  for (auto _ : bench) {
    model::BraceModel brace = model::build_brace_model(spec);
    const io::LoadingProtocol protocol =
        io::girona_protocol(brace.yield_deformation, 2, brace.yield_deformation / 10.0);
    const auto result = analysis::run_cyclic_test(brace, protocol.deformation, protocol.cycle,
                                                  protocol.cycle_amplitude);
    if (!result.completed)
      bench.SkipWithError(result.stop_reason.c_str());
    iterations += result.iterations;
    tests += 1.0;
  }
  bench.counters["newton_iterations"] = iterations / tests;
  bench.counters["time_per_iteration"] =
      benchmark::Counter(iterations, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BareCoreGironaCyclicTest)->Unit(benchmark::kMillisecond);

} // namespace
