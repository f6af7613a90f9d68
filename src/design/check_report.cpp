#include "brb/design/check_report.hpp"
#include "brb/io/csv.hpp"

#include <iomanip>
#include <sstream>

namespace brb::design {
namespace {

using io::significant;

nlohmann::ordered_json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

std::string drift_source(const CheckSpec& check) {
  switch (check.design_drift.source) {
  case DriftSource::ratio:
    return "ratio";
  case DriftSource::drift:
    return "drift";
  case DriftSource::elastic:
    return "elastic";
  }
  return "";
}

} // namespace

std::string verdict(const CheckResult& result) {
  return result.passed() ? "PASS" : "FAIL";
}

nlohmann::ordered_json check_json(const CheckSpec& check, const CheckResult& result) {
  using nlohmann::ordered_json;
  const QualificationResult& q = result.qualification;
  ordered_json out;
  out["check"] = check.name;
  out["brace"] = check.brace.name;
  out["brace_source"] = check.brace_source;
  out["edition"] = to_string(check.edition.edition);
  out["verdict"] = verdict(result);
  out["failed_criteria"] = failed_criteria(q);

  ordered_json story;
  story["height"] = check.story.story_height;
  story["bay_width"] = check.story.bay_width;
  story["configuration"] = to_string(check.story.configuration);
  story["angle_deg"] = check.story.angle() * 180.0 / 3.14159265358979323846;
  story["frame"] =
      check.frame_source.empty() ? ordered_json(nullptr) : ordered_json(check.frame_source);
  story["frame_story"] =
      check.frame_brace ? ordered_json(check.frame_brace->story) : ordered_json(nullptr);
  out["story"] = story;

  ordered_json demand;
  demand["drift_source"] = drift_source(check);
  demand["story_drift"] = result.demand.story_drift;
  demand["minimum_story_drift"] = result.demand.minimum_drift;
  demand["used_story_drift"] = result.demand.used_story_drift;
  demand["used_drift_ratio"] = result.demand.used_story_drift / check.story.story_height;
  demand["small_displacement_deformation"] = result.demand.small_displacement_deformation;
  demand["frame_deformation"] = optional_number(result.demand.frame_deformation);
  demand["design_deformation"] = result.demand.design_deformation;
  demand["design_deformation_dy"] = result.demand.design_deformation / result.yield_deformation;
  demand["kinematics"] = result.demand.kinematics;
  out["demand"] = demand;

  ordered_json brace;
  brace["yield_deformation"] = result.yield_deformation;
  brace["yield_force"] = result.yield_force;
  brace["core_area"] = result.forces.core_area;
  brace["Fysc_specified"] = optional_number(check.fysc_specified);
  brace["Fysc_measured"] = optional_number(check.fysc_measured);
  brace["Ry"] = check.Ry;
  brace["Pysc_tested"] = result.forces.tested;
  brace["Pysc_tested_basis"] = result.forces.tested_basis;
  brace["Pysc_design"] = result.forces.design;
  out["brace_properties"] = brace;

  ordered_json sequence;
  sequence["steps"] = ordered_json::array();
  for (const io::CycleGroup& group : q.sequence.groups)
    sequence["steps"].push_back({{"amplitude", group.amplitude}, {"cycles", group.cycles}});
  sequence["extra_amplitude"] = q.sequence.extra_amplitude;
  sequence["cumulative_target"] = q.sequence.cumulative_target;
  sequence["estimated_extra_cycles"] = q.estimated_extra_cycles;
  sequence["extra_cycles"] = q.extra_cycles;
  sequence["cumulative_target_reached"] = q.cumulative_target_reached;
  sequence["stopped_at_failure"] = q.stopped_at_failure;
  sequence["max_step"] = check.max_step * result.yield_deformation;
  out["sequence"] = sequence;

  ordered_json cycles = ordered_json::array();
  for (const QualificationCycle& cycle : q.cycles) {
    ordered_json row;
    row["index"] = cycle.index;
    row["step"] = cycle.sequence_step;
    row["amplitude"] = cycle.amplitude;
    row["amplitude_dy"] = cycle.amplitude / result.yield_deformation;
    row["Tmax"] = cycle.max_tension;
    row["Pmax"] = cycle.max_compression;
    row["beta"] = cycle.beta;
    row["omega"] = cycle.omega;
    row["cumulative_inelastic_deformation"] = cycle.cumulative_inelastic_deformation;
    row["largest_force_drop"] = cycle.largest_force_drop;
    row["beyond_yield"] = cycle.beyond_yield;
    row["in_adjustment_range"] = cycle.in_adjustment_range;
    cycles.push_back(row);
  }
  out["cycles"] = cycles;

  ordered_json adjusted;
  adjusted["beta"] = q.beta;
  adjusted["omega"] = q.omega;
  adjusted["tension"] = result.adjusted_tension;
  adjusted["compression"] = result.adjusted_compression;
  out["adjusted_strengths"] = adjusted;

  const analysis::BraceIndicators& indicators = q.test.indicators;
  ordered_json flags;
  flags["core_fracture"] = indicators.core_fracture;
  flags["casing_failure"] = indicators.casing_failure;
  flags["global_buckling"] = indicators.global_buckling;
  flags["max_steel_damage"] = indicators.max_steel_damage;
  flags["max_mortar_damage"] = indicators.max_mortar_damage;
  flags["max_casing_lateral_displacement"] = indicators.max_casing_lateral_displacement;
  flags["cumulative_inelastic_deformation"] = indicators.cumulative_inelastic_deformation;
  flags["core_strain_at_2dbm"] = optional_number(q.core_strain_at_2dbm);
  out["indicators"] = flags;

  ordered_json criteria = ordered_json::array();
  for (const Criterion& criterion : q.criteria) {
    criteria.push_back({{"id", criterion.id},
                        {"description", criterion.description},
                        {"value", criterion.value},
                        {"comparison", criterion.comparison},
                        {"limit", criterion.limit},
                        {"passed", criterion.passed},
                        {"note", criterion.note}});
  }
  out["criteria"] = criteria;

  if (result.drift_capacity) {
    const DriftCapacity& capacity = *result.drift_capacity;
    ordered_json c;
    c["drift_ratio"] = optional_number(capacity.drift_ratio);
    c["bracket"] = capacity.bracket;
    c["resolution"] = capacity.resolution;
    c["upper"] = capacity.upper;
    c["upper_passed"] = capacity.upper_passed;
    c["limited_by"] = capacity.limited_by;
    c["trials"] = ordered_json::array();
    for (const DriftTrial& trial : capacity.trials) {
      c["trials"].push_back({{"drift_ratio", trial.drift_ratio},
                             {"design_deformation", trial.design_deformation},
                             {"passed", trial.passed},
                             {"failed", trial.failed}});
    }
    out["drift_capacity"] = c;
  } else {
    out["drift_capacity"] = nullptr;
  }

  const analysis::CyclicTestResult& test = q.test;
  ordered_json solver;
  solver["completed"] = test.completed;
  solver["stop_reason"] = test.completed ? ordered_json(nullptr) : ordered_json(test.stop_reason);
  solver["steps"] = static_cast<int>(test.steps.size()) - 1;
  solver["iterations"] = test.iterations;
  solver["regularised_steps"] = test.regularised_steps;
  solver["energy_balance_error"] = test.energy_balance.relative_error();
  out["solver"] = solver;
  out["warnings"] = result.warnings;
  out["units"] = {{"force", "N"}, {"length", "mm"}, {"stress", "MPa"}};
  return out;
}

std::string check_markdown(const CheckSpec& check, const CheckResult& result) {
  const QualificationResult& q = result.qualification;
  const double dy = result.yield_deformation;
  std::ostringstream md;
  md << "# AISC " << to_string(check.edition.edition) << " BRB check: " << check.name << "\n\n"
     << "**Verdict: " << verdict(result) << "**";
  if (!q.passed)
    md << " (failed: " << failed_criteria(q) << ")";
  md << "\n\n"
     << "Virtual qualification test (K3.4c sequence) of the full reduced-order brace model; "
        "units N, mm, MPa.\n\n"
     << "## Brace and demand\n\n"
     << "| quantity | value |\n|---|---|\n"
     << "| brace | " << check.brace_source << " |\n"
     << "| story height, bay, configuration | " << fixed(check.story.story_height, 1) << " mm, "
     << fixed(check.story.bay_width, 1) << " mm, " << to_string(check.story.configuration) << " |\n"
     << "| design story drift (given) | " << fixed(result.demand.story_drift, 2) << " mm |\n"
     << "| used story drift (>= " << check.edition.minimum_drift_ratio << " h) | "
     << fixed(result.demand.used_story_drift, 2) << " mm |\n"
     << "| kinematics | " << result.demand.kinematics << " |\n"
     << "| Delta_bm | " << fixed(result.demand.design_deformation, 3) << " mm ("
     << fixed(result.demand.design_deformation / dy, 2) << " Delta_by) |\n"
     << "| Delta_by (model) | " << fixed(dy, 4) << " mm |\n"
     << "| Asc | " << fixed(result.forces.core_area, 1) << " mm^2 |\n"
     << "| Pysc tested (" << result.forces.tested_basis << ") | "
     << significant(result.forces.tested, 6) << " N |\n"
     << "| Ry | " << check.Ry << " |\n"
     << "| step-6 cycles at 1.5 Delta_bm | " << q.extra_cycles << " (estimate "
     << q.estimated_extra_cycles << ") |\n"
     << "| core strain at 2 Delta_bm | "
     << (q.core_strain_at_2dbm ? fixed(*q.core_strain_at_2dbm * 100.0, 3) + " %" : "not reached")
     << " |\n\n"
     << "## Cycles\n\n"
     << "| cycle | step | amplitude (mm) | amplitude (Delta_by) | Tmax (N) | Pmax (N) | beta | "
        "omega | CID (Delta_by) | largest force drop (Pysc) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const QualificationCycle& cycle : q.cycles) {
    md << "| " << cycle.index << " | " << cycle.sequence_step << " | " << fixed(cycle.amplitude, 3)
       << " | " << fixed(cycle.amplitude / dy, 2) << " | " << significant(cycle.max_tension, 6)
       << " | " << significant(cycle.max_compression, 6) << " | " << fixed(cycle.beta, 3) << " | "
       << fixed(cycle.omega, 3) << " | " << fixed(cycle.cumulative_inelastic_deformation, 1)
       << " | " << fixed(cycle.largest_force_drop, 4) << " |\n";
  }
  md << "\n## Adjusted brace strengths (F4.2a)\n\n"
     << "| quantity | value |\n|---|---|\n"
     << "| beta (cycles up to 2 Delta_bm, >= 1.0) | " << fixed(q.beta, 3) << " |\n"
     << "| omega (cycles up to 2 Delta_bm) | " << fixed(q.omega, 3) << " |\n"
     << "| tension omega Ry Pysc | " << significant(result.adjusted_tension, 6) << " N |\n"
     << "| compression beta omega Ry Pysc | " << significant(result.adjusted_compression, 6)
     << " N |\n\n"
     << "## Acceptance criteria (K3.8)\n\n"
     << "| criterion | check | value | limit | result | note |\n|---|---|---|---|---|---|\n";
  for (const Criterion& criterion : q.criteria) {
    const bool flag = criterion.comparison == "flag";
    md << "| " << criterion.id << " | " << criterion.description << " | "
       << (flag ? (criterion.value != 0.0 ? "raised" : "not raised")
                : significant(criterion.value, 4))
       << " | "
       << (flag ? "not raised" : criterion.comparison + " " + significant(criterion.limit, 4))
       << " | " << (criterion.passed ? "pass" : "**FAIL**") << " | " << criterion.note << " |\n";
  }
  if (result.drift_capacity) {
    const DriftCapacity& capacity = *result.drift_capacity;
    md << "\n## Drift capacity\n\n";
    if (!capacity.drift_ratio) {
      md << "None: the brace fails at the minimum design drift ("
         << check.edition.minimum_drift_ratio << " h); failed: " << capacity.limited_by << ".\n";
    } else if (capacity.upper_passed) {
      md << "At least " << fixed(*capacity.drift_ratio * 100.0, 3)
         << " % of the story height (the top of the search passed).\n";
    } else {
      md << "Largest passing design story drift: " << fixed(*capacity.drift_ratio * 100.0, 3)
         << " % of the story height (the capacity is below "
         << fixed((*capacity.drift_ratio + capacity.bracket) * 100.0, 3) << " %; resolution asked "
         << fixed(capacity.resolution * 100.0, 3) << " %); limited by: " << capacity.limited_by
         << ".\n";
    }
    md << "\n| drift ratio (%) | Delta_bm (mm) | result | failed |\n|---|---|---|---|\n";
    for (const DriftTrial& trial : capacity.trials) {
      md << "| " << fixed(trial.drift_ratio * 100.0, 3) << " | "
         << fixed(trial.design_deformation, 3) << " | " << (trial.passed ? "pass" : "FAIL") << " | "
         << trial.failed << " |\n";
    }
  }
  md << "\nbeta limit: " << check.beta_limit() << " ("
     << (check.beta_limit_override ? "set in the check file" : check.edition.beta_limit_source)
     << ").\n";
  return md.str();
}

} // namespace brb::design
