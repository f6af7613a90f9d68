// Scalar consistency equation shared by the 3D and the uniaxial steel return maps.
//
// With backward-Euler Armstrong-Frederick back-stresses the consistency condition reduces
// to one equation in the plastic multiplier dp (equivalent plastic strain increment):
//   f(dp) = |beta(dp)|_eq - [E_el dp + sum_k C_k dp / (1 + gamma_k dp) + R(p_n + dp)] = 0,
// E_el = 3G in 3D (|.|_eq = sqrt(3/2) |.|) and E in 1D. Since |beta'|_eq <= sum C_k/(1+gamma dp)^2
// (each back-stress stays inside its saturation ball |alpha_k|_eq <= C_k / gamma_k),
// f' <= -E_el < 0: f is strictly decreasing with a unique root in [0, f(0) / E_el].
#pragma once

#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/material/steel_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace brb::material {

/// Trial yield function values below this fraction of fy count as elastic.
inline constexpr double kYieldTolerance = 1e-12;
/// Damage loads only when tau exceeds the threshold r by more than this fraction, so a
/// re-evaluation at a converged strain (tau = r up to round-off) is consistently unloading.
inline constexpr double kDamageTolerance = 1e-12;

struct ReturnMapEquation {
  double residual = 0.0; ///< f(dp)
  double slope = 0.0;    ///< f'(dp) < 0
};

/// What the relative stress must exceed, E_el dp + sum_k C_k dp / (1 + gamma_k dp) + R(p_n +
/// dp), and its derivative in dp; one exponential for both (IsotropicHardening::response).
struct HardeningResistance {
  double value = 0.0; ///< MPa
  double slope = 0.0; ///< MPa
};

inline HardeningResistance hardening_resistance(const HardeningTerms& terms,
                                                const IsotropicHardening& isotropic,
                                                double elastic_modulus, double committed_p,
                                                double increment) {
  const IsotropicHardening::Response radius = isotropic.response(committed_p + increment);
  HardeningResistance resistance{elastic_modulus * increment + radius.radius,
                                 elastic_modulus + radius.slope};
  for (int k = 0; k < terms.count; ++k) {
    const double factor = 1.0 + terms.recall[k] * increment;
    resistance.value += terms.modulus[k] * increment / factor;
    resistance.slope += terms.modulus[k] / (factor * factor);
  }
  return resistance;
}

/// Safeguarded Newton on the bracket [0, f(0)/E_el]; converges to round-off.
template <class Consistency>
double solve_return_map(const Consistency& consistency, double trial_function,
                        double elastic_modulus) {
  double lower = 0.0;
  double upper = trial_function / elastic_modulus;
  const double step_tolerance = 1e-15 * upper;
  double increment = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const ReturnMapEquation equation = consistency(increment);
    if (equation.residual == 0.0)
      break;
    if (equation.residual > 0.0) {
      lower = increment;
    } else {
      upper = increment;
    }
    double next = increment - equation.residual / equation.slope;
    if (!(next > lower && next < upper))
      next = 0.5 * (lower + upper);
    const double step = std::abs(next - increment);
    increment = next;
    if (step <= step_tolerance)
      break;
  }
  return increment;
}

/// Books one step's dissipation in `state.dissipated` (DissipatedEnergy), given the
/// step's plastic dissipation (1 - d) dp (fy + sum 3/2 gamma/C |alpha|^2) (>= 0 by the
/// backward-Euler identities) and the stored hardening energy psi_p at the end of the step.
/// Damage releases psi0 dG, integrated exactly over the threshold's growth (psi0 = r^2 / 2
/// on the loading branch, so large steps do not over-count), and psi_p dd.
template <class State>
void record_step_dissipation(State& state, const State& committed,
                             const std::optional<ExponentialSoftening>& softening,
                             double plastic_dissipation, double hardening_energy) {
  const double damage_increment = state.damage - committed.damage;
  const double released = damage_increment > 0.0
                              ? softening->released_energy(std::max(committed.damage_threshold,
                                                                    softening->initial_threshold()),
                                                           state.damage_threshold)
                              : 0.0;
  state.dissipated.plastic += plastic_dissipation;
  state.dissipated.softening += released;
  state.dissipated.total += plastic_dissipation + released + hardening_energy * damage_increment;
}

} // namespace brb::material
