#include "brb/study/skips_study.hpp"

#include "brb/analysis/cyclic_test.hpp"
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/atomic_file.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_fidelity.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/study/scaling_fit.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace brb::study {

namespace {

/// What one run gives: the compared histories, its CPU time and the skips' hit counts.
struct RunOutcome {
  std::vector<double> values;
  double seconds = 0.0;
  long open_link_hits = 0;
  long reused_hits = 0;
  int steps = 0;
};

/// Largest difference over the largest magnitude of the reference (inf when the histories
/// differ in length: a run stopped early).
double relative_difference(const std::vector<double>& values,
                           const std::vector<double>& reference) {
  if (values.size() != reference.size())
    return std::numeric_limits<double>::infinity();
  double largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    largest = std::max(largest, std::abs(reference[k]));
    difference = std::max(difference, std::abs(values[k] - reference[k]));
  }
  return largest > 0.0 ? difference / largest : difference;
}

bool bitwise_equal(const std::vector<double>& values, const std::vector<double>& reference) {
  if (values.size() != reference.size())
    return false;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!(values[k] == reference[k]) || std::signbit(values[k]) != std::signbit(reference[k]))
      return false;
  }
  return true;
}

// --- cyclic scene ----------------------------------------------------------------------

struct CyclicScene {
  model::BraceSpec spec;
  io::LoadingProtocol protocol;
};

CyclicScene cyclic_scene(const SkipsStudyOptions& options) {
  CyclicScene scene;
  scene.spec = io::read_brace(options.brace_file);
  scene.spec.core_elements = options.core_elements;
  const double dy = model::build_brace_truss_model(scene.spec).yield_deformation;
  std::vector<io::CycleGroup> groups;
  for (const double amplitude : options.amplitudes_dy)
    groups.push_back({amplitude * dy, 1});
  scene.protocol = io::cyclic_protocol("skips", groups, options.max_step_dy * dy);
  return scene;
}

RunOutcome run_cyclic(const CyclicScene& scene, const model::WorkSkips& skips, bool truss) {
  RunOutcome outcome;
  const double start = process_cpu_seconds();
  model::BraceModel brace = truss ? model::build_brace_truss_model(scene.spec, skips)
                                  : model::build_brace_model(scene.spec, skips);
  const analysis::CyclicTestResult result = analysis::run_cyclic_test(
      brace, scene.protocol.deformation, scene.protocol.cycle, scene.protocol.cycle_amplitude);
  outcome.seconds = process_cpu_seconds() - start;
  if (!result.completed)
    throw std::runtime_error("bench skips: the cyclic test stopped: " + result.stop_reason);
  for (const analysis::CyclicStep& step : result.steps)
    outcome.values.push_back(step.force);
  if (brace.casing) {
    for (const element::CasingContact* contact : brace.casing->contacts)
      outcome.open_link_hits += contact->open_evaluations();
  }
  outcome.steps = static_cast<int>(result.steps.size()) - 1;
  return outcome;
}

// --- frame scene -----------------------------------------------------------------------

struct FrameScene {
  model::FrameSpec spec;
  std::string source;
  analysis::GroundAcceleration ground;
  frame::FrameRunOptions options;
};

FrameScene frame_scene(const SkipsStudyOptions& options) {
  FrameScene scene;
  scene.source = options.frame_file.string();
  scene.spec = io::read_frame(options.frame_file);
  scene.spec.set_brace_core_elements(options.frame_core_elements);
  io::GroundMotionOptions motion_options;
  motion_options.scale = options.record_scale;
  const io::GroundMotion motion = io::load_ground_motion(options.record, motion_options);
  scene.ground.dt = motion.dt;
  const auto samples = std::min<std::size_t>(
      motion.acceleration.size(),
      static_cast<std::size_t>(std::floor(options.window / motion.dt + 1e-9)) + 1);
  scene.ground.acceleration.assign(motion.acceleration.begin(),
                                   motion.acceleration.begin() +
                                       static_cast<std::ptrdiff_t>(samples));
  scene.options = frame::run_options_of(scene.spec);
  // what a summary-only run (IDA) asks: drifts and base shear, no brace histories
  scene.options.recorders = {true, false, true, false, {}};
  return scene;
}

RunOutcome run_frame(const FrameScene& scene, const model::WorkSkips& skips,
                     frame::BraceOverride braces) {
  RunOutcome outcome;
  const double start = process_cpu_seconds();
  frame::FrameModel frame = frame::build_frame(scene.spec, scene.source, braces, skips);
  frame::FrameRunOptions options = scene.options;
  options.skips = skips;
  const frame::FrameRunResult result = frame::run_time_history(frame, {scene.ground}, options);
  outcome.seconds = process_cpu_seconds() - start;
  if (!result.converged)
    throw std::runtime_error("bench skips: the frame run stopped: " + result.stop_reason);
  for (const char* name : {"drifts", "base_shear"}) {
    for (const std::vector<double>& row : result.histories.at(name).rows)
      outcome.values.insert(outcome.values.end(), row.begin() + 1, row.end());
  }
  outcome.values.insert(outcome.values.end(), result.max_drift.begin(), result.max_drift.end());
  for (const frame::BraceReference& brace : frame.braces) {
    if (!brace.full)
      continue;
    outcome.reused_hits += brace.full->reused_evaluations();
    for (const element::CasingContact* contact : brace.full->internal_brace().casing->contacts)
      outcome.open_link_hits += contact->open_evaluations();
  }
  outcome.steps = result.steps;
  return outcome;
}

/// Runs `on` and `off` `repeats` times each, interleaved (on off, off on, on off, ...) so that a
/// drift of the shared machine's load falls on both alike; the outcomes of their first runs
/// with the median times.
template <class RunOn, class RunOff>
std::pair<RunOutcome, RunOutcome> paired(int repeats, const RunOn& on, const RunOff& off) {
  RunOutcome first_on = on();
  RunOutcome first_off = off();
  std::vector<double> times_on{first_on.seconds}, times_off{first_off.seconds};
  for (int k = 1; k < repeats; ++k) {
    if (k % 2 == 1) {
      times_off.push_back(off().seconds);
      times_on.push_back(on().seconds);
    } else {
      times_on.push_back(on().seconds);
      times_off.push_back(off().seconds);
    }
  }
  first_on.seconds = median(times_on);
  first_off.seconds = median(times_off);
  return {first_on, first_off};
}

SkipMeasurement compare(const std::string& skip, const std::string& scene, bool exact,
                        const RunOutcome& on, const RunOutcome& off) {
  SkipMeasurement row;
  row.skip = skip;
  row.scene = scene;
  row.exact = exact;
  row.time_on = on.seconds;
  row.time_off = off.seconds;
  row.relative_error = relative_difference(on.values, off.values);
  row.identical = bitwise_equal(on.values, off.values);
  return row;
}

std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

std::string scientific(double value) {
  if (value == 0.0)
    return "0";
  std::ostringstream text;
  text << std::scientific << std::setprecision(2) << value;
  return text.str();
}

} // namespace

std::vector<NamedSkip> named_skips() {
  std::vector<NamedSkip> skips;
  const auto off = [](bool model::WorkSkips::*member) {
    model::WorkSkips skips;
    skips.*member = false;
    return skips;
  };
  skips.push_back({"open_links", off(&model::WorkSkips::open_links), true});
  skips.push_back({"elastic_fast_path", off(&model::WorkSkips::elastic_fast_path), true});
  skips.push_back({"reuse_tangents", off(&model::WorkSkips::reuse_tangents), false});
  skips.push_back({"requested_recorders", off(&model::WorkSkips::requested_recorders), true});
  skips.push_back({"auto", off(&model::WorkSkips::auto_fidelity), false});
  return skips;
}

SkipsStudyResult run_skips_study(const SkipsStudyOptions& options) {
  if (options.repeats < 1)
    throw std::invalid_argument("bench skips: repeats must be >= 1");
  SkipsStudyResult result;
  const int repeats = options.repeats;
  const model::WorkSkips all_on;

  const CyclicScene cyclic = cyclic_scene(options);
  const model::FidelityChoice cyclic_choice = model::choose_auto_fidelity(cyclic.spec);
  result.auto_choice_cyclic = cyclic_choice.reason;
  const FrameScene frame = frame_scene(options);
  {
    const frame::FrameModel built =
        frame::build_frame(frame.spec, frame.source, frame::BraceOverride::automatic);
    long trusses = 0;
    for (const frame::BraceReference& brace : built.braces)
      trusses += brace.truss != nullptr ? 1 : 0;
    result.auto_choice_frame =
        std::to_string(trusses) + " of " + std::to_string(built.braces.size()) + " braces as truss";
  }

  for (const NamedSkip& skip : named_skips()) {
    // cyclic scene: the full model (the brace's `auto` choice for the auto skip)
    const bool auto_skip = skip.name == "auto";
    const bool truss = cyclic_choice.fidelity == model::Fidelity::truss;
    const auto [cyclic_on, cyclic_off] = paired(
        repeats, [&] { return run_cyclic(cyclic, all_on, auto_skip && truss); },
        [&] { return run_cyclic(cyclic, skip.off, false); });
    SkipMeasurement cyclic_row = compare(skip.name, "cyclic", skip.exact, cyclic_on, cyclic_off);
    result.cyclic_steps = cyclic_off.steps;
    cyclic_row.applies = true;
    cyclic_row.hits = -1;
    if (auto_skip) {
      cyclic_row.applies = truss;
      cyclic_row.note = "on: " + cyclic_choice.reason + "; off: full";
    } else if (skip.name == "reuse_tangents" || skip.name == "requested_recorders") {
      cyclic_row.applies = false;
      cyclic_row.hits = 0;
      cyclic_row.note = skip.name == "reuse_tangents"
                            ? "no condensed element in the expanded brace of a cyclic test"
                            : "no frame recorders in a cyclic test";
    } else if (skip.name == "open_links") {
      cyclic_row.hits = cyclic_on.open_link_hits;
    }
    result.rows.push_back(cyclic_row);

    // frame scene: every brace full (at `auto` for the auto skip)
    const frame::BraceOverride braces =
        auto_skip ? frame::BraceOverride::automatic : frame::BraceOverride::full;
    const auto [frame_on, frame_off] = paired(
        repeats, [&] { return run_frame(frame, all_on, braces); },
        [&] { return run_frame(frame, skip.off, braces); });
    SkipMeasurement frame_row = compare(skip.name, "frame", skip.exact, frame_on, frame_off);
    result.frame_steps = frame_off.steps;
    frame_row.applies = true;
    frame_row.hits = skip.name == "open_links"       ? frame_on.open_link_hits
                     : skip.name == "reuse_tangents" ? frame_on.reused_hits
                                                     : -1;
    if (auto_skip) {
      frame_row.applies = result.auto_choice_frame.rfind("0 of", 0) != 0;
      frame_row.note = "on: " + result.auto_choice_frame + "; off: all full";
    }
    result.rows.push_back(frame_row);
  }
  return result;
}

void write_skips_report(const std::filesystem::path& directory, const SkipsStudyOptions& options,
                        const SkipsStudyResult& result) {
  std::ostringstream csv;
  csv << "skip,scene,exact,applies,time_on_s,time_off_s,saved_fraction,relative_error,identical,"
         "hits\n";
  csv << std::setprecision(9);
  for (const SkipMeasurement& row : result.rows) {
    csv << row.skip << "," << row.scene << "," << (row.exact ? 1 : 0) << ","
        << (row.applies ? 1 : 0) << "," << row.time_on << "," << row.time_off << ","
        << row.saved_fraction() << "," << row.relative_error << "," << (row.identical ? 1 : 0)
        << "," << row.hits << "\n";
  }
  io::write_file_atomically(directory / "skips.csv", csv.str());

  std::ostringstream md;
  md << "# Work skips: time saved and error added\n\n"
     << "Generated by `brb bench skips` (DESIGN.md section 10; `include/brb/model/work_skips.hpp`)."
     << " Each skip is switched off alone, all others on, and the run is compared with the run "
        "with every skip on. Times: process CPU seconds, median of "
     << options.repeats
     << " runs. Error: largest difference of the compared histories over "
        "their largest magnitude; *identical*: equal bit for bit.\n\n"
     << "Scenes:\n\n"
     << "- **cyclic**: `" << options.brace_file.filename().string() << "` with "
     << options.core_elements << " core elements, the full (expanded) model, one cycle each at ";
  for (std::size_t k = 0; k < options.amplitudes_dy.size(); ++k)
    md << (k ? ", " : "") << options.amplitudes_dy[k];
  md << " dy in steps of " << options.max_step_dy << " dy (" << result.cyclic_steps
     << " steps). Compared: the force at every step.\n"
     << "- **frame**: `" << options.frame_file.parent_path().filename().string() << "/"
     << options.frame_file.filename().string() << "`, every brace as the full condensed BRB "
     << "element with " << options.frame_core_elements << " core elements, the first "
     << options.window << " s of `" << options.record.filename().string() << "` (x"
     << options.record_scale << ", " << result.frame_steps
     << " steps). Recorders asked: drifts and base shear (as IDA runs ask). Compared: story "
        "drifts and base shear at every step, peak drifts.\n\n"
     << "`auto`: *on* runs the brace(s) at the `auto` choice (cyclic: " << result.auto_choice_cyclic
     << "; frame: " << result.auto_choice_frame << "), *off* as `full`.\n\n"
     << "| skip | scene | exact by construction | applies | CPU on (s) | CPU off (s) | time saved "
        "| relative error | identical | hits |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SkipMeasurement& row : result.rows) {
    md << "| " << row.skip << " | " << row.scene << " | " << (row.exact ? "yes" : "no") << " | "
       << (row.applies ? "yes" : "no") << " | " << fixed(row.time_on, 3) << " | "
       << fixed(row.time_off, 3) << " | " << fixed(100.0 * row.saved_fraction(), 1) << " % | "
       << scientific(row.relative_error) << " | " << (row.identical ? "yes" : "no") << " | "
       << (row.hits >= 0 ? std::to_string(row.hits) : std::string("-")) << " |\n";
  }
  md << "\nNotes:\n\n";
  for (const SkipMeasurement& row : result.rows) {
    if (!row.note.empty())
      md << "- " << row.skip << " (" << row.scene << "): " << row.note << "\n";
  }
  md << "- hits: evaluations answered by the skip (open links: open-link evaluations of all "
        "contact links; reused tangents: BRB element evaluations answered from the last one); "
        "- where not counted.\n"
     << "- Noise: a row whose skip has nothing to do in its scene (applies: no) measures the "
        "same work twice; its time saved is the resolution of these timings on the shared machine "
        "they ran on. Savings smaller than that are not resolved.\n";
  io::write_file_atomically(directory / "SKIPS.md", md.str());
}

} // namespace brb::study
