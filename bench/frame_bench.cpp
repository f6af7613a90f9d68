// Cost of a nonlinear time-history analysis of the example frames (frames/brbf3 and
// frames/brbf9) under one shared record, Pacoima Dam 1971 (RSN77_SFERN_PUL164.AT2), with
// every brace built as an elastic truss
// (the reference), as a `truss`, at `auto` and as the `full` BRB element (condensed).
// The full element solves its whole internal brace model at every global iteration (minutes
// per second of record), so every setting runs the same window: the first kWindow = 2 s of
// the record, before the main pulse (the braces stay near elastic: the window measures the
// cost of carrying full braces, not of their yielding). Counters: peak story drift and
// steps. Ratios to the elastic frame are what the README quotes (same machine, same run).
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace {

using namespace brb;

constexpr double kWindow = 2.0; // s of record

const std::filesystem::path kFrames = BRB_SOURCE_DIR "/frames";
const std::filesystem::path kRecord =
    BRB_SOURCE_DIR "/../shared/data/ground_motions/RSN77_SFERN_PUL164.AT2";

void frame_under_record(benchmark::State& bench, const char* building,
                        frame::BraceOverride braces) {
  const std::filesystem::path file = kFrames / building / "model.json";
  const model::FrameSpec spec = io::read_frame(file);
  const io::GroundMotion motion = io::read_peer_at2(kRecord);
  analysis::GroundAcceleration ground;
  ground.dt = motion.dt;
  ground.acceleration.assign(
      motion.acceleration.begin(),
      motion.acceleration.begin() +
          std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(motion.acceleration.size()),
                                   std::lround(kWindow / motion.dt) + 1));
  frame::FrameRunOptions options = frame::run_options_of(spec);
  options.recorders = {false, false, false, false, {}};
  double peak = 0.0, steps = 0.0;
  for (auto _ : bench) {
    frame::FrameModel frame = frame::build_frame(spec, file.string(), braces);
    const frame::FrameRunResult result = frame::run_time_history(frame, {ground}, options);
    if (!result.converged)
      bench.SkipWithError(result.stop_reason.c_str());
    peak = *std::max_element(result.max_drift.begin(), result.max_drift.end());
    steps = result.steps;
  }
  bench.counters["peak_drift"] = peak;
  bench.counters["steps"] = steps;
}

} // namespace

BENCHMARK_CAPTURE(frame_under_record, brbf3_elastic, "brbf3", frame::BraceOverride::elastic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(frame_under_record, brbf3_truss, "brbf3", frame::BraceOverride::truss)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(frame_under_record, brbf3_auto, "brbf3", frame::BraceOverride::automatic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(frame_under_record, brbf3_full, "brbf3", frame::BraceOverride::full)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(frame_under_record, brbf9_elastic, "brbf9", frame::BraceOverride::elastic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(frame_under_record, brbf9_truss, "brbf9", frame::BraceOverride::truss)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(frame_under_record, brbf9_auto, "brbf9", frame::BraceOverride::automatic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(frame_under_record, brbf9_full, "brbf9", frame::BraceOverride::full)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
