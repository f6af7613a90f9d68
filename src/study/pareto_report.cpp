#include "brb/study/pareto_report.hpp"

#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"
#include "brb/model/brace_fidelity.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace brb::study {
namespace {

std::string percent(std::optional<double> value) {
  if (!value)
    return "-";
  if (!std::isfinite(*value))
    return "inf";
  std::ostringstream text;
  text << std::fixed << std::setprecision(*value < 0.1 ? 2 : 1) << 100.0 * *value << " %";
  return text.str();
}

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text << std::setprecision(digits) << value;
  return text.str();
}

std::string time_text(double seconds) {
  std::ostringstream text;
  if (seconds < 1.0)
    text << std::setprecision(3) << 1000.0 * seconds << " ms";
  else
    text << std::setprecision(4) << seconds << " s";
  return text.str();
}

std::string step_text(const ParetoSetting& setting) {
  if (setting.max_step)
    return fixed(*setting.max_step, 4) + " dy";
  if (setting.dt)
    return fixed(*setting.dt, 4) + " s";
  return "default";
}

std::string fibers_text(const ParetoSetting& setting) {
  return setting.fibers
             ? std::to_string(setting.fibers->first) + "x" + std::to_string(setting.fibers->second)
             : "file";
}

std::string optional_int(const std::optional<int>& value) {
  return value ? std::to_string(*value) : "file";
}

std::string csv_number(std::optional<double> value) {
  if (!value)
    return "";
  if (!std::isfinite(*value))
    return "inf";
  return io::format_number(*value);
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"')
      quoted += '"';
    quoted += c == '\n' ? ' ' : c;
  }
  return quoted + "\"";
}

double speed_up(const CaseOutcome& outcome, const SettingOutcome& setting) {
  const SettingOutcome& reference = outcome.settings.at(outcome.study_case.reference);
  return setting.median_time > 0.0 ? reference.median_time / setting.median_time : 0.0;
}

std::string status_of(const SettingOutcome& setting) {
  if (!setting.ran)
    return "failed: " + setting.failure;
  if (!setting.stop_reason.empty())
    return "stopped: " + setting.stop_reason;
  return "completed";
}

std::string mode_text(const ParetoSetting& setting) {
  return setting.mode == model::ElementMode::condensed ? "condensed" : "expanded";
}

void case_section(std::ostream& out, const CaseOutcome& outcome) {
  const ParetoCase& study_case = outcome.study_case;
  const bool frame = study_case.kind == CaseKind::frame;
  const SettingOutcome& reference = outcome.settings.at(study_case.reference);
  out << "## " << study_case.name << " (" << to_string(study_case.kind) << ")\n\n";
  if (!study_case.description.empty())
    out << study_case.description << "\n\n";
  out << "- input: `"
      << (frame ? study_case.model.lexically_normal().string()
                : study_case.brace.lexically_normal().string())
      << "`, " << outcome.window << "; matrix `" << study_case.matrix_file.filename().string()
      << "`\n"
      << "- reference (the finest `full` setting of the matrix): `" << reference.setting.label
      << "`, " << time_text(reference.median_time) << " (" << status_of(reference) << ")\n"
      << "- role for the `auto` rule: "
      << (study_case.auto_rule == AutoRuleRole::derive ? "used to derive it"
                                                       : "not used to derive it (a check)")
      << "\n";
  if (outcome.solid) {
    out << "- `brb solid` reference (column \"vs `brb solid`\": cycle energy against it): `"
        << outcome.solid->file.lexically_normal().string() << "`, "
        << time_text(outcome.solid->run_seconds) << " ("
        << (outcome.solid->response.completed ? "completed" : "stopped early") << ", "
        << outcome.solid->response.cycles.size() << " cycles; its own run, not rerun here)";
    if (reference.ran && reference.median_time > 0.0)
      out << ", " << fixed(outcome.solid->run_seconds / reference.median_time, 4)
          << " times the reference setting's time";
    out << "\n";
  }
  if (const auto cheapest = cheapest_within(outcome, kAcceptanceError)) {
    const SettingOutcome& best = outcome.settings[*cheapest];
    out << "- cheapest setting within " << percent(kAcceptanceError) << " "
        << (frame ? "peak-drift" : "energy") << " error of the reference: `" << best.setting.label
        << "` (" << percent(best.errors.primary()) << ", " << time_text(best.median_time) << ", "
        << fixed(speed_up(outcome, best), 4) << " times faster than the reference)\n";
  } else {
    out << "- no setting is within " << percent(kAcceptanceError) << " of the reference\n";
  }
  out << "\n";
  if (frame) {
    out << "| setting | fidelity | built as | core elements | fibers | mode | dt | median time | "
           "runs | speed-up | peak drift | residual drift | brace CID | front | front (all) | "
           "status |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  } else {
    out << "| setting | fidelity | built as | core elements | fibers | points | step | median "
           "time | runs | speed-up | cycle energy | peak forces | beta | vs `brb solid` | front | "
           "front (all) | status |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  }
  for (std::size_t k = 0; k < outcome.settings.size(); ++k) {
    const SettingOutcome& s = outcome.settings[k];
    const std::string label =
        "`" + s.setting.label + "`" + (k == study_case.reference ? " (reference)" : "");
    out << "| " << label << " | " << to_string(s.setting.fidelity) << " | " << s.built_as << " | "
        << optional_int(s.setting.core_elements) << " | " << fibers_text(s.setting) << " | ";
    if (frame)
      out << mode_text(s.setting) << " | ";
    else
      out << optional_int(s.setting.integration_points) << " | ";
    out << step_text(s.setting) << " | " << (s.ran ? time_text(s.median_time) : "-") << " | "
        << (s.committed ? std::string("committed") : std::to_string(s.wall_times.size())) << " | "
        << (s.ran ? fixed(speed_up(outcome, s), 4) : "-") << " | ";
    if (frame) {
      out << percent(s.errors.peak_drift) << " | " << percent(s.errors.residual_drift) << " | "
          << percent(s.errors.cid) << " | ";
    } else {
      out << percent(s.errors.cycle_energy) << " | " << percent(s.errors.peak_force) << " | "
          << percent(s.errors.beta) << " | "
          << (outcome.solid ? percent(s.errors.solid) : std::string("n/a")) << " | ";
    }
    out << (s.front_primary ? "**front**" : "") << " | " << (s.front_worst ? "**front**" : "")
        << " | " << status_of(s) << " |\n";
  }
  out << "\n";
  bool any_committed = false;
  for (const SettingOutcome& s : outcome.settings) {
    if (s.committed && s.setting.committed_run) {
      any_committed = true;
      out << "- `" << s.setting.label << "`: read from its committed run `"
          << s.setting.committed_run->lexically_normal().string()
          << "` (a `brb frame` run of this setting; the time is the one it recorded), not run "
             "again (`--run-committed` runs it)\n";
    }
  }
  if (any_committed)
    out << "\n";
}

void auto_section(std::ostream& out, const std::vector<CaseOutcome>& outcomes) {
  out << "## The `auto` fidelity\n\n"
      << "The rule (`include/brb/model/brace_fidelity.hpp`, README \"The `auto` fidelity of "
         "braces in frames\") picks `truss` for a brace with a steel-tube casing whose Euler "
         "load is at least "
      << model::kEulerMargin << " P_y and whose friction coefficient is at most "
      << model::kTrussFrictionLimit
      << ", `full` otherwise. Its stated error bound: " << percent(model::kAutoErrorBound)
      << " of the finest `full` setting on every metric of this study (cycle energy, peak "
         "forces and beta for components; peak drift, residual drift and brace CID for frames).\n\n"
      << "| case | role | `auto` built as | primary error | worst metric | within "
      << percent(model::kAutoErrorBound) << " |\n|---|---|---|---|---|---|\n";
  for (const CaseOutcome& outcome : outcomes) {
    for (const SettingOutcome& s : outcome.settings) {
      if (s.setting.fidelity != SettingFidelity::automatic)
        continue;
      const bool within = s.ran && s.errors.worst() <= model::kAutoErrorBound;
      out << "| " << outcome.study_case.name << " (`" << s.setting.label << "`) | "
          << (outcome.study_case.auto_rule == AutoRuleRole::derive ? "derive" : "check") << " | "
          << s.built_as << " | " << percent(s.errors.primary()) << " | "
          << percent(s.errors.worst()) << " | " << (within ? "yes" : "**NO**") << " |\n";
    }
  }
  out << "\n";
}

} // namespace

std::optional<std::size_t> cheapest_within(const CaseOutcome& outcome, double bound) {
  std::optional<std::size_t> cheapest;
  for (std::size_t k = 0; k < outcome.settings.size(); ++k) {
    const SettingOutcome& s = outcome.settings[k];
    if (!s.ran || !(s.errors.primary() <= bound))
      continue;
    if (!cheapest || s.median_time < outcome.settings[*cheapest].median_time)
      cheapest = k;
  }
  return cheapest;
}

std::string pareto_csv(const std::vector<CaseOutcome>& outcomes) {
  std::ostringstream out;
  out << "case,kind,setting,reference,fidelity,built_as,core_elements,fibers,integration_points,"
         "mode,max_step_dy,dt_s,runs,median_time_s,wall_times_s,speed_up,cycle_energy_error,"
         "peak_force_error,beta_error,peak_drift_error,residual_drift_error,cid_error,"
         "solid_error,primary_error,worst_error,front_primary,front_worst,status,committed\n";
  for (const CaseOutcome& outcome : outcomes) {
    for (std::size_t k = 0; k < outcome.settings.size(); ++k) {
      const SettingOutcome& s = outcome.settings[k];
      const ParetoSetting& p = s.setting;
      std::string times;
      for (const double t : s.wall_times) {
        if (!times.empty())
          times += ';';
        times += io::format_number(t);
      }
      out << csv_field(outcome.study_case.name) << "," << to_string(outcome.study_case.kind) << ","
          << csv_field(p.label) << "," << (k == outcome.study_case.reference ? 1 : 0) << ","
          << to_string(p.fidelity) << "," << csv_field(s.built_as) << ","
          << (p.core_elements ? std::to_string(*p.core_elements) : "") << ","
          << (p.fibers ? fibers_text(p) : "") << ","
          << (p.integration_points ? std::to_string(*p.integration_points) : "") << ","
          << mode_text(p) << "," << csv_number(p.max_step) << "," << csv_number(p.dt)
          << "," << s.wall_times.size() << "," << (s.ran ? csv_number(s.median_time) : "") << ","
          << times << "," << (s.ran ? csv_number(speed_up(outcome, s)) : "") << ","
          << csv_number(s.errors.cycle_energy) << "," << csv_number(s.errors.peak_force) << ","
          << csv_number(s.errors.beta) << "," << csv_number(s.errors.peak_drift) << ","
          << csv_number(s.errors.residual_drift) << "," << csv_number(s.errors.cid) << ","
          << csv_number(s.errors.solid) << "," << csv_number(s.errors.primary()) << ","
          << csv_number(s.errors.worst()) << "," << (s.front_primary ? 1 : 0) << ","
          << (s.front_worst ? 1 : 0) << "," << csv_field(status_of(s)) << ","
          << (s.committed ? 1 : 0) << "\n";
    }
  }
  return out.str();
}

std::string pareto_markdown(const std::vector<CaseOutcome>& outcomes,
                            const ParetoRunDescription& description) {
  std::ostringstream out;
  out << "# Run time against error (`brb bench pareto`)\n\n"
      << "Generated by `" << description.command_line
      << "`; do not edit by hand (rerun the command). The numbers are in `pareto.csv`.\n\n"
      << "- Each setting ran "
      << (description.repeats ? std::to_string(*description.repeats) + " time(s)"
                              : "the number of times its matrix says (column runs)")
      << " on " << description.jobs
      << " thread(s); time = median wall time of the runs (model build + analysis), on a "
         "shared 2-core machine: ratios carry over, absolute times do not. Runs "
         "\"committed\": the setting's committed `brb frame` run was read, with the wall time "
         "it recorded."
      << (description.quick ? " **--quick**: shortened windows, one run each." : "") << "\n"
      << "- Errors are against the case's reference, the finest `full` setting of its matrix "
         "(relative; definitions in `include/brb/study/pareto_metrics.hpp`). Components: "
         "cycle energy = max over the cycles that dissipate at least 5 % of the largest "
         "reference loop of |E - E_ref| / E_ref; peak forces = max over all cycles of the "
         "relative error of the largest tension and compression; beta = the same over |C| / T. "
         "Frames: peak drift = max over stories of the relative error of the peak story drift; "
         "residual drift = max over stories of |r - r_ref| / (largest reference peak drift); "
         "brace CID = max over braces of |CID - CID_ref| / max(largest reference CID, 1 dy).\n"
      << "- front: on the Pareto front of (time, primary error: cycle energy for components, "
         "peak drift for frames); front (all): of (time, worst of the case's metrics).\n"
      << "- vs `brb solid`: the cycle energy error (as above) against the case's committed run "
         "of the 3D continuum model (issue 6), where its matrix names one (\"solid\"), on the "
         "cycles of the case's protocol (the 3D run's protocol begins with them); n/a: no 3D "
         "run; -: the setting did not complete, the 3D run has fewer cycles than the setting, or "
         "the cycles' amplitudes differ by more than "
      << percent(kSolidAmplitudeTolerance) << " (`solid_error` in the CSV).\n"
      << "- Contact (gap-link) spacing follows the core elements (one link per core station); "
         "the step is max_step (dy) for components, dt for frames.\n\n";
  for (const CaseOutcome& outcome : outcomes)
    case_section(out, outcome);
  auto_section(out, outcomes);
  return out.str();
}

void write_pareto_outputs(const std::filesystem::path& directory,
                          const std::vector<CaseOutcome>& outcomes,
                          const ParetoRunDescription& description) {
  io::write_file_atomically(directory / "pareto.csv", pareto_csv(outcomes));
  io::write_file_atomically(directory / "PARETO.md", pareto_markdown(outcomes, description));
}

} // namespace brb::study
