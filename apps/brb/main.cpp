// brb: the command-line program. Exit status: 0 success, 1 the run failed (analysis did
// not converge, output could not be written, ...), 2 invalid input or usage.
#include "bench_pareto_command.hpp"
#include "bench_skips_command.hpp"
#include "bench_stress_command.hpp"
#include "brb/io/state_archive.hpp"
#include "calibrate_command.hpp"
#include "check_command.hpp"
#include "cyclic_command.hpp"
#include "frame_command.hpp"
#include "ida_command.hpp"
#include "material_command.hpp"
#include "solid_command.hpp"
#include "spectrum_command.hpp"
#include "validate_command.hpp"

#include "brb/io/input_error.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

namespace {

constexpr int kRunFailed = 1;
constexpr int kInvalidInput = 2;

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"brb: reduced-order analysis of buckling-restrained braces.\n"
               "Units everywhere: N, mm, s, MPa, tonne.",
               "brb"};
  app.require_subcommand(1);

  brb::cli::MaterialCommand material_command;
  const CLI::App* material = brb::cli::add_material_command(app, material_command);
  brb::cli::CyclicCommand cyclic_command;
  const CLI::App* cyclic = brb::cli::add_cyclic_command(app, cyclic_command);
  brb::cli::SolidCommand solid_command;
  const CLI::App* solid = brb::cli::add_solid_command(app, solid_command);
  brb::cli::FrameCommand frame_command;
  const CLI::App* frame = brb::cli::add_frame_command(app, frame_command);
  brb::cli::IdaCommand ida_command;
  const CLI::App* ida = brb::cli::add_ida_command(app, ida_command);
  brb::cli::ValidateCommand validate_command;
  const CLI::App* validate = brb::cli::add_validate_command(app, validate_command);
  brb::cli::CalibrateCommand calibrate_command;
  const CLI::App* calibrate = brb::cli::add_calibrate_command(app, calibrate_command);
  brb::cli::SpectrumCommand spectrum_command;
  const CLI::App* spectrum = brb::cli::add_spectrum_command(app, spectrum_command);
  brb::cli::CheckCommand check_command;
  const CLI::App* check = brb::cli::add_check_command(app, check_command);
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks and numerical studies of the model's "
                                                "cost, accuracy and robustness.");
  bench->require_subcommand(1);
  brb::cli::BenchStressCommand bench_stress_command;
  const CLI::App* bench_stress = brb::cli::add_bench_stress_command(*bench, bench_stress_command);
  brb::cli::BenchSkipsCommand bench_skips_command;
  const CLI::App* bench_skips = brb::cli::add_bench_skips_command(*bench, bench_skips_command);
  brb::cli::BenchScalingCommand bench_scaling_command;
  const CLI::App* bench_scaling =
      brb::cli::add_bench_scaling_command(*bench, bench_scaling_command);
  brb::cli::BenchParetoCommand bench_pareto_command;
  const CLI::App* bench_pareto = brb::cli::add_bench_pareto_command(*bench, bench_pareto_command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return app.exit(error); // --help
    }
    std::cerr << "brb: error: " << error.what() << "\n"
              << "Run 'brb --help' or 'brb <command> --help' (material, cyclic, solid, frame, ida, "
                 "validate, calibrate, spectrum, check, bench) for usage.\n";
    return kInvalidInput;
  }

  try {
    if (material->parsed())
      return brb::cli::run_material_command(material_command, std::cerr);
    if (cyclic->parsed())
      return brb::cli::run_cyclic_command(cyclic_command, std::cout, std::cerr);
    if (solid->parsed())
      return brb::cli::run_solid_command(solid_command, std::cout, std::cerr);
    if (frame->parsed())
      return brb::cli::run_frame_command(frame_command, std::cout, std::cerr);
    if (ida->parsed())
      return brb::cli::run_ida_command(ida_command, std::cout, std::cerr);
    if (validate->parsed())
      return brb::cli::run_validate_command(validate_command, std::cout);
    if (calibrate->parsed())
      return brb::cli::run_calibrate_command(calibrate_command, std::cout);
    if (spectrum->parsed())
      return brb::cli::run_spectrum_command(spectrum_command, std::cout);
    if (check->parsed())
      return brb::cli::run_check_command(check_command, std::cout, std::cerr);
    if (bench_stress->parsed())
      return brb::cli::run_bench_stress_command(bench_stress_command, std::cout);
    if (bench_skips->parsed())
      return brb::cli::run_bench_skips_command(bench_skips_command, std::cout);
    if (bench_scaling->parsed())
      return brb::cli::run_bench_scaling_command(bench_scaling_command, std::cout);
    if (bench_pareto->parsed())
      return brb::cli::run_bench_pareto_command(bench_pareto_command, std::cout, std::cerr);
  } catch (const brb::io::InputError& error) {
    std::cerr << "brb: error: " << error.what() << "\n";
    return kInvalidInput;
  } catch (const brb::io::CheckpointMismatch& error) {
    std::cerr << "brb: error: " << error.what() << "\n";
    return kInvalidInput;
  } catch (const std::exception& error) {
    std::cerr << "brb: error: " << error.what() << "\n";
    return kRunFailed;
  }
  return kInvalidInput;
}
