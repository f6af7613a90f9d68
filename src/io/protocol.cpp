#include "brb/io/protocol.hpp"

#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace brb::io {
namespace {

/// The most entries a "cycles" list may have (a real protocol has a few dozen).
constexpr std::size_t kMaxCycleGroups = 10'000;

/// The Girona amplitudes before the repeated final one, in multiples of dy, one cycle each
/// (BRB_SOURCE_FACTS section 7).
constexpr double kGironaRampAmplitudes[] = {0.25, 0.5, 0.75, 1.0, 2.0, 2.5};
/// The Girona amplitude repeated until failure, in multiples of dy (section 7).
constexpr double kGironaFinalAmplitude = 5.0;
/// The UC San Diego G-series protocol, (amplitude in dy, cycles) (BRB_SOURCE_FACTS section 8).
constexpr std::pair<double, int> kUcsdGroups[] = {{1.0, 5}, {2.0, 2}, {3.0, 1}, {4.0, 1}};

void require_positive_finite(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string(what) + " must be a positive finite number, got " +
                                format_number(value));
  }
}

/// The number of equal steps of at most max_step (to within step_rounding_tolerance) that
/// cover a leg of `length` (>= 0); at least one, so that every given point is kept. A double,
/// so that absurd ratios can be checked against max_protocol_points before any conversion.
double steps_on_leg(double length, double max_step) {
  return std::max(1.0, std::ceil(length / max_step * (1.0 - step_rounding_tolerance)));
}

/// Points of a cycle of amplitude A, its initial zero excluded: legs 0 -> A, A -> -A, -A -> 0.
double points_per_cycle(double amplitude, double max_step) {
  return 2.0 * steps_on_leg(amplitude, max_step) + steps_on_leg(2.0 * amplitude, max_step);
}

double cyclic_point_count(const std::vector<CycleGroup>& groups, double max_step) {
  double count = 1.0; // the initial zero
  for (const CycleGroup& group : groups) {
    count += group.cycles * points_per_cycle(group.amplitude, max_step);
  }
  return count;
}

/// The points of history_protocol(points, max_step), with 0.0 put first if needed.
double history_point_count(const std::vector<double>& points, double max_step) {
  double count = 1.0;
  double previous = 0.0;
  for (const double point : points) {
    count += steps_on_leg(std::abs(point - previous), max_step);
    previous = point;
  }
  return points.front() == 0.0 ? count - 1.0 : count;
}

bool exceeds_point_limit(double count) {
  return count > static_cast<double>(max_protocol_points);
}

std::string too_many_points_message(double count) {
  return "the protocol would have " + format_number(count) + " points, more than " +
         std::to_string(max_protocol_points) + ": give a larger max_step or fewer cycles";
}

/// Appends the leg from the last point to `target` in equal steps of at most max_step; the
/// target itself is appended exactly. std::lerp is exact at both ends and monotonic.
void append_leg(LoadingProtocol& protocol, double target, int cycle, double max_step) {
  const double start = protocol.deformation.back();
  const auto steps = static_cast<std::size_t>(steps_on_leg(std::abs(target - start), max_step));
  for (std::size_t step = 1; step <= steps; ++step) {
    const double fraction = static_cast<double>(step) / static_cast<double>(steps);
    protocol.deformation.push_back(step == steps ? target : std::lerp(start, target, fraction));
    protocol.cycle.push_back(cycle);
  }
}

LoadingProtocol starting_at_zero(std::string name, std::size_t expected_points) {
  LoadingProtocol protocol;
  protocol.name = std::move(name);
  protocol.deformation = {0.0};
  protocol.cycle = {0};
  protocol.deformation.reserve(expected_points);
  protocol.cycle.reserve(expected_points);
  return protocol;
}

std::vector<CycleGroup> girona_groups(double yield_deformation, int final_cycles) {
  std::vector<CycleGroup> groups;
  for (const double amplitude : kGironaRampAmplitudes) {
    groups.push_back({.amplitude = amplitude * yield_deformation, .cycles = 1});
  }
  groups.push_back(
      {.amplitude = kGironaFinalAmplitude * yield_deformation, .cycles = final_cycles});
  return groups;
}

std::vector<CycleGroup> ucsd_groups(double yield_deformation) {
  std::vector<CycleGroup> groups;
  for (const auto& [amplitude, cycles] : kUcsdGroups) {
    groups.push_back({.amplitude = amplitude * yield_deformation, .cycles = cycles});
  }
  return groups;
}

// ---- Protocol JSON files ----

/// What the amplitudes and max_step of a protocol file are measured in.
enum class ProtocolUnit { millimetre, yield_deformation };

constexpr std::string_view kUnitsMeaning =
    "units of the amplitudes and max_step: \"mm\", or \"dy\" for multiples of the brace's "
    "yield deformation; a protocol with unit-less amplitudes is rejected";

double positive_number(const JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (!(number > 0.0)) {
    throw value.error("expected a number > 0 (" + std::string(meaning) + "), got " +
                      describe_json_value(value.json()));
  }
  return number;
}

int positive_integer(const JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (number != std::floor(number) || number < 1.0) {
    throw value.error("expected a positive integer (" + std::string(meaning) + "), got " +
                      describe_json_value(value.json()));
  }
  if (number > std::numeric_limits<int>::max()) {
    throw value.error("expected a positive integer of at most " +
                      std::to_string(std::numeric_limits<int>::max()) + " (" +
                      std::string(meaning) + "), got " + describe_json_value(value.json()));
  }
  return static_cast<int>(number);
}

/// "units": required with "cycles"; optional with "builtin" (default "dy").
ProtocolUnit read_unit(const JsonValue& root, bool builtin) {
  const auto units = builtin ? root.find("units") : root.at("units", kUnitsMeaning);
  if (!units)
    return ProtocolUnit::yield_deformation;
  const std::string unit = units->string(kUnitsMeaning);
  if (unit == "mm")
    return ProtocolUnit::millimetre;
  if (unit == "dy")
    return ProtocolUnit::yield_deformation;
  throw units->error("expected \"mm\" or \"dy\" (multiples of the brace's yield deformation), "
                     "got " +
                     describe_json_value(units->json()));
}

double millimetres_per_unit(ProtocolUnit unit, double yield_deformation) {
  return unit == ProtocolUnit::millimetre ? 1.0 : yield_deformation;
}

std::vector<CycleGroup> read_cycle_groups(const JsonValue& cycles, double unit_in_mm) {
  constexpr std::string_view kGroupMeaning =
      "cycle groups {\"amplitude\": number > 0, \"cycles\": positive integer}";
  const std::size_t count = cycles.expect_array(kMaxCycleGroups, kGroupMeaning);
  if (count == 0) {
    throw cycles.error("protocol with no cycles: expected at least one of the " +
                       std::string(kGroupMeaning));
  }
  std::vector<CycleGroup> groups;
  groups.reserve(count);
  for (std::size_t index = 0; index < count; ++index) {
    const JsonValue group = cycles.element(index);
    group.expect_object({"amplitude", "cycles"},
                        "an object {\"amplitude\": number > 0, \"cycles\": positive integer}");
    constexpr std::string_view kAmplitude = "cycle amplitude, in \"units\"";
    constexpr std::string_view kCycles = "number of full cycles at this amplitude";
    const JsonValue amplitude = group.at("amplitude", kAmplitude);
    const double amplitude_in_mm = positive_number(amplitude, kAmplitude) * unit_in_mm;
    if (!(std::isfinite(amplitude_in_mm) && amplitude_in_mm > 0.0)) {
      // Possible only for absurd values: the conversion of dy to mm overflowed or underflowed.
      throw amplitude.error("the amplitude in mm is " + format_number(amplitude_in_mm) +
                            ", not a positive finite number");
    }
    groups.push_back({.amplitude = amplitude_in_mm,
                      .cycles = positive_integer(group.at("cycles", kCycles), kCycles)});
  }
  return groups;
}

/// "max_step" in mm.
double read_max_step(const JsonValue& value, double unit_in_mm) {
  const double max_step =
      positive_number(value, "largest deformation change between two points, in \"units\"") *
      unit_in_mm;
  if (!(std::isfinite(max_step) && max_step > 0.0)) {
    // Possible only for absurd values: the conversion of dy to mm overflowed or underflowed.
    throw value.error("max_step in mm is " + format_number(max_step) +
                      ", not a positive finite number");
  }
  return max_step;
}

struct BuiltinChoice {
  std::string name;
  std::vector<CycleGroup> groups;
};

BuiltinChoice read_builtin(const JsonValue& root, const JsonValue& builtin,
                           double yield_deformation) {
  if (const auto cycles = root.find("cycles")) {
    throw cycles->error("not allowed with \"builtin\": a protocol is either built in or given "
                        "by its cycles");
  }
  const std::string name = builtin.string("built-in protocol, \"girona\" or \"ucsd\"");
  const auto final_cycles = root.find("final_cycles");
  if (name == "girona") {
    constexpr std::string_view kFinalCycles =
        "number of cycles at 5 dy after the ramp; the Girona tests repeated them until failure";
    const JsonValue value = final_cycles ? *final_cycles : root.at("final_cycles", kFinalCycles);
    return {name, girona_groups(yield_deformation, positive_integer(value, kFinalCycles))};
  }
  if (name == "ucsd") {
    if (final_cycles) {
      throw final_cycles->error("not allowed with \"builtin\": \"ucsd\" (only \"girona\" ends "
                                "with repeated cycles)");
    }
    return {name, ucsd_groups(yield_deformation)};
  }
  throw builtin.error("unknown built-in protocol \"" + name +
                      "\"; expected \"girona\" or \"ucsd\"");
}

LoadingProtocol read_protocol_json(const std::filesystem::path& file, double yield_deformation,
                                   double default_max_step) {
  const std::string source = file.string();
  const nlohmann::json document = read_json_file(file);
  const JsonValue root(document, source);
  root.expect_object({"units", "cycles", "max_step", "builtin", "final_cycles"},
                     "a protocol object with \"units\" and \"cycles\", or with \"builtin\"");

  const auto builtin = root.find("builtin");
  std::optional<JsonValue> cycles;
  if (!builtin) {
    if (const auto final_cycles = root.find("final_cycles")) {
      throw final_cycles->error("allowed only with \"builtin\": \"girona\"");
    }
    // Asked for before "units", so that an empty object says what a protocol is made of.
    cycles = root.at("cycles", "list of cycle groups {\"amplitude\", \"cycles\"}; or give "
                               "\"builtin\": \"girona\" or \"ucsd\"");
  }
  const double unit_in_mm =
      millimetres_per_unit(read_unit(root, builtin.has_value()), yield_deformation);

  const auto max_step_value = root.find("max_step");
  const double max_step =
      max_step_value ? read_max_step(*max_step_value, unit_in_mm) : default_max_step;

  auto [name, groups] = builtin ? read_builtin(root, *builtin, yield_deformation)
                                : BuiltinChoice{source, read_cycle_groups(*cycles, unit_in_mm)};
  if (const double count = cyclic_point_count(groups, max_step); exceeds_point_limit(count)) {
    throw max_step_value
        ? max_step_value->error(too_many_points_message(count))
        : root.error(too_many_points_message(count) + " (give \"max_step\"; the default is " +
                     format_number(default_max_step) + " mm)");
  }
  return cyclic_protocol(std::move(name), groups, max_step);
}

// ---- CSV histories ----

constexpr const char* kDeformationColumn = "deformation";

LoadingProtocol read_protocol_csv(const std::filesystem::path& file, double max_step) {
  const std::string source = file.string();
  const NumericColumn column = read_numeric_column(file, kDeformationColumn);
  const auto& points = column.values;
  if (std::all_of(points.begin(), points.end(), [](double point) { return point == 0.0; })) {
    throw InputError(source, "",
                     "the deformation never leaves 0: a protocol needs at least one non-zero "
                     "point in column 'deformation' (mm)");
  }
  if (const double count = history_point_count(points, max_step); exceeds_point_limit(count)) {
    throw InputError(source, "",
                     "subdivided in steps of at most " + format_number(max_step) +
                         " mm, the history would have " + format_number(count) +
                         " points, more than " + std::to_string(max_protocol_points));
  }
  return history_protocol(source, points, max_step);
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char character) {
    return static_cast<char>(std::tolower(character));
  });
  return text;
}

} // namespace

LoadingProtocol read_protocol(const std::filesystem::path& file, double yield_deformation,
                              double default_max_step) {
  require_positive_finite(yield_deformation, "read_protocol: yield_deformation (mm)");
  require_positive_finite(default_max_step, "read_protocol: default_max_step (mm)");
  const std::string extension = lowercase(file.extension().string());
  if (extension == ".json")
    return read_protocol_json(file, yield_deformation, default_max_step);
  if (extension == ".csv")
    return read_protocol_csv(file, default_max_step);
  throw InputError(file.string(), "",
                   "unknown protocol file type: expected a protocol file ending in .json or a "
                   "deformation history ending in .csv (column 'deformation', mm)");
}

LoadingProtocol girona_protocol(double yield_deformation, int final_cycles, double max_step) {
  require_positive_finite(yield_deformation, "girona_protocol: yield_deformation (mm)");
  if (final_cycles < 1) {
    throw std::invalid_argument("girona_protocol: final_cycles must be at least 1, got " +
                                std::to_string(final_cycles));
  }
  return cyclic_protocol("girona", girona_groups(yield_deformation, final_cycles), max_step);
}

LoadingProtocol ucsd_protocol(double yield_deformation, double max_step) {
  require_positive_finite(yield_deformation, "ucsd_protocol: yield_deformation (mm)");
  return cyclic_protocol("ucsd", ucsd_groups(yield_deformation), max_step);
}

LoadingProtocol cyclic_protocol(std::string name, const std::vector<CycleGroup>& groups,
                                double max_step) {
  require_positive_finite(max_step, "cyclic_protocol: max_step (mm)");
  if (groups.empty())
    throw std::invalid_argument("cyclic_protocol: no cycle groups");
  for (const CycleGroup& group : groups) {
    require_positive_finite(group.amplitude, "cyclic_protocol: amplitude (mm)");
    if (group.cycles < 1) {
      throw std::invalid_argument("cyclic_protocol: cycles must be at least 1, got " +
                                  std::to_string(group.cycles));
    }
  }
  const double count = cyclic_point_count(groups, max_step);
  if (exceeds_point_limit(count))
    throw std::invalid_argument("cyclic_protocol: " + too_many_points_message(count));

  LoadingProtocol protocol = starting_at_zero(std::move(name), static_cast<std::size_t>(count));
  int cycle = 0;
  for (const CycleGroup& group : groups) {
    for (int repetition = 0; repetition < group.cycles; ++repetition) {
      ++cycle;
      append_leg(protocol, group.amplitude, cycle, max_step);
      append_leg(protocol, -group.amplitude, cycle, max_step);
      append_leg(protocol, 0.0, cycle, max_step);
      protocol.cycle_amplitude.push_back(group.amplitude);
    }
  }
  return protocol;
}

LoadingProtocol history_protocol(std::string name, const std::vector<double>& points,
                                 double max_step) {
  require_positive_finite(max_step, "history_protocol: max_step (mm)");
  if (points.empty())
    throw std::invalid_argument("history_protocol: no points");
  if (!std::all_of(points.begin(), points.end(), [](double point) { return std::isfinite(point); }))
    throw std::invalid_argument("history_protocol: a point is not a finite number");
  const auto first_nonzero =
      std::find_if(points.begin(), points.end(), [](double point) { return point != 0.0; });
  if (first_nonzero == points.end())
    throw std::invalid_argument("history_protocol: every point is zero");
  const double count = history_point_count(points, max_step);
  if (exceeds_point_limit(count))
    throw std::invalid_argument("history_protocol: " + too_many_points_message(count));

  // Subdivide, all points in cycle 1 for now; the given first point, when it is 0, is the
  // initial point (a -0.0 is stored as 0.0).
  LoadingProtocol protocol = starting_at_zero(std::move(name), static_cast<std::size_t>(count));
  const auto rest = points.front() == 0.0 ? points.begin() + 1 : points.begin();
  for (auto point = rest; point != points.end(); ++point) {
    append_leg(protocol, *point, 1, max_step);
  }

  // Count cycles by sign reversals (rule at the top of protocol.hpp): with the leading sign
  // s of the first excursion, cycle c ends at the first point d_i with s d_i >= 0 after a
  // point with s d_(i-1) < 0.
  const double leading_sign = *first_nonzero > 0.0 ? 1.0 : -1.0;
  int cycle = 1;
  for (std::size_t i = 1; i < protocol.deformation.size(); ++i) {
    const double previous = leading_sign * protocol.deformation[i - 1];
    const double current = leading_sign * protocol.deformation[i];
    protocol.cycle[i] = cycle;
    if (protocol.cycle_amplitude.size() < static_cast<std::size_t>(cycle))
      protocol.cycle_amplitude.push_back(0.0);
    protocol.cycle_amplitude.back() =
        std::max(protocol.cycle_amplitude.back(), std::abs(protocol.deformation[i]));
    if (previous < 0.0 && current >= 0.0)
      ++cycle;
  }
  return protocol;
}

} // namespace brb::io
