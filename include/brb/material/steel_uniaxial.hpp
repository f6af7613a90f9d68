// SteelUniaxial: the closed-form uniaxial-stress evaluation of SteelDamagePlasticity3D
// (the fiber fast path). Under sigma_22 = sigma_33 = tau = 0 every tensor of the 3D law
// stays coaxial with diag(1, -1/2, -1/2), so the backward-Euler update of the 3D law
// reduces exactly to this scalar one; tests check the two agree to round-off.
#pragma once

#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/material/steel_parameters.hpp"

#include <optional>

namespace brb::material {

struct SteelStateUniaxial {
  double plastic_strain = 0.0;
  double back_stress[HardeningTerms::kMax] = {}; ///< uniaxial back-stresses (MPa)
  double equivalent_plastic_strain = 0.0;
  double damage_threshold = 0.0; ///< r (0 = not yet loaded: r0 applies)
  double damage = 0.0;
  DissipatedEnergy dissipated;
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, SteelStateUniaxial>
void state_fields(Archive& archive, Self& state) {
  static_assert(sizeof(SteelStateUniaxial) == (7 + HardeningTerms::kMax) * sizeof(double),
                "a new field of SteelStateUniaxial must be listed here");
  archive(state.plastic_strain, state.back_stress, state.equivalent_plastic_strain,
          state.damage_threshold, state.damage, state.dissipated);
}

class SteelUniaxial {
public:
  using State = SteelStateUniaxial;
  struct Response {
    double stress = 0.0;  ///< MPa
    double tangent = 0.0; ///< MPa
    State state;
  };

  SteelUniaxial(const SteelParameters& parameters, double characteristic_length,
                LongElementRule rule = LongElementRule::lower_strength);

  State initial_state() const { return State{}; }
  /// Elastic fast path (DESIGN.md section 10, on by default): below yield and below the
  /// damage threshold, evaluate() returns E (times the integrity) and the committed state
  /// without the energy bookkeeping of a plastic step, which would add exactly zero. Off:
  /// every evaluation takes the general path (the benchmark's reference); same numbers.
  void set_elastic_fast_path(bool enabled) { elastic_fast_path_ = enabled; }
  bool elastic_fast_path() const { return elastic_fast_path_; }
  Response evaluate(const State& committed, double strain) const;
  double free_energy(const State& state, double strain) const;
  /// Energy dissipated so far per unit volume (MPa).
  static double dissipated_energy(const State& state) { return state.dissipated.total; }

  const SteelParameters& parameters() const { return parameters_; }
  const std::optional<ExponentialSoftening>& softening() const { return softening_; }
  double stress_scale() const { return parameters_.yield_stress; }

private:
  SteelParameters parameters_;
  HardeningTerms terms_;
  IsotropicHardening isotropic_;
  std::optional<ExponentialSoftening> softening_;
  bool elastic_fast_path_ = true;
};

} // namespace brb::material
