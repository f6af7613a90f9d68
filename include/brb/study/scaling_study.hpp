// `brb bench scaling` (issue 9): cost of a frame's time-history analysis against its number
// of braces and against the length of the record, with the least-squares exponent of each.
//
// Generated frames: one storey of N bays with one brace per bay (N = number of braces), built
// from the first storey of a frame file: its column and beam sections, the first brace of
// that storey (its work points give the bay's width and height), the mass of its first
// floor node on every floor node, its damping and analysis settings. The braces alternate in
// direction from bay to bay; the columns are fixed at the base. The bays are alike, so the
// cost grows with the size of the model; the response is not quite the same for every N
// (N + 1 columns and floor masses for N braces: the mass per brace falls from 2 to 1 floor
// masses as N grows, and the peak drift with it). Record lengths: the first L seconds of
// one record.
#pragma once

#include "brb/frame/frame_builder.hpp"
#include "brb/model/frame_spec.hpp"
#include "brb/study/scaling_fit.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace brb::study {

struct ScalingStudyOptions {
  std::filesystem::path frame_file; ///< frame whose first storey the generated frames copy
  std::filesystem::path record;     ///< ground motion (AT2 or CSV)
  double record_scale = 1.0;
  std::vector<int> brace_counts = {1, 4, 16, 64};
  double brace_series_length = 5.0; ///< s of record for the brace series
  std::vector<double> record_lengths = {2.5, 5.0, 10.0, 20.0};
  int length_series_braces = 4; ///< braces of the frame of the record-length series
  frame::BraceOverride braces = frame::BraceOverride::truss;
  int repeats = 3;
};

struct ScalingPoint {
  std::string series; ///< "braces" or "record_length"
  int braces = 0;
  double record_length = 0.0; ///< s
  int steps = 0;
  int equations = 0;    ///< DOF of the model (6 per node before constraints)
  double seconds = 0.0; ///< CPU, median of the repeats
  double peak_drift = 0.0;
};

struct ScalingStudyResult {
  std::vector<ScalingPoint> brace_series;
  std::vector<ScalingPoint> length_series;
  PowerLawFit brace_fit;  ///< time against number of braces
  PowerLawFit length_fit; ///< time against record length
};

/// The generated one-storey frame with `braces` bays (see above) from `base`'s first storey.
/// Throws std::invalid_argument when `base` has no brb element between a support and a
/// node above it, or braces < 1.
model::FrameSpec generated_frame(const model::FrameSpec& base, int braces);

/// Runs both series (minutes with the defaults).
ScalingStudyResult run_scaling_study(const ScalingStudyOptions& options);

/// Writes DIR/SCALING.md and DIR/scaling.csv atomically.
void write_scaling_report(const std::filesystem::path& directory,
                          const ScalingStudyOptions& options, const ScalingStudyResult& result);

} // namespace brb::study
