// Checkpoints of a cyclic test (io/state_archive.hpp, CyclicTest::save_state/load_state,
// run_cyclic_test's CyclicCheckpoint): a run taken up from a checkpoint must give the results
// of the run that never stopped, to the bit. So must a run whose elements are evaluated on
// several threads (NewtonSettings::element_threads). The brace is the source's small BRB of case 3
// (validation/thesis_small_case3: a 10 x 10 mm core in a mortar casing at 0.3 mm clearance,
// friction, the core buckling in the gap), through its first cycles: its steps need
// substepping, energy cuts and far-branch cuts, so the taken-up part runs the solver's
// fallbacks from the loaded state.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/io/state_archive.hpp"

#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>

namespace brb::analysis {
namespace {

namespace fs = std::filesystem;

const fs::path kSmallBrace = fs::path(BRB_SOURCE_DIR) / "validation/thesis_small_case3/brace.json";

model::BraceSpec small_brace(int core_elements_factor = 1) {
  model::BraceSpec spec = io::read_brace(kSmallBrace);
  spec.core_elements *= core_elements_factor;
  return spec;
}

/// Cycles at 1, 2, 3 and 5 dy in steps of dy / 10 (case 3's first four cycles).
io::LoadingProtocol small_protocol(double yield_deformation) {
  return io::cyclic_protocol("case 3, first cycles",
                             {{1.0 * yield_deformation, 1},
                              {2.0 * yield_deformation, 1},
                              {3.0 * yield_deformation, 1},
                              {5.0 * yield_deformation, 1}},
                             yield_deformation / 10.0);
}

/// Every number a run reports, compared exactly.
void expect_same_run(const CyclicTestResult& taken_up, const CyclicTestResult& reference) {
  ASSERT_TRUE(reference.completed) << reference.stop_reason;
  EXPECT_TRUE(taken_up.completed) << taken_up.stop_reason;
  ASSERT_EQ(taken_up.steps.size(), reference.steps.size());
  for (std::size_t k = 0; k < reference.steps.size(); ++k) {
    const CyclicStep& a = taken_up.steps[k];
    const CyclicStep& b = reference.steps[k];
    EXPECT_EQ(a.step, b.step);
    EXPECT_EQ(a.cycle, b.cycle);
    EXPECT_EQ(a.deformation, b.deformation) << "step " << k;
    EXPECT_EQ(a.force, b.force) << "step " << k;
    EXPECT_EQ(a.max_lateral_displacement, b.max_lateral_displacement) << "step " << k;
    EXPECT_EQ(a.substeps, b.substeps) << "step " << k;
    if (a.force != b.force)
      break; // one message is enough to see where the paths part
  }
  ASSERT_EQ(taken_up.cycles.size(), reference.cycles.size());
  for (std::size_t c = 0; c < reference.cycles.size(); ++c)
    EXPECT_EQ(taken_up.cycles[c].energy, reference.cycles[c].energy) << "cycle " << c + 1;
  EXPECT_EQ(taken_up.energy_total, reference.energy_total);
  EXPECT_EQ(taken_up.energy_balance.external_work, reference.energy_balance.external_work);
  EXPECT_EQ(taken_up.energy_balance.stored, reference.energy_balance.stored);
  EXPECT_EQ(taken_up.energy_balance.dissipated, reference.energy_balance.dissipated);
  EXPECT_EQ(taken_up.energy_balance.released_in_jumps, reference.energy_balance.released_in_jumps);
  EXPECT_EQ(taken_up.energy_balance.gross_work, reference.energy_balance.gross_work);
  EXPECT_EQ(taken_up.iterations, reference.iterations);
  EXPECT_EQ(taken_up.substeps, reference.substeps);
  EXPECT_EQ(taken_up.regularised_steps, reference.regularised_steps);
  EXPECT_EQ(taken_up.energy_cuts, reference.energy_cuts);
  EXPECT_EQ(taken_up.far_branch_cuts, reference.far_branch_cuts);
  EXPECT_EQ(taken_up.work.assemblies, reference.work.assemblies);
  EXPECT_EQ(taken_up.work.line_search_assemblies, reference.work.line_search_assemblies);
  EXPECT_EQ(taken_up.work.failed_newton_iterations, reference.work.failed_newton_iterations);
  EXPECT_EQ(taken_up.work.pseudo_time_steps, reference.work.pseudo_time_steps);
  EXPECT_EQ(taken_up.indicators.max_mortar_damage, reference.indicators.max_mortar_damage);
  EXPECT_EQ(taken_up.indicators.max_buckling_half_waves,
            reference.indicators.max_buckling_half_waves);
  EXPECT_EQ(taken_up.indicators.cumulative_inelastic_deformation,
            reference.indicators.cumulative_inelastic_deformation);
  EXPECT_EQ(taken_up.indicators.max_core_lateral_displacement,
            reference.indicators.max_core_lateral_displacement);
  ASSERT_EQ(taken_up.history.size(), reference.history.size());
  if (!reference.history.empty()) {
    EXPECT_EQ(taken_up.history.back().dissipated_energy,
              reference.history.back().dissipated_energy);
  }
}

struct Reference {
  io::LoadingProtocol protocol;
  CyclicTestResult result;
};

/// The uninterrupted run, with its element histories.
const Reference& reference_run() {
  static const Reference reference = [] {
    model::BraceModel brace = model::build_brace_model(small_brace());
    Reference run{small_protocol(brace.yield_deformation), {}};
    run.result = run_cyclic_test(brace, run.protocol.deformation, run.protocol.cycle,
                                 run.protocol.cycle_amplitude, {}, /*record_history=*/true);
    return run;
  }();
  return reference;
}

/// The first point of the 5 dy cycle's compression excursion past -3 dy: where the core
/// buckles in the gap and the solver cuts steps.
std::size_t split_point(const io::LoadingProtocol& protocol, double yield_deformation) {
  for (std::size_t k = 0; k < protocol.deformation.size(); ++k)
    if (protocol.cycle[k] == 4 && protocol.deformation[k] < -3.0 * yield_deformation)
      return k;
  throw std::logic_error("no such point");
}

/// The last point of cycle 3 (CyclicTest::follow closes a cycle at the end of the points it
/// is given, so a run split by hand splits between cycles; run_cyclic_test's checkpoints fall
/// anywhere, the next test).
std::size_t end_of_third_cycle(const io::LoadingProtocol& protocol) {
  for (std::size_t k = 0; k + 1 < protocol.deformation.size(); ++k)
    if (protocol.cycle[k] == 3 && protocol.cycle[k + 1] == 4)
      return k;
  throw std::logic_error("no such point");
}

TEST(CyclicCheckpoint, ATakenUpRunGivesTheUninterruptedRunsResultsToTheBit) {
  const Reference& reference = reference_run();
  const io::LoadingProtocol& protocol = reference.protocol;
  const std::span<const double> deformation(protocol.deformation);
  const std::span<const int> cycle(protocol.cycle);

  // the first run stops after the 3 dy cycle and writes its state
  model::BraceModel first_brace = model::build_brace_model(small_brace());
  const std::size_t split = end_of_third_cycle(protocol);
  io::StateWriter out;
  int fallbacks_before = 0;
  {
    CyclicTest first(first_brace, {}, /*record_history=*/true);
    ASSERT_TRUE(first.follow(deformation.subspan(1, split), cycle.subspan(1, split),
                             protocol.cycle_amplitude));
    first.save_state(out);
    const CyclicTestResult partial = first.result();
    fallbacks_before = partial.substeps + partial.energy_cuts + partial.far_branch_cuts;
  }

  // a second brace, built from the same file, takes it up
  model::BraceModel second_brace = model::build_brace_model(small_brace());
  CyclicTest second(second_brace, {}, /*record_history=*/true);
  io::StateReader in(out.bytes(), "in memory");
  second.load_state(in);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(second.steps_done(), static_cast<int>(split));
  ASSERT_TRUE(second.follow(deformation.subspan(split + 1), cycle.subspan(split + 1),
                            protocol.cycle_amplitude));
  CyclicTestResult taken_up = second.result();
  taken_up.steps.front().cycle = protocol.cycle[0];
  expect_same_run(taken_up, reference.result);

  // the taken-up part ran the solver's fallbacks (else this test would prove little)
  const CyclicTestResult& whole = reference.result;
  EXPECT_GT(whole.substeps + whole.energy_cuts + whole.far_branch_cuts, fallbacks_before + 20);
  EXPECT_GT(whole.indicators.max_buckling_half_waves, 0);
}

TEST(ElementThreads, ARunOnThreadsGivesTheOneThreadRunsResultsToTheBit) {
  const Reference& reference = reference_run();
  // 3 threads on any machine: more threads than cores still gives every element its own
  // buffers, and the sums are taken in element order
  NewtonSettings settings;
  settings.element_threads = 3;
  model::BraceModel brace = model::build_brace_model(small_brace());
  const CyclicTestResult threaded =
      run_cyclic_test(brace, reference.protocol.deformation, reference.protocol.cycle,
                      reference.protocol.cycle_amplitude, settings, /*record_history=*/true);
  expect_same_run(threaded, reference.result);
  // the run went through the solver's fallbacks (line searches, cuts, pseudo-time)
  EXPECT_GT(reference.result.work.line_search_assemblies, 0);
  EXPECT_GT(reference.result.substeps, static_cast<int>(reference.protocol.deformation.size()));
}

TEST(CyclicCheckpoint, ARunKilledAfterACheckpointIsTakenUpFromTheFile) {
  const Reference& reference = reference_run();
  const io::LoadingProtocol& protocol = reference.protocol;
  const testing::ScratchDirectory scratch;
  // a checkpoint after every step (any interval below one step's wall time)
  const CyclicCheckpoint checkpoint{scratch.path() / "run.checkpoint", 1e-12, "the run's key"};
  model::BraceModel brace = model::build_brace_model(small_brace());
  const std::size_t kill_at = split_point(protocol, brace.yield_deformation);
  // the observer runs before the checkpoint is written: "killed" at step kill_at, the file
  // holds step kill_at - 1
  struct Killed {};
  const StepObserver kill = [&](const CyclicStep& step) {
    if (static_cast<std::size_t>(step.step) == kill_at)
      throw Killed{};
  };
  EXPECT_THROW(run_cyclic_test(brace, protocol.deformation, protocol.cycle,
                               protocol.cycle_amplitude, {}, true, std::nullopt, kill, checkpoint),
               Killed);
  ASSERT_TRUE(fs::exists(checkpoint.file));

  model::BraceModel fresh = model::build_brace_model(small_brace());
  const CyclicTestResult taken_up =
      run_cyclic_test(fresh, protocol.deformation, protocol.cycle, protocol.cycle_amplitude, {},
                      true, std::nullopt, {}, checkpoint);
  EXPECT_EQ(taken_up.resumed_from_step, static_cast<int>(kill_at) - 1);
  EXPECT_GE(taken_up.seconds_before_resume, 0.0);
  expect_same_run(taken_up, reference.result);
  // run_cyclic_test leaves the file to its caller (removed once the outputs are written)
  EXPECT_TRUE(fs::exists(checkpoint.file));
}

/// A checkpoint of the small brace after a few steps, written to `file`.
void write_small_checkpoint(const fs::path& file, const std::string& key) {
  model::BraceModel brace = model::build_brace_model(small_brace());
  const io::LoadingProtocol protocol = small_protocol(brace.yield_deformation);
  CyclicTest test(brace);
  ASSERT_TRUE(test.follow(std::span(protocol.deformation).subspan(1, 15),
                          std::span(protocol.cycle).subspan(1, 15), protocol.cycle_amplitude));
  write_checkpoint(test, CyclicCheckpoint{file, 600.0, key}, 1.5);
}

TEST(CyclicCheckpoint, ACheckpointOfAnotherRunOrModelIsRefused) {
  const testing::ScratchDirectory scratch;
  const fs::path file = scratch.path() / "small.checkpoint";
  write_small_checkpoint(file, "small brace");

  { // read back by the same run: 15 steps, 1.5 s before
    model::BraceModel brace = model::build_brace_model(small_brace());
    CyclicTest test(brace);
    const ResumedRun resumed = read_checkpoint(test, CyclicCheckpoint{file, 600.0, "small brace"});
    EXPECT_EQ(resumed.steps, 15);
    EXPECT_EQ(resumed.elapsed_seconds, 1.5);
  }
  const auto refused = [&](const model::BraceSpec& spec, const std::string& key,
                           const std::string& expected) {
    model::BraceModel brace = model::build_brace_model(spec);
    CyclicTest test(brace);
    try {
      read_checkpoint(test, CyclicCheckpoint{file, 600.0, key});
      ADD_FAILURE() << "read a checkpoint it should refuse (" << expected << ")";
    } catch (const io::CheckpointMismatch& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(file.string()), std::string::npos) << message;
      EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
  };
  refused(small_brace(), "another run", "written for another run");
  refused(small_brace(2), "small brace", "where this one has"); // twice the core elements

  // a truncated file (a copy cut in the middle of the model's state)
  std::ifstream in(file, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  bytes.resize(bytes.size() / 2);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  refused(small_brace(), "small brace", "ends early");
  // not a checkpoint at all
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "step,deformation\n0,0\n";
  refused(small_brace(), "small brace", "not a checkpoint");
}

TEST(StateArchive, NumbersListsAndOptionalsRoundTripExactly) {
  io::StateWriter out;
  const double third = 1.0 / 3.0;
  const std::vector<double> values{third, -0.0, 1e-300, 6.02e23};
  const std::optional<int> some = 7;
  const std::optional<int> none;
  const Eigen::Matrix3d rotation = Eigen::Matrix3d::Random();
  out(third, values, some, none, rotation, std::string("key"), true);

  double third_back = 0.0;
  std::vector<double> values_back(4);
  std::optional<int> some_back, none_back = 3;
  Eigen::Matrix3d rotation_back;
  std::string key;
  bool flag = false;
  io::StateReader in(out.bytes(), "test");
  in(third_back, values_back, some_back, none_back, rotation_back, key, flag);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(third_back, third);
  EXPECT_EQ(values_back, values);
  EXPECT_TRUE(std::signbit(values_back[1]));
  EXPECT_EQ(some_back, some);
  EXPECT_FALSE(none_back.has_value());
  EXPECT_EQ(rotation_back, rotation);
  EXPECT_EQ(key, "key");
  EXPECT_TRUE(flag);

  // a list of the model keeps its size: another size is a mismatch, not a resize
  std::vector<double> shorter(3);
  io::StateReader again(out.bytes(), "test");
  double skipped = 0.0;
  again(skipped);
  EXPECT_THROW(again(shorter), io::CheckpointMismatch);
}

} // namespace
} // namespace brb::analysis
