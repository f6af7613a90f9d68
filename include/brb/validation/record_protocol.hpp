// The loading protocol that drives a brace model through a laboratory record (issue 4): the
// record's own deformation points, thinned. A record has tens of thousands of points, most
// of which add nothing for a displacement-controlled model (noise, tiny increments); the
// model needs every reversal (the loops' tips), and steps small enough for its Newton
// solver. Each kept point remembers its record index, so that the model's force at protocol
// point k is compared with the test's force at exactly that record point.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace brb::validation {

struct RecordProtocolOptions {
  /// mm, >= 0: a change of direction smaller than this is noise, not a reversal (see
  /// find_reversals). The specimens use 0.1 dy.
  double reversal_threshold = 0.0;
  /// mm, > 0: the largest step between two consecutive protocol points. The specimens use
  /// just under dy / 10, the default step of `brb cyclic`, so that the cyclic command adds no
  /// point of its own and model step k is protocol point k.
  double max_step = 0.0;
};

/// Protocol points: the first is 0.0 (the unloaded initial state), then record points in
/// order, plus equally spaced points where the record itself jumps by more than max_step.
struct RecordProtocol {
  static constexpr std::size_t kNoRecordPoint = std::numeric_limits<std::size_t>::max();

  std::vector<double> deformation; ///< mm
  /// One per point: index into the record arrays of the point it is, or kNoRecordPoint for
  /// the initial 0.0 and for points interpolated across a jump of the record (not compared).
  std::vector<std::size_t> record_index;
  /// Positions (into `deformation`) of the record's reversals.
  std::vector<std::size_t> reversal_points;

  std::size_t size() const { return deformation.size(); }
};

/// Thins the record deformation history `deformation` (mm) into a protocol:
/// - every reversal of the record (find_reversals with options.reversal_threshold) is kept,
///   at its exact record value, and so are the record's last point;
/// - between two kept record points, the next kept point is the last record point that is
///   still within max_step of the previous kept one (the points in between, including noise
///   wiggles below the threshold, add nothing to a displacement-driven model);
/// - where consecutive record points are farther apart than max_step (a jump of the record,
///   or the start from 0.0), equally spaced points are put in, marked kNoRecordPoint.
/// So consecutive protocol points are at most max_step apart (up to round-off).
/// Throws std::invalid_argument for an empty or non-finite history, a negative threshold or
/// a max_step that is not > 0.
RecordProtocol extract_record_protocol(std::span<const double> deformation,
                                       const RecordProtocolOptions& options);

} // namespace brb::validation
