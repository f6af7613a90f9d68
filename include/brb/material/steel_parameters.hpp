// Parameters of the steel plasticity-damage law (BRB_SOURCE_FACTS section 2 and its
// Chaboche/Voce generalisation). Units: MPa, N/mm.
#pragma once

#include "brb/material/exponential_softening.hpp"

#include <optional>
#include <vector>

namespace brb::material {

/// One Armstrong-Frederick back-stress: d(alpha) = 2/3 C d(eps_p) - gamma alpha dp.
/// gamma = 0 is Prager's linear kinematic hardening with H_kin = C.
struct BackStressTerm {
  double modulus = 0.0; ///< C (MPa)
  double recall = 0.0;  ///< gamma (-)
};

/// Ductile damage (core fracture): onset at effective stress fu, fracture energy Gf.
struct SteelDamageParameters {
  double onset_stress = 0.0;    ///< fu (MPa), >= fy
  double fracture_energy = 0.0; ///< Gf (N/mm), > 0
};

struct SteelParameters {
  static constexpr int kMaxChabocheTerms = 4;

  double youngs_modulus = 0.0;          ///< E (MPa)
  double poissons_ratio = 0.3;          ///< nu (-)
  double yield_stress = 0.0;            ///< fy (MPa)
  double kinematic_hardening = 0.0;     ///< H_kin (MPa), Prager: eta_dot = 2/3 H_kin eps_p_dot
  double isotropic_hardening = 0.0;     ///< H_iso (MPa), linear in equivalent plastic strain
  std::vector<BackStressTerm> chaboche; ///< up to 4 nonlinear back-stresses
  double voce_saturation = 0.0;         ///< Q (MPa), isotropic Voce saturation
  double voce_rate = 0.0;               ///< b (-)
  std::optional<SteelDamageParameters> damage; ///< absent: no damage

  /// Throws ParameterError naming the user-facing key (E, nu, fy, H_kin, H_iso,
  /// chaboche[i].C, chaboche[i].gamma, voce.Q, voce.b, fu, Gf).
  void validate() const;

  /// Saturation (bounding) uniaxial stress under monotonic loading without linear terms:
  /// fy + sum C_k / gamma_k + Q (infinite when a linear term is present).
  double saturation_stress() const;
};

/// The steel law's back-stress terms in one list: Prager's linear term (gamma = 0) first,
/// then the Chaboche terms. At most 5.
struct HardeningTerms {
  static constexpr int kMax = SteelParameters::kMaxChabocheTerms + 1;
  int count = 0;
  double modulus[kMax] = {};
  double recall[kMax] = {};

  static HardeningTerms from(const SteelParameters& parameters);
};

/// Isotropic part: yield radius fy + H_iso p + Q (1 - exp(-b p)), its slope and its
/// stored energy (the integral of the hardening stress over p).
struct IsotropicHardening {
  double yield_stress = 0.0;
  double linear = 0.0;
  double saturation = 0.0;
  double rate = 0.0;

  struct Response {
    double radius = 0.0; ///< MPa
    double slope = 0.0;  ///< MPa
  };

  double radius(double p) const;
  /// radius(p) and its slope dR/dp, H_iso + Q b exp(-b p), from one exponential (the return
  /// map needs both at every iterate).
  Response response(double p) const;
  double stored_energy(double p) const;
};

/// The softening of a steel point with characteristic length lc (mm), or nothing when
/// the parameters have no damage.
std::optional<ExponentialSoftening> steel_softening(const SteelParameters& parameters,
                                                    double characteristic_length,
                                                    LongElementRule rule);

} // namespace brb::material
