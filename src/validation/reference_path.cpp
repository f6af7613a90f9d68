#include "brb/validation/reference_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace brb::validation {

std::vector<double> deformation_travel(std::span<const double> deformation) {
  std::vector<double> travel(deformation.size(), 0.0);
  for (std::size_t i = 1; i < deformation.size(); ++i)
    travel[i] = travel[i - 1] + std::abs(deformation[i] - deformation[i - 1]);
  return travel;
}

PathMatch match_along_path(std::span<const double> model_deformation,
                           std::span<const double> reference_deformation,
                           std::span<const double> reference_force) {
  if (reference_deformation.size() != reference_force.size())
    throw std::invalid_argument("match_along_path: the reference's deformation and force "
                                "differ in length");
  if (reference_deformation.size() < 2)
    throw std::invalid_argument("match_along_path: the reference needs at least 2 points");
  const std::vector<double> model_travel = deformation_travel(model_deformation);
  const std::vector<double> reference_travel = deformation_travel(reference_deformation);

  PathMatch match;
  match.force.assign(model_deformation.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < model_deformation.size(); ++k) {
    const double s = model_travel[k];
    if (s > reference_travel.back())
      break;
    // The first reference point at or beyond s: an exact hit takes that point's values (the
    // first of a run of points at the same travel, e.g. a hold), else the segment before it.
    const auto found = std::lower_bound(reference_travel.begin(), reference_travel.end(), s);
    const auto j = static_cast<std::size_t>(found - reference_travel.begin());
    double force = reference_force[j];
    double deformation = reference_deformation[j];
    if (*found != s) {
      const double weight =
          (s - reference_travel[j - 1]) / (reference_travel[j] - reference_travel[j - 1]);
      force = reference_force[j - 1] + weight * (reference_force[j] - reference_force[j - 1]);
      deformation = reference_deformation[j - 1] +
                    weight * (reference_deformation[j] - reference_deformation[j - 1]);
    }
    match.force[k] = force;
    match.matched = k + 1;
    const double difference = std::abs(deformation - model_deformation[k]);
    if (difference > match.largest_deformation_difference) {
      match.largest_deformation_difference = difference;
      match.largest_difference_point = k;
    }
  }
  return match;
}

} // namespace brb::validation
