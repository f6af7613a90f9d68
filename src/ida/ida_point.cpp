#include "brb/ida/ida_point.hpp"

#include <algorithm>
#include <stdexcept>

namespace brb::ida {

std::string_view collapse_kind_name(CollapseKind kind) {
  switch (kind) {
  case CollapseKind::none:
    return "none";
  case CollapseKind::drift_limit:
    return "drift";
  case CollapseKind::numerical:
    return "numerical";
  }
  return "none";
}

namespace {

CollapseKind collapse_kind_named(std::string_view text) {
  for (const CollapseKind kind :
       {CollapseKind::none, CollapseKind::drift_limit, CollapseKind::numerical}) {
    if (collapse_kind_name(kind) == text)
      return kind;
  }
  throw std::invalid_argument("unknown collapse kind \"" + std::string(text) + "\"");
}

double largest(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

} // namespace

double IdaPoint::peak_drift() const {
  return largest(max_drift);
}

double IdaPoint::peak_residual() const {
  return largest(residual_drift);
}

nlohmann::json to_json(const IdaPoint& point) {
  return {{"record", point.record},
          {"record_name", point.record_name},
          {"intensity", point.intensity},
          {"scale", point.scale},
          {"collapse", collapse_kind_name(point.collapse)},
          {"converged", point.converged},
          {"max_drift", point.max_drift},
          {"residual_drift", point.residual_drift},
          {"peak_floor_acceleration", point.peak_floor_acceleration},
          {"max_core_strain", point.max_core_strain},
          {"max_cid", point.max_cid},
          {"end_time", point.end_time},
          {"fallbacks", point.fallbacks},
          {"run_time", point.run_time},
          {"stop_reason", point.stop_reason}};
}

IdaPoint point_from_json(const nlohmann::json& line) {
  try {
    IdaPoint point;
    point.record = line.at("record").get<int>();
    point.record_name = line.at("record_name").get<std::string>();
    point.intensity = line.at("intensity").get<double>();
    point.scale = line.at("scale").get<double>();
    point.collapse = collapse_kind_named(line.at("collapse").get<std::string>());
    point.converged = line.at("converged").get<bool>();
    point.max_drift = line.at("max_drift").get<std::vector<double>>();
    point.residual_drift = line.at("residual_drift").get<std::vector<double>>();
    point.peak_floor_acceleration = line.at("peak_floor_acceleration").get<double>();
    point.max_core_strain = line.at("max_core_strain").get<double>();
    point.max_cid = line.at("max_cid").get<double>();
    point.end_time = line.at("end_time").get<double>();
    point.fallbacks = line.at("fallbacks").get<int>();
    point.run_time = line.at("run_time").get<double>();
    point.stop_reason = line.at("stop_reason").get<std::string>();
    return point;
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(std::string("malformed IDA point: ") + error.what());
  }
}

} // namespace brb::ida
