#include "brb/material/steel_parameters.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace brb::material {
namespace {

std::string got(double value) {
  std::ostringstream text;
  text << " (got " << value << ")";
  return text.str();
}

void require(bool condition, const std::string& field, const std::string& expected, double value) {
  if (!condition)
    throw ParameterError(field, expected + got(value));
}

} // namespace

void SteelParameters::validate() const {
  require(std::isfinite(youngs_modulus) && youngs_modulus > 0.0, "E", "must be > 0 MPa",
          youngs_modulus);
  require(poissons_ratio > -1.0 && poissons_ratio < 0.5, "nu", "must lie in (-1, 0.5)",
          poissons_ratio);
  require(std::isfinite(yield_stress) && yield_stress > 0.0, "fy", "must be > 0 MPa", yield_stress);
  require(std::isfinite(kinematic_hardening) && kinematic_hardening >= 0.0, "H_kin",
          "must be >= 0 MPa", kinematic_hardening);
  require(std::isfinite(isotropic_hardening) && isotropic_hardening >= 0.0, "H_iso",
          "must be >= 0 MPa", isotropic_hardening);
  if (chaboche.size() > static_cast<std::size_t>(kMaxChabocheTerms)) {
    throw ParameterError("chaboche", "at most 4 back-stress terms are supported (got " +
                                         std::to_string(chaboche.size()) + ")");
  }
  for (std::size_t k = 0; k < chaboche.size(); ++k) {
    const std::string prefix = "chaboche[" + std::to_string(k) + "].";
    require(std::isfinite(chaboche[k].modulus) && chaboche[k].modulus > 0.0, prefix + "C",
            "must be > 0 MPa", chaboche[k].modulus);
    require(std::isfinite(chaboche[k].recall) && chaboche[k].recall >= 0.0, prefix + "gamma",
            "must be >= 0", chaboche[k].recall);
  }
  require(std::isfinite(voce_saturation) && voce_saturation >= 0.0, "voce.Q", "must be >= 0 MPa",
          voce_saturation);
  require(std::isfinite(voce_rate) && voce_rate >= 0.0, "voce.b", "must be >= 0", voce_rate);
  if (damage) {
    require(std::isfinite(damage->onset_stress) && damage->onset_stress >= yield_stress, "fu",
            "must be >= fy = " + std::to_string(yield_stress) + " MPa", damage->onset_stress);
    require(std::isfinite(damage->fracture_energy) && damage->fracture_energy > 0.0, "Gf",
            "must be > 0 N/mm", damage->fracture_energy);
  }
}

double SteelParameters::saturation_stress() const {
  if (kinematic_hardening > 0.0 || isotropic_hardening > 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  double stress = yield_stress + voce_saturation;
  for (const auto& term : chaboche) {
    if (term.recall == 0.0)
      return std::numeric_limits<double>::infinity();
    stress += term.modulus / term.recall;
  }
  return stress;
}

HardeningTerms HardeningTerms::from(const SteelParameters& parameters) {
  HardeningTerms terms;
  if (parameters.kinematic_hardening > 0.0) {
    terms.modulus[terms.count] = parameters.kinematic_hardening;
    terms.recall[terms.count] = 0.0;
    ++terms.count;
  }
  for (const auto& term : parameters.chaboche) {
    terms.modulus[terms.count] = term.modulus;
    terms.recall[terms.count] = term.recall;
    ++terms.count;
  }
  return terms;
}

double IsotropicHardening::radius(double p) const {
  return response(p).radius;
}

IsotropicHardening::Response IsotropicHardening::response(double p) const {
  const double decay = std::exp(-rate * p);
  return {yield_stress + linear * p + saturation * (1.0 - decay),
          linear + saturation * rate * decay};
}

double IsotropicHardening::stored_energy(double p) const {
  // integral_0^p (H p' + Q (1 - exp(-b p'))) dp'; -expm1 keeps it exact for small b p.
  double energy = 0.5 * linear * p * p;
  if (saturation > 0.0 && rate > 0.0) {
    energy += saturation * (p + std::expm1(-rate * p) / rate);
  }
  return energy;
}

std::optional<ExponentialSoftening> steel_softening(const SteelParameters& parameters,
                                                    double characteristic_length,
                                                    LongElementRule rule) {
  if (!parameters.damage)
    return std::nullopt;
  return ExponentialSoftening::from_fracture_energy(
      parameters.damage->onset_stress, parameters.youngs_modulus,
      parameters.damage->fracture_energy, characteristic_length, rule);
}

} // namespace brb::material
