// A validation specimen (DESIGN.md section 9): one folder `validation/<id>/` with the brace
// file, the loading protocol and `metrics.json`, which names the specimen's source, the mesh
// refinements to run, an optional measured record, the assumptions and the metrics to check
// (schema: validation/README.md). Every problem is an io::InputError naming the file, the
// JSON path and what was expected.
#pragma once

#include "brb/io/force_record.hpp"
#include "brb/io/json_input.hpp"
#include "brb/validation/failure_mode.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brb::validation {

/// How a computed value is compared with its reference: |result - reference| <= value
/// (absolute, in the metric's unit) or <= value |reference| (relative).
struct Tolerance {
  enum class Kind { relative, absolute };
  Kind kind = Kind::relative;
  double value = 0.0;
};

/// One metric of metrics.json. The kind (metric_kinds.hpp) turns a run into a value; the
/// check is one of: a reference with a tolerance, bounds (at_least / at_most), an expected
/// flag (kind "flag"), or none (the value is reported, not judged).
struct MetricSpec {
  std::string name;
  std::string kind;
  /// The whole metric object, from which the kind reads its own parameters (already checked
  /// by the kind when the file was read).
  nlohmann::json parameters;
  std::optional<double> reference;
  std::optional<Tolerance> tolerance; ///< present exactly when reference is
  std::optional<double> at_least;
  std::optional<double> at_most;
  std::optional<bool> expected; ///< kind "flag" only, and required there
  std::string unit;             ///< of the value and reference ("N", "N mm", "-")
  std::string source;           ///< where the reference or bound comes from
};

/// What a specimen's model is compared with (metrics.json's "reference"; schema in
/// validation/README.md):
/// - lab_record: a measured force-deformation record (a lab test) whose rows the protocol CSV
///   names point by point (column record_row_column), model step k being protocol point k;
/// - solid_run: the output directory of a `brb solid` run, its hysteresis.csv (the `brb
///   cyclic` columns, N and mm);
/// - solver_csv: a force-deformation CSV exported from another 3D solver (e.g. Abaqus), its
///   columns named and its units given like a lab record's.
/// The last two are sampled their own way and matched to the protocol's points along the
/// deformation path (reference_path.hpp).
enum class ReferenceType { lab_record, solid_run, solver_csv };

/// "lab_record", "solid_run", "solver_csv".
std::string to_string(ReferenceType type);

/// A reference force-deformation history for the record-based metrics: the CSV file, its
/// columns, units and excluded rows (io/force_record.hpp reads and converts it to N and mm at
/// the edge), how the model's points are matched to it, and the failure it states.
struct RecordReference {
  ReferenceType type = ReferenceType::lab_record;
  io::ForceRecordReference source; ///< resolved file and format (solid_run: its hysteresis.csv)
  std::string written;             ///< the file (or directory) as written in metrics.json
  /// solver_csv: the time column named in "columns" (checked to hold numbers; not used: the
  /// comparison follows the deformation path, not time).
  std::optional<std::string> time_column;
  /// lab_record: the protocol CSV's column holding, per point, the record's 0-based data row
  /// (-1: not a record point; not compared). Model step k is protocol point k.
  std::string record_row_column = "record_row";
  double reversal_threshold_dy = 0.1;  ///< cycle segmentation threshold, in dy
  double energy_floor_fraction = 0.05; ///< cycles below this share of the largest: not scored
  /// solid_run, solver_csv: the most the reference's deformation may differ from the
  /// protocol's at the same deformation travel (in dy) before the reference is refused as
  /// following another path.
  double path_tolerance_dy = 0.1;
  /// The failure mode and cycle the reference states ("failure"), for record_failure_mode.
  std::optional<FailureEvent> failure;
  /// solid_run: the 3D run's wall-clock time (its summary.json's solid.run_seconds, when the
  /// directory has one), which the report sets against the model's run time (issue 6: both run
  /// times and their ratio).
  std::optional<double> run_seconds;
  /// solid_run: the 3D run's quasi-static check (its summary.json's
  /// solid.max_kinetic_over_internal and solid.max_hourglass_over_internal, when written),
  /// which brb validate checks against issue 6's 0.05 (kQuasiStaticRatioLimit).
  std::optional<double> max_kinetic_over_internal;
  std::optional<double> max_hourglass_over_internal;
};

/// Issue 6: kinetic energy and hourglass energy below 5 % of the internal energy throughout
/// every validation run of the 3D model.
inline constexpr double kQuasiStaticRatioLimit = 0.05;

struct Specimen {
  std::string id; ///< the folder's name; metrics.json's "id" must equal it
  std::string title;
  std::string source;
  std::filesystem::path directory;
  std::filesystem::path metrics_file;
  std::filesystem::path brace_file;    ///< resolved against the folder
  std::filesystem::path protocol_file; ///< resolved against the folder
  std::vector<int> refinements;        ///< multipliers of every zone's element count
  /// The solver's balance control for this specimen's runs (NewtonSettings::
  /// balance_tolerance; 0: off, the default), metrics.json's solver.balance_tolerance.
  double balance_tolerance = 0.0;
  std::optional<RecordReference> record;
  /// For lab records: "calibration" (the specimen calibrated its grade's steel) or
  /// "prediction" (run with the steel calibrated on `calibrated_on`); empty otherwise.
  std::string role;
  std::string calibrated_on;
  std::vector<std::string> notes;
  std::vector<MetricSpec> metrics;
};

/// The name of the metrics file of a specimen folder.
inline constexpr const char* metrics_file_name = "metrics.json";
/// The prefix of a path that resolves against the shared directory (--shared).
inline constexpr const char* shared_prefix = "shared:";

/// Reads `directory/metrics.json`; `shared_directory` resolves "shared:" paths of the
/// reference record, whose file must exist. Checks that the brace and protocol files exist
/// (their content is read by the run). Throws io::InputError.
Specimen read_specimen(const std::filesystem::path& directory,
                       const std::filesystem::path& shared_directory);

/// A metrics.json "reference" object on its own (any type: lab_record, solid_run, solver_csv;
/// schema in validation/README.md), its files resolved against `directory` and "shared:"
/// paths against `shared_directory`, e.g. for `brb calibrate --record`. Throws
/// io::InputError naming the JSON path.
RecordReference read_record_reference(const io::JsonValue& value,
                                      const std::filesystem::path& directory,
                                      const std::filesystem::path& shared_directory);

/// The specimen folders under `validation_directory`: its sub-directories that hold a
/// metrics.json, sorted by name. Throws io::InputError when `validation_directory` is not a
/// directory.
std::vector<std::filesystem::path>
find_specimen_directories(const std::filesystem::path& validation_directory);

/// A list of positive whole numbers "1,2,4" (the --refinements option); `what` names the
/// option in the error (std::invalid_argument).
std::vector<int> parse_refinement_list(const std::string& text);

} // namespace brb::validation
