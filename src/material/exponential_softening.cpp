#include "brb/material/exponential_softening.hpp"

#include "brb/material/parameter_error.hpp"

#include <sstream>

namespace brb::material {

ExponentialSoftening ExponentialSoftening::from_fracture_energy(double onset_stress,
                                                                double youngs_modulus,
                                                                double fracture_energy,
                                                                double characteristic_length,
                                                                LongElementRule rule) {
  if (!(fracture_energy > 0.0)) {
    throw ParameterError("Gf", "fracture energy Gf must be > 0 N/mm");
  }
  if (!(characteristic_length > 0.0)) {
    throw ParameterError("lc", "characteristic length lc must be > 0 mm");
  }
  ExponentialSoftening softening;
  softening.onset_stress_ = onset_stress;
  const double lc_max = max_characteristic_length(onset_stress, youngs_modulus, fracture_energy);
  if (characteristic_length >= lc_max) {
    if (rule == LongElementRule::reject) {
      std::ostringstream message;
      message << "characteristic length lc = " << characteristic_length
              << " mm is too long for the softening: exponential softening needs lc < 2 Gf E / "
                 "f^2 = "
              << lc_max << " mm (else the stress-strain curve snaps back)";
      throw ParameterError("lc", message.str());
    }
    // Fallback: keep the dissipated energy Gf/lc and lower the onset stress so that
    // Gf E / (lc f^2) = 1, i.e. A = 2 (a brittle but regular softening branch).
    softening.onset_stress_ = std::sqrt(fracture_energy * youngs_modulus / characteristic_length);
    softening.strength_lowered_ = true;
  }
  const double f = softening.onset_stress_;
  softening.initial_threshold_ = f / std::sqrt(youngs_modulus);
  softening.softening_parameter_ =
      1.0 / (fracture_energy * youngs_modulus / (characteristic_length * f * f) - 0.5);
  return softening;
}

} // namespace brb::material
