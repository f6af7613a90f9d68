#include "spectrum_command.hpp"

#include "brb/analysis/sdof_exact.hpp"
#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/ground_motion.hpp"
#include "brb/io/input_error.hpp"

#include <array>
#include <cmath>
#include <iomanip>
#include <vector>

namespace brb::cli {
namespace {

constexpr const char* kCommandLine = "command line";
/// Periods of the spectrum: 100 per decade from 0.01 s to 10 s (301 periods).
constexpr double kShortestPeriod = 0.01;
constexpr double kLongestPeriod = 10.0;
constexpr int kPeriodsPerDecade = 100;

io::GroundMotionOptions motion_options(const SpectrumCommand& command) {
  io::GroundMotionOptions options;
  const auto format = io::ground_motion_format_named(command.format);
  if (!format) {
    throw io::InputError(kCommandLine, "--format",
                         "expected auto, at2, csv or column, got \"" + command.format + "\"");
  }
  options.format = *format;
  if (command.units)
    options.units = io::parse_acceleration_units(*command.units, kCommandLine, "--units");
  if (command.dt && !(*command.dt > 0.0 && std::isfinite(*command.dt))) {
    throw io::InputError(kCommandLine, "--dt",
                         "expected a time step > 0 s, got " + io::format_number(*command.dt));
  }
  options.dt = command.dt;
  if (!std::isfinite(command.scale) || command.scale == 0.0) {
    throw io::InputError(kCommandLine, "--scale",
                         "expected a finite, non-zero factor, got " +
                             io::format_number(command.scale));
  }
  options.scale = command.scale;
  return options;
}

/// The output's directory must exist: say so as an input error rather than fail to write.
void check_output_file(const std::filesystem::path& output) {
  if (output.filename().empty())
    throw io::InputError(output.string(), "", "--out must name a file, not a directory");
  const auto directory = output.parent_path();
  if (!directory.empty() && !std::filesystem::is_directory(directory)) {
    throw io::InputError(output.string(), "",
                         "cannot write the output: directory '" + directory.string() +
                             "' does not exist");
  }
}

} // namespace

CLI::App* add_spectrum_command(CLI::App& app, SpectrumCommand& command) {
  auto* spectrum = app.add_subcommand(
      "spectrum", "Pseudo-acceleration response spectrum of a ground motion (exact "
                  "piecewise-linear SDOF solution, Nigam-Jennings).");
  spectrum
      ->add_option("motion", command.motion,
                   "Ground motion: PEER .AT2, CSV (time,accel or one column accel), or one "
                   "value per line (.rec, .txt)")
      ->required();
  spectrum->add_option("--units", command.units,
                       "Units of the record's values: g, m/s^2 or mm/s^2 (required unless an AT2 "
                       "header states them; overrides it)");
  spectrum->add_option("--dt", command.dt,
                       "Time step, s (required for one-column files; must agree with the "
                       "file's own)");
  spectrum->add_option("--scale", command.scale, "Scale factor on the record (default 1)");
  spectrum->add_option("--damping", command.damping_ratio,
                       "Damping ratio zeta of the oscillators, 0 <= zeta < 1 (default 0.05)");
  spectrum->add_option("--format", command.format,
                       "auto (from the extension: .at2, .csv, .rec/.txt), at2, csv or column");
  spectrum
      ->add_option("--out", command.output,
                   "Output CSV: period (s), Sa_g (pseudo-acceleration omega^2 max|u|, g); "
                   "100 periods per decade, 0.01 s to 10 s")
      ->required();
  spectrum->footer("Exit status: 0 success, 1 run failed, 2 invalid input or usage.");
  return spectrum;
}

int run_spectrum_command(const SpectrumCommand& command, std::ostream& notes) {
  const io::GroundMotionOptions options = motion_options(command);
  if (!(command.damping_ratio >= 0.0 && command.damping_ratio < 1.0)) {
    throw io::InputError(kCommandLine, "--damping",
                         "expected a damping ratio in [0, 1), got " +
                             io::format_number(command.damping_ratio));
  }
  const io::GroundMotion motion = io::load_ground_motion(command.motion, options);
  check_output_file(command.output);

  const std::vector<double> periods =
      analysis::log_spaced_periods(kShortestPeriod, kLongestPeriod, kPeriodsPerDecade);
  const std::vector<double> spectrum =
      analysis::response_spectrum(motion, periods, command.damping_ratio);
  io::NumericTable table({"period", "Sa_g"});
  for (std::size_t k = 0; k < periods.size(); ++k)
    table.append_row(std::array{periods[k], spectrum[k] / io::kStandardGravity});
  io::write_file_atomically(command.output, table.text());

  notes << "brb spectrum: " << motion.name << ": " << motion.acceleration.size() << " points, dt "
        << motion.dt << " s, PGA " << std::setprecision(4)
        << motion.peak_acceleration() / io::kStandardGravity << " g; " << periods.size()
        << " periods written to " << command.output.string() << "\n";
  return 0;
}

} // namespace brb::cli
