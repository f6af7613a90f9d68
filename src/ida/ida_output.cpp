#include "brb/ida/ida_output.hpp"

#include "brb/ida/ida_statistics.hpp"
#include "brb/io/atomic_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <sstream>

namespace brb::ida {
namespace {

/// The shortest text that reads back to the same double (std::to_chars), "inf" for infinity.
std::string number(double value) {
  if (std::isinf(value))
    return value > 0 ? "inf" : "-inf";
  std::array<char, 32> text{};
  const auto end = std::to_chars(text.data(), text.data() + text.size(), value).ptr;
  return std::string(text.data(), end);
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  io::AtomicFile out(file);
  out.write(text);
  out.commit();
}

std::vector<std::vector<CurvePoint>> curves_of(const IdaStudy& study,
                                               const std::vector<IdaPoint>& points) {
  std::vector<std::vector<CurvePoint>> curves(study.record_count());
  for (const IdaPoint& point : points)
    curves.at(static_cast<std::size_t>(point.record))
        .push_back({point.intensity, point.peak_drift(), point.collapsed()});
  return curves;
}

std::string points_csv(const IdaStudy& study, const std::vector<IdaPoint>& points) {
  std::ostringstream csv;
  csv << "record,intensity_g,scale,collapse,converged,max_drift,residual_drift,"
         "peak_floor_acceleration_g,max_core_strain,max_cid";
  for (const std::string& story : study.story_names())
    csv << ",drift_" << story;
  for (const std::string& story : study.story_names())
    csv << ",residual_" << story;
  csv << ",end_time,fallbacks,run_time_s\n";
  for (const IdaPoint& point : points) {
    csv << point.record_name << ',' << number(point.intensity) << ',' << number(point.scale) << ','
        << collapse_kind_name(point.collapse) << ',' << (point.converged ? 1 : 0) << ','
        << number(point.peak_drift()) << ',' << number(point.peak_residual()) << ','
        << number(point.peak_floor_acceleration) << ',' << number(point.max_core_strain) << ','
        << number(point.max_cid);
    // a run that stopped before its first step has no drifts: empty cells
    for (std::size_t s = 0; s < study.story_names().size(); ++s)
      csv << ',' << (s < point.max_drift.size() ? number(point.max_drift[s]) : "");
    for (std::size_t s = 0; s < study.story_names().size(); ++s)
      csv << ',' << (s < point.residual_drift.size() ? number(point.residual_drift[s]) : "");
    csv << ',' << number(point.end_time) << ',' << point.fallbacks << ',' << number(point.run_time)
        << '\n';
  }
  return csv.str();
}

std::string curves_csv(const IdaStudy& study, const std::vector<std::vector<CurvePoint>>& curves) {
  std::ostringstream csv;
  csv << "record,intensity_g,max_drift,state\n";
  for (std::size_t r = 0; r < curves.size(); ++r) {
    const std::string& name = study.suite().records[r].name;
    csv << name << ",0,0,origin\n";
    for (const CurvePoint& point : curve_below_flatline(curves[r]))
      csv << name << ',' << number(point.intensity) << ',' << number(point.demand) << ",run\n";
    // the flatline: from the lowest collapse on, the curve is at infinite demand
    if (!curves[r].empty()) {
      const CollapseCapacity capacity = collapse_capacity(curves[r]);
      if (!capacity.censored)
        csv << name << ',' << number(capacity.intensity) << ",inf,collapse\n";
    }
  }
  return csv.str();
}

std::string fractiles_csv(const std::vector<FractileRow>& rows) {
  std::ostringstream csv;
  csv << "max_drift,intensity_16_g,intensity_50_g,intensity_84_g\n";
  for (const FractileRow& row : rows)
    csv << number(row.demand) << ',' << number(row.p16) << ',' << number(row.p50) << ','
        << number(row.p84) << '\n';
  return csv.str();
}

} // namespace

std::vector<double> fractile_drift_levels(double drift_limit) {
  std::vector<double> levels;
  constexpr int kLevels = 40;
  for (int k = 1; k <= kLevels; ++k)
    levels.push_back(drift_limit * k / kLevels);
  return levels;
}

nlohmann::json write_ida_outputs(const std::filesystem::path& directory, const IdaStudy& study,
                                 const std::vector<IdaPoint>& points,
                                 const IdaRunDescription& description) {
  const std::vector<std::vector<CurvePoint>> curves = curves_of(study, points);
  const std::vector<double> levels = fractile_drift_levels(study.drift_limit());
  const std::vector<FractileRow> fractiles = fractiles_given_demand(curves, levels);

  nlohmann::json records = nlohmann::json::array();
  std::vector<CollapseCapacity> capacities;
  std::size_t drift_collapses = 0, numerical_collapses = 0, fallbacks = 0;
  for (const IdaPoint& point : points) {
    drift_collapses += point.collapse == CollapseKind::drift_limit ? 1 : 0;
    numerical_collapses += point.collapse == CollapseKind::numerical ? 1 : 0;
    fallbacks += static_cast<std::size_t>(point.fallbacks);
  }
  for (std::size_t r = 0; r < curves.size(); ++r) {
    nlohmann::json record = {{"name", study.suite().records[r].name},
                             {"file", study.suite().records[r].file.string()},
                             {"intensity_unscaled_g", study.record_intensity(r)},
                             {"runs", curves[r].size()}};
    if (!curves[r].empty()) {
      const CollapseCapacity capacity = collapse_capacity(curves[r]);
      capacities.push_back(capacity);
      record["collapse_intensity_g"] = capacity.intensity;
      record["censored"] = capacity.censored;
      // the collapse bracket: the highest survival below the lowest collapse, and whether
      // the bisection narrowed it to the resolution before the run budget ran out
      const std::vector<CurvePoint> below = curve_below_flatline(curves[r]);
      const double survival = below.empty() ? 0.0 : below.back().intensity;
      record["highest_survival_g"] = survival;
      record["bracket_resolved"] =
          !capacity.censored &&
          capacity.intensity - survival <= study.settings().trace.resolution * (1.0 + 1e-12);
    }
    records.push_back(record);
  }

  nlohmann::json fragility_json = nullptr;
  std::string fragility_note;
  std::ostringstream fragility_csv;
  fragility_csv << "intensity_g,probability_fitted,fraction_collapsed\n";
  try {
    const LognormalFragility fragility = fit_collapse_fragility(capacities);
    fragility_json = {{"median_g", fragility.median},
                      {"dispersion", fragility.dispersion},
                      {"collapses", fragility.collapses},
                      {"censored", fragility.censored},
                      {"log_median_standard_error", fragility.log_median_standard_error},
                      {"dispersion_standard_error", fragility.dispersion_standard_error}};
    if (study.settings().mce_intensity) {
      fragility_json["mce_intensity_g"] = *study.settings().mce_intensity;
      fragility_json["collapse_margin_ratio"] =
          collapse_margin_ratio(fragility, *study.settings().mce_intensity);
    }
    // the fitted curve against the fraction of records whose capacity is at or below IM
    // (censored capacities never count as collapsed)
    constexpr int kRows = 60;
    const double top = fragility.median * std::exp(3.0 * fragility.dispersion);
    for (int k = 1; k <= kRows; ++k) {
      const double intensity = top * k / kRows;
      std::size_t collapsed = 0;
      for (const CollapseCapacity& capacity : capacities)
        collapsed += !capacity.censored && capacity.intensity <= intensity ? 1 : 0;
      fragility_csv << number(intensity) << ',' << number(fragility.probability(intensity)) << ','
                    << number(static_cast<double>(collapsed) /
                              static_cast<double>(capacities.size()))
                    << '\n';
    }
  } catch (const std::invalid_argument& error) {
    fragility_note = std::string("no fragility: ") + error.what();
  }

  nlohmann::json summary = {{"model", description.model_file},
                            {"suite", description.suite_file},
                            {"intensity_measure", study.measure_label()},
                            {"intensity_units", "g"},
                            {"period", study.period()},
                            {"damping_ratio", study.settings().damping_ratio},
                            {"drift_limit", study.drift_limit()},
                            {"hunt_and_fill", to_json(study.settings().trace)},
                            {"runs", points.size()},
                            {"collapses_drift", drift_collapses},
                            {"collapses_numerical", numerical_collapses},
                            {"fallbacks", fallbacks},
                            {"records", records},
                            {"fragility", fragility_json},
                            {"parallelism", description.parallelism},
                            {"jobs", description.jobs},
                            {"runs_this_session", description.runs_this_session},
                            {"wall_time_s", description.wall_time}};
  if (!fragility_note.empty())
    summary["fragility_note"] = fragility_note;

  write_text(directory / "ida_points.csv", points_csv(study, points));
  write_text(directory / "ida_curves.csv", curves_csv(study, curves));
  write_text(directory / "ida_fractiles.csv", fractiles_csv(fractiles));
  if (!fragility_json.is_null())
    write_text(directory / "collapse_fragility.csv", fragility_csv.str());
  write_text(directory / "summary.json", summary.dump(2) + "\n");
  return summary;
}

} // namespace brb::ida
