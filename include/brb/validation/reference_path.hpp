// Matching a reference force-deformation history that was not sampled at the protocol's
// points (a `brb solid` run, an external 3D solver's export) to the points the model is
// driven through, so that the record comparison (record_comparison.hpp) applies to it as to a
// laboratory record.
//
// Both histories follow the same deformation path (the protocol), each sampled its own way.
// The parameter along that path is the deformation travel s = sum |d(delta)| from the first
// point: it increases through reversals, where the deformation itself turns back, so a
// deformation value that the path passes several times (every cycle crosses 0) is found on
// the right excursion. At each model point the reference's force (and deformation) is
// interpolated linearly in s between the two reference points around it; where the two
// samplings coincide (a reference made from the same protocol) the interpolation returns the
// reference's own values exactly.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace brb::validation {

/// Deformation travel s_k = sum_{i<=k} |delta_i - delta_{i-1}| (s_0 = 0), mm.
std::vector<double> deformation_travel(std::span<const double> deformation);

struct PathMatch {
  /// Reference force at each model point (N); NaN beyond the reference's travel (a reference
  /// that stopped early is compared over the part both have).
  std::vector<double> force;
  /// Points that have a reference force (the first `matched`: travel only grows).
  std::size_t matched = 0;
  /// Largest |delta_reference(s) - delta_model(s)| over the matched points (mm) and where.
  double largest_deformation_difference = 0.0;
  std::size_t largest_difference_point = 0;
};

/// The reference (deformation, force: same length, at least 2 points) at the model's points
/// `model_deformation` (mm), by linear interpolation in the deformation travel. Throws
/// std::invalid_argument for series of different lengths or fewer than 2 reference points.
PathMatch match_along_path(std::span<const double> model_deformation,
                           std::span<const double> reference_deformation,
                           std::span<const double> reference_force);

} // namespace brb::validation
