#include "solid_command.hpp"

#include "cyclic_command.hpp"
#include "output_directory.hpp"
#include "progress_line.hpp"

#include "brb/io/atomic_file.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/cyclic_output.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/protocol.hpp"
#include "brb/io/vtu_writer.hpp"
#include "brb/solid/brace_mesh.hpp"
#include "brb/solid/solid_body.hpp"
#include "brb/solid/solid_cyclic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace brb::cli {
namespace {

using io::significant;

namespace fs = std::filesystem;

constexpr int kCompleted = 0;
constexpr int kStoppedEarly = 1;
constexpr double kDefaultStepsPerYieldDeformation = 10.0;

/// energies.csv: one row per output record of the explicit run.
io::NumericTable energy_table(const solid::SolidBraceRun& run) {
  io::NumericTable table({"step", "time", "explicit_steps", "deformation", "force", "kinetic",
                          "internal", "hourglass", "contact_stored", "friction", "damping",
                          "external", "energy_error"});
  for (std::size_t k = 0; k < run.records.size(); ++k) {
    const solid::SolidBraceRecord& r = run.records[k];
    const double row[] = {static_cast<double>(k),
                          r.time,
                          static_cast<double>(r.steps),
                          r.deformation,
                          r.force,
                          r.kinetic,
                          r.internal,
                          r.hourglass,
                          r.contact_stored,
                          r.friction,
                          r.damping,
                          r.external,
                          r.energy_error};
    table.append_row(row);
  }
  return table;
}

/// The body's state as a VTK snapshot: reference points, the parts' hexahedra in global node
/// numbers, displacement and contact pressure per node, damage, plastic strain and part per
/// element.
io::VtuSnapshot snapshot_of(const solid::SolidBraceState& state) {
  io::VtuSnapshot snapshot;
  snapshot.time = state.record.time;
  snapshot.points = state.body.reference_nodes();
  for (const auto& part : state.body.parts()) {
    const std::vector<int>& global = part->global_nodes();
    for (const solid::HexConnectivity& element : part->mesh().elements) {
      io::VtuHexahedron cell{};
      for (std::size_t a = 0; a < 8; ++a)
        cell[a] = global[static_cast<std::size_t>(element[a])];
      snapshot.cells.push_back(cell);
    }
  }
  const Eigen::VectorXd& u = state.displacement;
  snapshot.point_data.push_back(
      {"displacement", 3, std::vector<double>(u.data(), u.data() + u.size())});
  snapshot.point_data.push_back({"contact_pressure", 1, solid::contact_pressure(state.body)});
  solid::SolidElementFields fields = solid::element_fields(state.body);
  snapshot.cell_data.push_back({"equivalent_plastic_strain", 1, std::move(fields.plastic_strain)});
  snapshot.cell_data.push_back({"steel_damage", 1, std::move(fields.steel_damage)});
  snapshot.cell_data.push_back({"mortar_damage", 1, std::move(fields.mortar_damage)});
  snapshot.cell_data.push_back({"part", 1, std::move(fields.part)});
  return snapshot;
}

nlohmann::ordered_json solid_block(const SolidCommand& command, const model::SolidMeshSpec& mesh,
                                   const solid::SolidCyclicResult& result, double seconds) {
  const solid::SolidBraceRun& run = result.run;
  nlohmann::ordered_json block;
  block["model"] = "3D continuum (brb solid)";
  block["nodes"] = run.nodes;
  block["elements"] = run.elements;
  block["half_length"] = mesh.half_length;
  block["end_faces"] = model::end_faces_name(mesh.end_faces);
  block["mass_scaling"] = mesh.mass_scaling;
  block["hourglass"] = model::hourglass_name(mesh.hourglass);
  if (mesh.hourglass == model::SolidHourglass::tangent)
    block["hourglass_min_scale"] = mesh.hourglass_min_scale;
  block["threads"] = command.threads.value_or(mesh.threads);
  block["time_step_s"] = run.time_step;
  block["explicit_steps"] = run.steps;
  block["first_axial_period_s"] = run.first_axial_period;
  block["time_per_deformation_s_per_mm"] = run.time_per_deformation;
  block["min_excursion_time_s"] = run.min_excursion_time;
  block["lateral_damping_per_s"] = run.lateral_damping;
  const double damping = run.records.empty() ? 0.0 : run.records.back().damping;
  const double external = run.records.empty() ? 0.0 : run.records.back().external;
  block["damping_energy_N_mm"] = damping;
  block["damping_energy_over_external_work"] = external > 0.0 ? damping / external : 0.0;
  block["duration_s"] = run.records.empty() ? 0.0 : run.records.back().time;
  block["contact_penalty_N_per_mm3"] = result.contact_penalty;
  block["quasi_static_floor_N_mm"] = result.quasi_static_floor;
  block["max_kinetic_over_internal"] = result.max_kinetic_ratio;
  block["max_hourglass_over_internal"] = result.max_hourglass_ratio;
  block["max_energy_balance_error"] = result.max_energy_error;
  block["run_seconds"] = seconds;
  return block;
}

} // namespace

CLI::App* add_solid_command(CLI::App& app, SolidCommand& command) {
  auto* solid = app.add_subcommand(
      "solid", "Virtual cyclic test of a brace's 3D continuum model (hexahedra, contact with "
               "friction, explicit dynamics): the same protocol and outputs as brb cyclic.");
  solid
      ->add_option("brace", command.brace,
                   "Brace file, JSON; its optional \"solid\" block sets the mesh (README, "
                   "\"Brace files\")")
      ->type_name("BRACE.json")
      ->required();
  solid->add_option("--protocol", command.protocol, "Loading protocol, as brb cyclic")
      ->type_name("P.json|P.csv")
      ->required();
  solid
      ->add_option("--out", command.output_directory,
                   "Output directory (created if missing; its parent must exist)")
      ->type_name("DIR")
      ->required();
  add_max_step_option(*solid, command.max_step,
                      "Largest change of deformation between protocol points, mm, when the "
                      "protocol gives none; default dy / 10 (the points of brb cyclic)");
  solid
      ->add_option("--outputs-per-step", command.outputs_per_step,
                   "Output records per protocol step (default 1)")
      ->check(CLI::Range(1, 1000));
  solid
      ->add_option("--time-per-deformation", command.time_per_deformation,
                   "Loading time per mm of brace elongation, s/mm; default 20 first axial "
                   "periods of the core per yield deformation")
      ->check(CLI::PositiveNumber);
  CLI::Option* duration =
      solid
          ->add_option("--duration", command.duration,
                       "Total loading time, s (overrides --time-per-deformation)")
          ->check(CLI::PositiveNumber);
  solid
      ->add_option("--min-excursion-time", command.min_excursion_time,
                   "Shortest loading time of an excursion (reversal to reversal), s: slows "
                   "the small first cycles, where the internal energy is small; default none")
      ->check(CLI::PositiveNumber)
      ->excludes(duration);
  solid
      ->add_option("--lateral-damping", command.lateral_damping,
                   "Mass-proportional damping alpha of the nodes' lateral (y, z) motion, 1/s "
                   "(a mode of frequency w gets the damping ratio alpha / 2w): calms a dynamic "
                   "snap (global buckling, loose split mortar) without slowing the axial "
                   "loading; its energy is reported; default none")
      ->check(CLI::NonNegativeNumber);
  solid
      ->add_option_function<int>(
          "--threads",
          [&command](const int& threads) {
            if (threads < 1)
              throw CLI::ValidationError("--threads", "must be a whole number >= 1");
            command.threads = threads;
          },
          "Threads of the element and contact loops (default: the solid block's, 1)")
      ->type_name("N");
  solid
      ->add_option("--snapshots", command.snapshot_steps,
                   "Steps of hysteresis.csv whose fields are written as fields/step_K.vtu")
      ->delimiter(',')
      ->check(CLI::NonNegativeNumber)
      ->type_name("K,...");
  solid
      ->add_option("--snapshot-every", command.snapshot_every,
                   "Also write the fields of every N-th step (and the last); 0: off")
      ->check(CLI::NonNegativeNumber)
      ->type_name("N");
  solid->add_flag("--histories", command.histories,
                  "Also write element_history.csv: the element outputs (damage, residual "
                  "strength, flags) after every step, as brb cyclic --histories");
  add_progress_option(
      *solid, command.progress_interval,
      "Print a progress line on stderr at most every SECONDS of wall time (0: after every "
      "record) and after the last: step k of N (hysteresis.csv's records), deformation, force, "
      "explicit steps so far, elapsed time (a 3D run takes minutes to hours)");
  solid->footer(
      "Outputs (README, \"brb solid\"):\n"
      "  hysteresis.csv, summary.json: as brb cyclic (summary.json adds a \"solid\" block:\n"
      "    mesh, time step, energy ratios, run time)\n"
      "  energies.csv: time, force and the energies of every output record\n"
      "  element_history.csv (with --histories): the element outputs after every step\n"
      "  fields/step_K.vtu, fields.pvd (with --snapshots or --snapshot-every): ParaView\n"
      "Units: N, mm, s, MPa. Exit status: 0 completed, 1 the run stopped early (what was\n"
      "computed is written) or failed, 2 invalid input or usage (nothing written).");
  return solid;
}

int run_solid_command(const SolidCommand& command, std::ostream& report, std::ostream& notes) {
  // Every input is read and checked before anything is written.
  model::BraceSpec spec = io::read_brace(command.brace);
  const std::string name = brace_name(spec, command.brace);
  const model::BraceModel reduced = build_brace(spec, command.brace);
  const double dy = reduced.yield_deformation;
  const io::LoadingProtocol protocol = io::read_protocol(
      command.protocol, dy, command.max_step.value_or(dy / kDefaultStepsPerYieldDeformation));
  check_output_directory(command.output_directory);
  model::SolidMeshSpec mesh = spec.solid.value_or(model::SolidMeshSpec{});
  if (command.threads)
    mesh.threads = *command.threads;
  spec.solid = mesh;

  solid::SolidCyclicSettings settings;
  settings.run.outputs_per_segment = command.outputs_per_step;
  settings.run.time_per_deformation = command.time_per_deformation;
  settings.run.duration = command.duration;
  settings.run.min_excursion_time = command.min_excursion_time;
  settings.run.lateral_damping = command.lateral_damping;

  const fs::path fields_directory = command.output_directory / "fields";
  const bool snapshots = !command.snapshot_steps.empty() || command.snapshot_every > 0;
  const std::set<int> chosen(command.snapshot_steps.begin(), command.snapshot_steps.end());
  const int last_step =
      static_cast<int>(protocol.deformation.size() - 1) * command.outputs_per_step;
  std::vector<io::PvdEntry> written;
  int step = -1;
  fs::create_directory(command.output_directory);
  if (snapshots)
    fs::create_directory(fields_directory);
  const auto start = std::chrono::steady_clock::now();
  std::optional<ProgressLine> progress;
  if (command.progress_interval)
    progress.emplace(notes, "brb: solid: ", static_cast<std::size_t>(last_step),
                     *command.progress_interval, nullptr, "explicit steps");
  long explicit_steps = 0; // up to the previous record
  const auto observer = [&](const solid::SolidBraceState& state) {
    ++step; // records come in order: record k is hysteresis step k
    if (progress) {
      const solid::SolidBraceRecord& record = state.record;
      (*progress)({.step = step,
                   .deformation = record.deformation,
                   .force = record.force,
                   .substeps = static_cast<int>(record.steps - explicit_steps)});
      explicit_steps = record.steps;
    }
    const bool wanted =
        chosen.contains(step) ||
        (command.snapshot_every > 0 && (step % command.snapshot_every == 0 || step == last_step));
    if (!wanted)
      return;
    char file_name[32];
    std::snprintf(file_name, sizeof file_name, "step_%06d.vtu", step);
    io::write_vtu(fields_directory / file_name, snapshot_of(state));
    written.push_back({state.record.time, fs::path("fields") / file_name});
  };

  const solid::SolidCyclicResult result = solid::run_solid_cyclic(
      spec, protocol.deformation, protocol.cycle, protocol.cycle_amplitude, reduced.yield_force, dy,
      settings, snapshots || progress ? solid::SolidBraceObserver(observer) : nullptr);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const fs::path hysteresis = command.output_directory / "hysteresis.csv";
  const fs::path summary = command.output_directory / "summary.json";
  const fs::path energies = command.output_directory / "energies.csv";
  io::write_file_atomically(hysteresis, io::hysteresis_table(result.cyclic).text());
  io::write_file_atomically(energies, energy_table(result.run).text());
  if (command.histories)
    io::write_file_atomically(command.output_directory / "element_history.csv",
                              io::element_history_table(result.cyclic).text());
  nlohmann::ordered_json summary_json =
      io::cyclic_summary_json(name, dy, reduced.yield_force, result.cyclic);
  summary_json["solid"] = solid_block(command, mesh, result, seconds);
  io::write_file_atomically(summary, summary_json.dump(2) + "\n");
  if (!written.empty())
    io::write_pvd(command.output_directory / "fields.pvd", written);

  const solid::SolidBraceRun& run = result.run;
  report << "brb solid: brace " << name << " (" << command.brace.string() << ")\n"
         << "  3D model: " << run.nodes << " nodes, " << run.elements << " hexahedra"
         << (mesh.half_length ? " (half length)" : "") << "; dy = " << significant(dy, 6)
         << " mm, Py = " << significant(reduced.yield_force, 6) << " N\n"
         << "  explicit: " << run.steps << " steps of " << significant(run.time_step, 4)
         << " s over " << significant(run.records.empty() ? 0.0 : run.records.back().time, 4)
         << " s (first axial period of the core " << significant(run.first_axial_period, 4)
         << " s)\n"
         << "  peak forces: tension " << significant(result.cyclic.max_tension, 6)
         << " N, compression " << significant(result.cyclic.max_compression, 6) << " N; "
         << result.cyclic.cycles.size() << " cycles completed\n"
         << "  quasi-static check: max KE/IE " << significant(result.max_kinetic_ratio, 3)
         << ", max hourglass/IE " << significant(result.max_hourglass_ratio, 3)
         << ", max energy-balance error " << significant(result.max_energy_error, 3) << "\n";
  if (run.lateral_damping > 0.0)
    report << "  lateral damping " << significant(run.lateral_damping, 4) << " 1/s took "
           << significant(run.records.empty() ? 0.0 : run.records.back().damping, 4)
           << " N mm (released in jumps of the energy balance)\n";
  report << "  indicators: max steel damage "
         << significant(result.cyclic.indicators.max_steel_damage, 3) << ", max mortar damage "
         << significant(result.cyclic.indicators.max_mortar_damage, 3)
         << ", least bearing residual strength "
         << significant(result.cyclic.indicators.min_bearing_residual_strength, 3)
         << ", casing failure " << (result.cyclic.indicators.casing_failure ? "yes" : "no")
         << ", global buckling " << (result.cyclic.indicators.global_buckling ? "yes" : "no")
         << "\n"
         << "  run time " << significant(seconds, 4) << " s\n"
         << "  wrote " << hysteresis.string() << "\n        " << summary.string() << "\n        "
         << energies.string() << "\n";
  if (command.histories)
    report << "        " << (command.output_directory / "element_history.csv").string() << "\n";
  if (!written.empty())
    report << "        " << (command.output_directory / "fields.pvd").string() << " ("
           << written.size() << " snapshots)\n";
  if (!result.cyclic.completed) {
    notes << "brb: error: " << command.brace.string()
          << ": the 3D run stopped early: " << result.cyclic.stop_reason
          << "; the records computed before are written\n";
    return kStoppedEarly;
  }
  return kCompleted;
}

} // namespace brb::cli
