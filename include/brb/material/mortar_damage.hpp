// MortarDamage: isotropic scalar damage with exponential softening for mortar / grout
// (BRB_SOURCE_FACTS section 3): sigma = (1 - d) E0 : eps, no plasticity,
// tau = (theta + (1 - theta)/n) sqrt(sigma0 : E0^-1 : sigma0), n = fc / ft,
// theta = sum <sigma0_i> / sum |sigma0_i| over principal effective stresses,
// r0 = ft / sqrt(E), d = G(r) (see exponential_softening.hpp).
// Damage therefore starts at ft in uniaxial tension and at fc in uniaxial compression.
#pragma once

#include "brb/io/state_archive.hpp"
#include "brb/material/exponential_softening.hpp"
#include "brb/material/tensor6.hpp"

namespace brb::material {

struct MortarParameters {
  double youngs_modulus = 0.0;       ///< E (MPa)
  double poissons_ratio = 0.2;       ///< nu (-)
  double compressive_strength = 0.0; ///< fc (MPa), > 0, >= ft
  double tensile_strength = 0.0;     ///< ft (MPa), > 0
  double fracture_energy = 0.0;      ///< Gf (N/mm), > 0

  /// Throws ParameterError naming the key (E, nu, fc, ft, Gf).
  void validate() const;
};

struct MortarState {
  double damage_threshold = 0.0; ///< r (0 = not yet loaded: r0 applies)
  double damage = 0.0;
  double dissipated_energy = 0.0; ///< integral of psi0 dd per unit volume (MPa)
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, MortarState>
void state_fields(Archive& archive, Self& state) {
  static_assert(sizeof(MortarState) == 3 * sizeof(double),
                "a new field of MortarState must be listed here");
  archive(state.damage_threshold, state.damage, state.dissipated_energy);
}

/// 3D form. Strain and stress in Voigt order with engineering shear strains.
class MortarDamage3D {
public:
  using State = MortarState;
  struct Response {
    Vector6 stress;
    Matrix6 tangent; ///< non-symmetric on damage loading
    State state;
    Vector6 effective_stress;  ///< sigma0 = E0 : eps (Voigt)
    Matrix6 effective_tangent; ///< E0 (Voigt)
  };

  MortarDamage3D(const MortarParameters& parameters, double characteristic_length,
                 LongElementRule rule = LongElementRule::lower_strength);

  State initial_state() const { return State{}; }
  Response evaluate(const State& committed, const Vector6& strain) const;
  double free_energy(const State& state, const Vector6& strain) const;
  double stress_scale() const { return parameters_.tensile_strength; }
  /// The state's residual strength as a fraction of its onset stress (f_t in tension, f_c in
  /// compression): ExponentialSoftening::residual_strength of its threshold.
  double residual_strength(const State& state) const {
    return softening_.residual_strength(state.damage_threshold);
  }
  const MortarParameters& parameters() const { return parameters_; }
  const ExponentialSoftening& softening() const { return softening_; }

private:
  MortarParameters parameters_;
  IsotropicElasticity elasticity_;
  ExponentialSoftening softening_;
};

/// Closed-form uniaxial collapse of MortarDamage3D (theta = 1 in tension, 0 in compression).
class MortarUniaxial {
public:
  using State = MortarState;
  struct Response {
    double stress = 0.0;
    double tangent = 0.0;
    State state;
  };

  MortarUniaxial(const MortarParameters& parameters, double characteristic_length,
                 LongElementRule rule = LongElementRule::lower_strength);

  State initial_state() const { return State{}; }
  Response evaluate(const State& committed, double strain) const;
  double free_energy(const State& state, double strain) const;
  /// Energy dissipated so far per unit volume (MPa).
  static double dissipated_energy(const State& state) { return state.dissipated_energy; }
  double stress_scale() const { return parameters_.tensile_strength; }
  /// The state's residual strength as a fraction of its onset stress (f_t in tension, f_c in
  /// compression): ExponentialSoftening::residual_strength of its threshold.
  double residual_strength(const State& state) const {
    return softening_.residual_strength(state.damage_threshold);
  }
  const MortarParameters& parameters() const { return parameters_; }
  const ExponentialSoftening& softening() const { return softening_; }

private:
  MortarParameters parameters_;
  ExponentialSoftening softening_;
};

} // namespace brb::material
