#include "brb/validation/reversals.hpp"

#include <cmath>
#include <stdexcept>

namespace brb::validation {

std::vector<std::size_t> find_reversals(std::span<const double> deformation, double threshold) {
  if (!std::isfinite(threshold) || threshold < 0.0)
    throw std::invalid_argument("find_reversals: the threshold must be a finite number >= 0");
  std::vector<std::size_t> reversals;
  if (deformation.empty())
    return reversals;

  // direction: +1 rising, -1 falling, 0 not yet known: the history has not left the band
  // of +-threshold about its first point (the start is not a turning point). `extreme` is
  // the running maximum (rising) or minimum (falling) since the last reversal.
  int direction = 0;
  std::size_t extreme = 0;
  std::size_t lowest = 0, highest = 0; // running extremes while the direction is unknown
  for (std::size_t i = 1; i < deformation.size(); ++i) {
    const double value = deformation[i];
    if (direction == 0) {
      if (value > deformation[highest])
        highest = i;
      if (value < deformation[lowest])
        lowest = i;
      if (value - deformation[0] > threshold) {
        direction = +1;
        extreme = highest;
      } else if (deformation[0] - value > threshold) {
        direction = -1;
        extreme = lowest;
      }
      continue;
    }
    if (direction > 0) {
      if (value >= deformation[extreme]) {
        extreme = i;
      } else if (deformation[extreme] - value > threshold) {
        reversals.push_back(extreme);
        direction = -1;
        extreme = i;
      }
    } else {
      if (value <= deformation[extreme]) {
        extreme = i;
      } else if (value - deformation[extreme] > threshold) {
        reversals.push_back(extreme);
        direction = +1;
        extreme = i;
      }
    }
  }
  return reversals;
}

} // namespace brb::validation
