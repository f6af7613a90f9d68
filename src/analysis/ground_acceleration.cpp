// The small pieces of transient_analysis.hpp shared by the implicit and explicit analyses:
// the ground acceleration's interpolation and the Rayleigh coefficients.
#include "brb/analysis/transient_analysis.hpp"

#include <cmath>
#include <stdexcept>

namespace brb::analysis {

double GroundAcceleration::at(double time) const {
  if (acceleration.empty() || time < 0.0)
    return 0.0;
  const double position = time / dt;
  const auto sample = static_cast<std::size_t>(std::floor(position));
  if (sample + 1 >= acceleration.size()) {
    // the last sample holds exactly at its time, zero after it
    return sample + 1 == acceleration.size() && position - static_cast<double>(sample) < 1e-9
               ? acceleration.back()
               : 0.0;
  }
  const double fraction = position - static_cast<double>(sample);
  return (1.0 - fraction) * acceleration[sample] + fraction * acceleration[sample + 1];
}

std::pair<double, double> rayleigh_coefficients(double w_i, double xi_i, double w_j, double xi_j) {
  if (!(w_i > 0.0) || !(w_j > 0.0) || w_i == w_j)
    throw std::invalid_argument("Rayleigh damping needs two distinct positive frequencies");
  // Chopra, Dynamics of Structures, eq. 11.4.9 solved for two ratios
  const double denominator = w_j * w_j - w_i * w_i;
  const double mass_factor = 2.0 * w_i * w_j * (xi_i * w_j - xi_j * w_i) / denominator;
  const double stiffness_factor = 2.0 * (xi_j * w_j - xi_i * w_i) / denominator;
  return {mass_factor, stiffness_factor};
}

} // namespace brb::analysis
