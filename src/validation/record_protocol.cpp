#include "brb/validation/record_protocol.hpp"

#include "brb/validation/reversals.hpp"

#include <cmath>
#include <stdexcept>

namespace brb::validation {
namespace {

/// Appends `target` (record point `index`) after the protocol's last point, with equally
/// spaced interpolated points in between when it is more than max_step away.
void append_point(RecordProtocol& protocol, double target, std::size_t index, double max_step) {
  const double from = protocol.deformation.back();
  const double distance = std::abs(target - from);
  // A relative slack of 1e-9 so that a distance of exactly n steps is not cut into n + 1.
  const auto pieces = static_cast<std::size_t>(std::ceil(distance / max_step * (1.0 - 1e-9)));
  for (std::size_t piece = 1; piece < pieces; ++piece) {
    const double fraction = static_cast<double>(piece) / static_cast<double>(pieces);
    protocol.deformation.push_back(from + fraction * (target - from));
    protocol.record_index.push_back(RecordProtocol::kNoRecordPoint);
  }
  protocol.deformation.push_back(target);
  protocol.record_index.push_back(index);
}

} // namespace

RecordProtocol extract_record_protocol(std::span<const double> deformation,
                                       const RecordProtocolOptions& options) {
  if (deformation.empty())
    throw std::invalid_argument("extract_record_protocol: empty deformation history");
  for (const double value : deformation) {
    if (!std::isfinite(value))
      throw std::invalid_argument("extract_record_protocol: non-finite deformation");
  }
  if (!(options.max_step > 0.0) || !std::isfinite(options.max_step))
    throw std::invalid_argument("extract_record_protocol: max_step must be > 0");

  // The record points that must be kept: reversals and the last point.
  std::vector<std::size_t> anchors = find_reversals(deformation, options.reversal_threshold);
  if (anchors.empty() || anchors.back() != deformation.size() - 1)
    anchors.push_back(deformation.size() - 1);

  RecordProtocol protocol;
  protocol.deformation.push_back(0.0);
  protocol.record_index.push_back(RecordProtocol::kNoRecordPoint);

  std::size_t next = 0; // first record point not yet considered
  for (const std::size_t anchor : anchors) {
    // Greedy thinning up to the anchor: skip ahead while the next record point stays within
    // max_step of the last kept point; keep the last one that does.
    while (next < anchor) {
      const double from = protocol.deformation.back();
      std::size_t candidate = next;
      if (std::abs(deformation[candidate] - from) > options.max_step) {
        append_point(protocol, deformation[candidate], candidate, options.max_step);
        next = candidate + 1;
        continue;
      }
      while (candidate + 1 < anchor &&
             std::abs(deformation[candidate + 1] - from) <= options.max_step) {
        ++candidate;
      }
      if (candidate + 1 == anchor && std::abs(deformation[anchor] - from) <= options.max_step) {
        next = anchor; // the anchor itself is within reach: the points before add nothing
        break;
      }
      append_point(protocol, deformation[candidate], candidate, options.max_step);
      next = candidate + 1;
    }
    append_point(protocol, deformation[anchor], anchor, options.max_step);
    if (anchor != deformation.size() - 1)
      protocol.reversal_points.push_back(protocol.size() - 1);
    next = anchor + 1;
  }
  return protocol;
}

} // namespace brb::validation
