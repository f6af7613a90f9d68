#include "brb/validation/report.hpp"
#include "brb/io/csv.hpp"

#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace brb::validation {
namespace {

/// `value` with `digits` significant digits (6 by default).
std::string significant(double value, int digits = 6) {
  return io::significant(value, digits);
}

using Json = nlohmann::ordered_json;

void count(Tally& tally, CheckStatus status) {
  switch (status) {
  case CheckStatus::pass:
    ++tally.passed;
    break;
  case CheckStatus::fail:
    ++tally.failed;
    break;
  case CheckStatus::reported:
    ++tally.reported;
    break;
  }
}

std::string with_unit(double value, const std::string& unit) {
  return significant(value) + (unit.empty() || unit == "-" ? "" : " " + unit);
}

std::string percent(double fraction) {
  std::ostringstream text;
  text << std::showpos << std::fixed << std::setprecision(2) << 100.0 * fraction << " %";
  return text.str();
}

/// Markdown table cells must not contain '|' or line breaks.
std::string cell(std::string text) {
  for (char& character : text) {
    if (character == '|' || character == '\n')
      character = character == '|' ? '/' : ' ';
  }
  return text;
}

std::string reference_text(const CheckResult& check) {
  if (check.expected)
    return *check.expected ? "true" : "false";
  if (check.reference)
    return with_unit(*check.reference, check.unit);
  std::string bounds;
  if (check.at_least)
    bounds = ">= " + with_unit(*check.at_least, check.unit);
  if (check.at_most)
    bounds += (bounds.empty() ? "" : ", ") + ("<= " + with_unit(*check.at_most, check.unit));
  return bounds.empty() ? "-" : bounds;
}

std::string result_text(const CheckResult& check) {
  if (!check.value)
    return "none";
  if (check.expected)
    return *check.value != 0.0 ? "true" : "false";
  return with_unit(*check.value, check.unit);
}

std::string error_text(const CheckResult& check) {
  if (!check.error)
    return "-";
  if (check.tolerance && check.tolerance->kind == Tolerance::Kind::relative)
    return percent(*check.error);
  return with_unit(*check.error, check.unit);
}

std::string tolerance_text(const CheckResult& check) {
  if (!check.tolerance)
    return "-";
  if (check.tolerance->kind == Tolerance::Kind::relative)
    return significant(100.0 * check.tolerance->value) + " %";
  return with_unit(check.tolerance->value, check.unit);
}

std::string summary_line(const Tally& tally) {
  std::ostringstream text;
  text << "**" << (tally.all_passed() ? "PASS" : "FAIL") << "**: " << tally.passed
       << " checks passed, " << tally.failed << " failed, " << tally.reported
       << " values reported without a check.";
  return text.str();
}

Tally tally_of(const RunOutcome& run) {
  Tally tally;
  for (const CheckResult& check : run.checks)
    count(tally, check.status);
  return tally;
}

void write_run(std::ostringstream& out, const SpecimenOutcome& specimen, const RunOutcome& run,
               const std::string& validation_directory) {
  out << "### " << specimen.specimen.id << ", refinement x" << run.refinement << " ("
      << run.core_elements << " core elements)\n\n";
  out << "- " << (run.completed ? "completed" : "**stopped early**") << ": " << run.steps << " of "
      << run.planned_steps << " steps, " << run.iterations << " Newton iterations, " << std::fixed
      << std::setprecision(1) << run.run_seconds << std::defaultfloat << " s";
  if (run.resumed_from_step > 0) // README, "Checkpoints": the time of every session it ran in
    out << " (taken up from a checkpoint at step " << run.resumed_from_step
        << "; the time is the runs' before and after it)";
  out << "\n";
  if (const auto& record = specimen.specimen.record; record && record->run_seconds) {
    out << "- the reference `brb solid` run took " << std::fixed << std::setprecision(1)
        << *record->run_seconds << std::defaultfloat << " s";
    if (run.run_seconds > 0.0)
      out << ": " << significant(*record->run_seconds / run.run_seconds, 3)
          << " times this run (same machine only if both were measured on it)";
    out << "\n";
  }
  if (!run.completed)
    out << "- stop reason: " << run.stop_reason << "\n";
  out << "- energy-balance relative error " << significant(run.energy_balance_error, 3)
      << " (target <= " << significant(energy_balance_tolerance, 3)
      << "); the laws' integration misfit, set apart from it, "
      << significant(run.integration_misfit, 3) << " of the gross work\n";
  if (specimen.specimen.balance_tolerance > 0.0) {
    out << "- solver: balance control at " << significant(specimen.specimen.balance_tolerance, 3)
        << " of the gross work (metrics.json solver.balance_tolerance; `brb cyclic "
           "--balance-tolerance`)\n";
  }
  std::string outputs = run.output_directory.string();
  if (!validation_directory.empty() && outputs.rfind(validation_directory, 0) == 0) {
    outputs = outputs.substr(validation_directory.size());
    while (!outputs.empty() && outputs.front() == '/')
      outputs.erase(outputs.begin());
  }
  out << "- hysteresis and summary: `" << outputs << "/`\n\n";
  out << "| metric | reference | result | error | tolerance | pass | where / why |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const CheckResult& check : run.checks) {
    out << "| " << cell(check.name) << " | " << cell(reference_text(check)) << " | "
        << cell(result_text(check)) << " | " << cell(error_text(check)) << " | "
        << cell(tolerance_text(check)) << " | " << to_string(check.status) << " | "
        << cell(check.note) << " |\n";
  }
  out << "\n";
}

void write_specimen(std::ostringstream& out, const SpecimenOutcome& outcome,
                    const std::string& validation_directory) {
  const Specimen& specimen = outcome.specimen;
  out << "## " << specimen.id << ": " << specimen.title << "\n\n";
  out << "Source: " << specimen.source << ". Model: dy = " << significant(outcome.yield_deformation)
      << " mm, Py = " << significant(outcome.yield_force) << " N.\n\n";
  if (specimen.record) {
    const RecordReference& reference = *specimen.record;
    out << "Compared with: " << to_string(reference.type) << " `" << reference.written << "`";
    if (reference.failure) {
      out << "; it states failure " << to_string(reference.failure->mode);
      if (reference.failure->mode != FailureMode::none)
        out << " in cycle " << reference.failure->cycle;
    }
    out << ".\n\n";
  }
  if (!specimen.notes.empty()) {
    out << "Assumptions and notes:\n\n";
    for (const std::string& note : specimen.notes)
      out << "- " << note << "\n";
    out << "\n";
  }
  bool sourced = false;
  for (const MetricSpec& metric : specimen.metrics) {
    if (metric.source.empty())
      continue;
    if (!sourced)
      out << "References:\n\n";
    sourced = true;
    out << "- " << metric.name << ": " << metric.source << "\n";
  }
  if (sourced)
    out << "\n";
  for (const RunOutcome& run : outcome.runs)
    write_run(out, outcome, run, validation_directory);
}

/// "x2", or "-" when there is none. (Built with a stream: GCC 12 warns falsely on
/// "x" + std::to_string(...) here, -Wrestrict.)
std::string refinement_text(const std::optional<int>& refinement) {
  if (!refinement)
    return "-";
  std::ostringstream text;
  text << 'x' << *refinement;
  return text.str();
}

std::string relation_words(const std::string& relation) {
  return relation == ">" ? "greater than" : "less than";
}

Json optional_number(const std::optional<double>& value) {
  return value ? Json(*value) : Json(nullptr);
}

/// The specimen's reference: type, file or directory as written, stated failure (null
/// without a reference).
Json reference_json(const Specimen& specimen) {
  if (!specimen.record)
    return nullptr;
  const RecordReference& reference = *specimen.record;
  Json failure = nullptr;
  if (reference.failure) {
    failure = Json{{"failure_mode", std::string(to_string(reference.failure->mode))},
                   {"cycle", reference.failure->mode == FailureMode::none
                                 ? Json(nullptr)
                                 : Json(reference.failure->cycle)}};
  }
  return Json{
      {"type", to_string(reference.type)},
      {"source", reference.written},
      {"failure", std::move(failure)},
      {"run_seconds", reference.run_seconds ? Json(*reference.run_seconds) : Json(nullptr)}};
}

Json check_json(const CheckResult& check) {
  Json json = Json::object();
  json["name"] = check.name;
  json["kind"] = check.kind;
  json["unit"] = check.unit;
  json["value"] = optional_number(check.value);
  json["reference"] = optional_number(check.reference);
  if (check.tolerance) {
    json["tolerance"] =
        Json{{check.tolerance->kind == Tolerance::Kind::relative ? "relative" : "absolute",
              check.tolerance->value}};
  } else {
    json["tolerance"] = nullptr;
  }
  json["at_least"] = optional_number(check.at_least);
  json["at_most"] = optional_number(check.at_most);
  json["expected"] = check.expected ? Json(*check.expected) : Json(nullptr);
  json["error"] = optional_number(check.error);
  json["status"] = check.status == CheckStatus::fail ? "fail" : to_string(check.status);
  json["note"] = check.note;
  json["source"] = check.source;
  return json;
}

std::string status_word(CheckStatus status) {
  return status == CheckStatus::fail ? "fail" : to_string(status);
}

} // namespace

Tally tally(const ValidationReport& report) {
  Tally total;
  for (const SpecimenOutcome& specimen : report.specimens) {
    for (const RunOutcome& run : specimen.runs) {
      for (const CheckResult& check : run.checks)
        count(total, check.status);
    }
  }
  for (const ContrastResult& contrast : report.contrasts)
    count(total, contrast.status);
  return total;
}

std::string report_markdown(const ValidationReport& report) {
  std::ostringstream out;
  out << "# Validation report\n\n"
      << summary_line(tally(report)) << "\n\n"
      << "Generated by `"
      << (report.invocation.empty() ? "brb validate " + report.validation_directory
                                    : report.invocation)
      << "` (do not edit: run it again). Each specimen ran its whole protocol at every "
         "refinement listed (a multiplier of every zone's element count); every run is checked "
         "for completion and for an energy-balance relative error <= "
      << significant(energy_balance_tolerance, 3)
      << ", then against its metrics (`<id>/metrics.json`). The balance is external work = "
         "stored + dissipated + integration misfit + released in jumps, over the gross work; "
         "the misfit (the stresses' trapezoidal work at the integration points minus the laws' "
         "own stored and dissipated energy: their time discretisation, which falls with the "
         "step) is reported in its own column.\n\n";
  out << "| specimen | refinement | completed | steps | run time (s) | energy-balance error | "
         "integration misfit | passed | failed | reported |\n"
      << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SpecimenOutcome& specimen : report.specimens) {
    for (const RunOutcome& run : specimen.runs) {
      const Tally counts = tally_of(run);
      out << "| " << specimen.specimen.id << " | x" << run.refinement << " | "
          << (run.completed ? "yes" : "**no**") << " | " << run.steps << " / " << run.planned_steps
          << " | " << std::fixed << std::setprecision(1) << run.run_seconds << std::defaultfloat
          << " | " << significant(run.energy_balance_error, 3) << " | "
          << significant(run.integration_misfit, 3) << " | " << counts.passed << " | "
          << counts.failed << " | " << counts.reported << " |\n";
    }
  }
  out << "\n";
  for (const SpecimenOutcome& specimen : report.specimens)
    write_specimen(out, specimen, report.validation_directory);

  out << "## Contrasts\n\n";
  if (report.contrasts.empty()) {
    out << "None.\n";
  } else {
    out << "| contrast | refinement | left | relation | right | holds | statement |\n"
        << "|---|---|---|---|---|---|---|\n";
    for (const ContrastResult& result : report.contrasts) {
      const ContrastSpec& contrast = result.contrast;
      const auto operand = [](const ContrastSpec::Operand& side, const std::optional<double>& v) {
        return side.specimen + " " + side.metric + (v ? " = " + significant(*v) : "");
      };
      out << "| " << cell(contrast.name) << " | " << refinement_text(result.refinement) << " | "
          << cell(operand(contrast.left, result.left)) << " | " << relation_words(contrast.relation)
          << " | " << cell(operand(contrast.right, result.right)) << " | "
          << to_string(result.status) << " | "
          << cell(contrast.statement + (result.note.empty() ? "" : " (" + result.note + ")"))
          << " |\n";
    }
    out << "\nSources:\n\n";
    std::set<std::string> listed; // a contrast has one result per refinement: list it once
    for (const ContrastResult& result : report.contrasts) {
      if (listed.insert(result.contrast.name).second)
        out << "- " << result.contrast.name << ": " << result.contrast.source << "\n";
    }
  }
  return out.str();
}

Json report_json(const ValidationReport& report) {
  const Tally counts = tally(report);
  Json json = Json::object();
  json["validation_directory"] = report.validation_directory;
  json["invocation"] = report.invocation;
  json["passed"] = counts.all_passed();
  json["checks"] =
      Json{{"passed", counts.passed}, {"failed", counts.failed}, {"reported", counts.reported}};
  json["energy_balance_tolerance"] = energy_balance_tolerance;
  Json specimens = Json::array();
  for (const SpecimenOutcome& outcome : report.specimens) {
    Json runs = Json::array();
    for (const RunOutcome& run : outcome.runs) {
      Json checks = Json::array();
      for (const CheckResult& check : run.checks)
        checks.push_back(check_json(check));
      runs.push_back(Json{{"refinement", run.refinement},
                          {"core_elements", run.core_elements},
                          {"output_directory", run.output_directory.string()},
                          {"completed", run.completed},
                          {"stop_reason", run.completed ? Json(nullptr) : Json(run.stop_reason)},
                          {"steps", run.steps},
                          {"planned_steps", run.planned_steps},
                          {"iterations", run.iterations},
                          {"run_seconds", run.run_seconds},
                          {"resumed_from_step", run.resumed_from_step},
                          {"energy_balance_error", run.energy_balance_error},
                          {"integration_misfit", run.integration_misfit},
                          {"checks", std::move(checks)}});
    }
    const Specimen& specimen = outcome.specimen;
    specimens.push_back(Json{{"id", specimen.id},
                             {"title", specimen.title},
                             {"source", specimen.source},
                             {"yield_deformation", outcome.yield_deformation},
                             {"yield_force", outcome.yield_force},
                             {"notes", specimen.notes},
                             {"reference", reference_json(specimen)},
                             {"runs", std::move(runs)}});
  }
  json["specimens"] = std::move(specimens);
  Json contrasts = Json::array();
  for (const ContrastResult& result : report.contrasts) {
    const ContrastSpec& contrast = result.contrast;
    contrasts.push_back(Json{
        {"name", contrast.name},
        {"statement", contrast.statement},
        {"left", Json{{"specimen", contrast.left.specimen}, {"metric", contrast.left.metric}}},
        {"relation", contrast.relation},
        {"right", Json{{"specimen", contrast.right.specimen}, {"metric", contrast.right.metric}}},
        {"refinement", result.refinement ? Json(*result.refinement) : Json(nullptr)},
        {"left_value", optional_number(result.left)},
        {"right_value", optional_number(result.right)},
        {"status", status_word(result.status)},
        {"note", result.note},
        {"source", contrast.source}});
  }
  json["contrasts"] = std::move(contrasts);
  json["units"] = Json{{"force", "N"}, {"length", "mm"}};
  return json;
}

} // namespace brb::validation
