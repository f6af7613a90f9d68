#include "bench_skips_command.hpp"

#include "output_directory.hpp"

#include "brb/io/input_error.hpp"
#include "brb/study/scaling_study.hpp"
#include "brb/study/skips_study.hpp"

#include <iomanip>

namespace brb::cli {

namespace fs = std::filesystem;

namespace {

fs::path default_record() {
  return fs::path(BRB_DEFAULT_SHARED_DIR) / "data" / "ground_motions" / "RSN77_SFERN_PUL164.AT2";
}

void require_file(const fs::path& file, const std::string& option) {
  if (!fs::is_regular_file(file))
    throw io::InputError(file.string(), option, "an existing file");
}

} // namespace

CLI::App* add_bench_skips_command(CLI::App& bench, BenchSkipsCommand& command) {
  auto* skips = bench.add_subcommand(
      "skips", "Time saved and error added by each work skip (open links, elastic fast path, "
               "reused tangents, requested-only recorders, auto), on a cyclic test of a full "
               "brace and on a frame window with full braces.");
  skips->add_option("--brace", command.brace, "Restrained brace of the cyclic scene")
      ->type_name("BRACE.json")
      ->capture_default_str();
  skips->add_option("--core-elements", command.core_elements, "Its core elements")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  skips->add_option("--amplitudes", command.amplitudes, "Cycle amplitudes (dy), one cycle each")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  skips->add_option("--max-step", command.max_step, "Protocol step (dy)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  skips->add_option("--frame", command.frame, "Frame model of the frame scene")
      ->type_name("MODEL.json")
      ->capture_default_str();
  skips
      ->add_option("--frame-core-elements", command.frame_core_elements,
                   "Core elements of every brace of the frame (all run as full BRB elements)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  skips->add_option("--record", command.record,
                    "Ground motion (default: shared RSN77_SFERN_PUL164.AT2)");
  skips->add_option("--scale", command.scale, "Factor on the record")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  skips->add_option("--window", command.window, "Seconds of record the frame scene runs")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  skips->add_option("--repeats", command.repeats, "Runs per setting (the median time is kept)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  skips->add_option("--out", command.output_directory, "Directory for SKIPS.md and skips.csv")
      ->required();
  return skips;
}

CLI::App* add_bench_scaling_command(CLI::App& bench, BenchScalingCommand& command) {
  auto* scaling = bench.add_subcommand(
      "scaling", "Cost of a frame analysis against the number of braces (generated one-storey "
                 "frames of N braced bays) and against the record length; fitted exponents.");
  scaling->add_option("--frame", command.frame, "Frame whose first storey is copied")
      ->type_name("MODEL.json")
      ->capture_default_str();
  scaling->add_option("--record", command.record,
                      "Ground motion (default: shared RSN77_SFERN_PUL164.AT2)");
  scaling->add_option("--scale", command.scale, "Factor on the record")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  scaling->add_option("--braces", command.brace_counts, "Numbers of braces of the brace series")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  scaling->add_option("--series-length", command.series_length, "Record seconds of that series")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  scaling->add_option("--lengths", command.lengths, "Record lengths (s) of the length series")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  scaling->add_option("--length-braces", command.length_braces, "Braces of the length series")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  scaling->add_option("--fidelity", command.fidelity, "Brace fidelity")
      ->check(CLI::IsMember({"elastic", "truss", "full", "auto"}))
      ->capture_default_str();
  scaling->add_option("--repeats", command.repeats, "Runs per point (the median time is kept)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  scaling->add_option("--out", command.output_directory, "Directory for SCALING.md and scaling.csv")
      ->required();
  return scaling;
}

int run_bench_skips_command(const BenchSkipsCommand& command, std::ostream& report) {
  study::SkipsStudyOptions options;
  options.brace_file = command.brace;
  options.core_elements = command.core_elements;
  options.amplitudes_dy = command.amplitudes;
  options.max_step_dy = command.max_step;
  options.frame_file = command.frame;
  options.frame_core_elements = command.frame_core_elements;
  options.record = command.record.empty() ? default_record() : command.record;
  options.record_scale = command.scale;
  options.window = command.window;
  options.repeats = command.repeats;
  require_file(options.brace_file, "--brace");
  require_file(options.frame_file, "--frame");
  require_file(options.record, "--record");
  check_output_directory(command.output_directory);

  const study::SkipsStudyResult result = study::run_skips_study(options);
  fs::create_directory(command.output_directory);
  study::write_skips_report(command.output_directory, options, result);
  report
      << "skip                 scene   CPU on (s)  CPU off (s)  saved    rel. error  identical\n";
  for (const study::SkipMeasurement& row : result.rows) {
    report << std::left << std::setw(21) << row.skip << std::setw(8) << row.scene << std::right
           << std::fixed << std::setprecision(3) << std::setw(10) << row.time_on << std::setw(13)
           << row.time_off << std::setw(7) << std::setprecision(1) << 100.0 * row.saved_fraction()
           << " %" << std::scientific << std::setprecision(2) << std::setw(12) << row.relative_error
           << "  " << (row.identical ? "yes" : "no") << std::defaultfloat << "\n";
  }
  report << "wrote " << (command.output_directory / "SKIPS.md").string() << " and skips.csv\n";
  return 0;
}

int run_bench_scaling_command(const BenchScalingCommand& command, std::ostream& report) {
  study::ScalingStudyOptions options;
  options.frame_file = command.frame;
  options.record = command.record.empty() ? default_record() : command.record;
  options.record_scale = command.scale;
  options.brace_counts = command.brace_counts;
  options.brace_series_length = command.series_length;
  options.record_lengths = command.lengths;
  options.length_series_braces = command.length_braces;
  options.braces = *frame::brace_override_named(command.fidelity);
  options.repeats = command.repeats;
  require_file(options.frame_file, "--frame");
  require_file(options.record, "--record");
  if (options.brace_counts.size() < 2 || options.record_lengths.size() < 2)
    throw io::InputError("command line", "--braces/--lengths",
                         "at least two values each (an exponent is fitted)");
  check_output_directory(command.output_directory);

  const study::ScalingStudyResult result = study::run_scaling_study(options);
  fs::create_directory(command.output_directory);
  study::write_scaling_report(command.output_directory, options, result);
  report << "series          braces  record (s)  steps     DOF   CPU (s)\n";
  for (const auto* series : {&result.brace_series, &result.length_series}) {
    for (const study::ScalingPoint& point : *series) {
      report << std::left << std::setw(16) << point.series << std::right << std::setw(6)
             << point.braces << std::setw(12) << point.record_length << std::setw(7) << point.steps
             << std::setw(8) << point.equations << std::fixed << std::setprecision(4)
             << std::setw(10) << point.seconds << std::defaultfloat << "\n";
    }
  }
  report << "exponent against braces: " << result.brace_fit.exponent
         << ", against record length: " << result.length_fit.exponent << "\n"
         << "wrote " << (command.output_directory / "SCALING.md").string() << " and scaling.csv\n";
  return 0;
}

} // namespace brb::cli
