// SteelDamagePlasticity3D: von Mises plasticity in effective-stress space with mixed
// (Prager + Armstrong-Frederick/Chaboche) kinematic and (linear + Voce) isotropic
// hardening, weakly coupled with scalar damage driven by the effective-stress energy
// norm (BRB_SOURCE_FACTS section 2). Backward Euler; exact consistent tangent.
//
// The law is a value: parameters in, no mutable members. `evaluate(committed, strain)`
// returns stress, tangent and the trial state; the caller decides whether to commit it.
#pragma once

#include "brb/io/state_archive.hpp"
#include "brb/material/steel_parameters.hpp"
#include "brb/material/tensor6.hpp"

#include <array>
#include <optional>

namespace brb::material {

/// Energy bookkeeping of a material point, per unit volume (MPa = N mm / mm^3).
struct DissipatedEnergy {
  double plastic = 0.0;   ///< (1 - d) x effective plastic dissipation
  double softening = 0.0; ///< integral of psi0 dd: tends to Gf / lc when fully damaged
  double total = 0.0;     ///< plastic + softening + hardening energy released by damage
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, DissipatedEnergy>
void state_fields(Archive& archive, Self& energy) {
  static_assert(sizeof(DissipatedEnergy) == 3 * sizeof(double),
                "a new field of DissipatedEnergy must be listed here");
  archive(energy.plastic, energy.softening, energy.total);
}

struct SteelState3D {
  Vector6 plastic_strain = Vector6::Zero();                ///< Mandel
  std::array<Vector6, HardeningTerms::kMax> back_stress{}; ///< Mandel, one per term
  double equivalent_plastic_strain = 0.0;                  ///< p
  double damage_threshold = 0.0;                           ///< r (0 = not yet loaded: r0 applies)
  double damage = 0.0;                                     ///< d in [0, 1)
  DissipatedEnergy dissipated;

  SteelState3D() {
    for (auto& alpha : back_stress)
      alpha.setZero();
  }
};

class SteelDamagePlasticity3D {
public:
  using State = SteelState3D;
  struct Response {
    Vector6 stress;            ///< Voigt, MPa
    Matrix6 tangent;           ///< d stress / d strain (Voigt, engineering shear), non-symmetric
    State state;               ///< trial state to commit if the step is accepted
    Vector6 effective_stress;  ///< sigma_bar = sigma / (1 - d) (Voigt)
    Matrix6 effective_tangent; ///< d sigma_bar / d strain (Voigt)
  };

  /// lc: characteristic length of the point (mm); used only when damage is on.
  SteelDamagePlasticity3D(const SteelParameters& parameters, double characteristic_length,
                          LongElementRule rule = LongElementRule::lower_strength);

  State initial_state() const { return State{}; }
  /// strain: total small strain, Voigt with engineering shears.
  Response evaluate(const State& committed, const Vector6& strain) const;

  /// Free energy (1 - d)(psi0(eps - eps_p) + psi_p) per unit volume.
  double free_energy(const State& state, const Vector6& strain) const;

  const SteelParameters& parameters() const { return parameters_; }
  const std::optional<ExponentialSoftening>& softening() const { return softening_; }
  /// A stress magnitude for relative tolerances (fy).
  double stress_scale() const { return parameters_.yield_stress; }
  double youngs_modulus() const { return parameters_.youngs_modulus; }

private:
  SteelParameters parameters_;
  IsotropicElasticity elasticity_;
  HardeningTerms terms_;
  IsotropicHardening isotropic_;
  std::optional<ExponentialSoftening> softening_;
};

} // namespace brb::material
