#include "brb/material/steel_uniaxial.hpp"

#include "steel_return_map.hpp"

#include <cmath>

namespace brb::material {

SteelUniaxial::SteelUniaxial(const SteelParameters& parameters, double characteristic_length,
                             LongElementRule rule)
    : parameters_(parameters) {
  parameters_.validate();
  terms_ = HardeningTerms::from(parameters_);
  isotropic_ = {parameters_.yield_stress, parameters_.isotropic_hardening,
                parameters_.voce_saturation, parameters_.voce_rate};
  softening_ = steel_softening(parameters_, characteristic_length, rule);
}

SteelUniaxial::Response SteelUniaxial::evaluate(const State& committed, double strain) const {
  Response response;
  State& state = response.state;
  state = committed;
  const double youngs = parameters_.youngs_modulus;

  // Uniaxial images of the 3D quantities: back-stress a = 3/2 alpha_11, plastic strain
  // eps_p = eps_p,11, and sqrt(3/2)|xi| = |sigma - sum a|; the 3D equation with 3G -> E.
  const double trial_stress = youngs * (strain - committed.plastic_strain);
  double relative_trial = trial_stress;
  for (int k = 0; k < terms_.count; ++k)
    relative_trial -= committed.back_stress[k];
  const double trial_function =
      std::abs(relative_trial) - isotropic_.radius(committed.equivalent_plastic_strain);

  const bool elastic = !(trial_function > kYieldTolerance * parameters_.yield_stress);
  double effective_stress = trial_stress;
  double effective_tangent = youngs;
  double plastic_increment = 0.0;
  if (!elastic) {
    const auto beta_of = [&](double increment) {
      double beta = trial_stress;
      for (int k = 0; k < terms_.count; ++k) {
        beta -= committed.back_stress[k] / (1.0 + terms_.recall[k] * increment);
      }
      return beta;
    };
    const auto beta_rate_of = [&](double increment) {
      double rate = 0.0;
      for (int k = 0; k < terms_.count; ++k) {
        const double factor = 1.0 + terms_.recall[k] * increment;
        rate += terms_.recall[k] * committed.back_stress[k] / (factor * factor);
      }
      return rate;
    };
    const auto consistency = [&](double increment) {
      const double beta = beta_of(increment);
      const double direction = beta >= 0.0 ? 1.0 : -1.0;
      const HardeningResistance resistance = hardening_resistance(
          terms_, isotropic_, youngs, committed.equivalent_plastic_strain, increment);
      ReturnMapEquation equation;
      equation.residual = std::abs(beta) - resistance.value;
      equation.slope = direction * beta_rate_of(increment) - resistance.slope;
      return equation;
    };
    plastic_increment = solve_return_map(consistency, trial_function, youngs);

    const double direction = beta_of(plastic_increment) >= 0.0 ? 1.0 : -1.0;
    for (int k = 0; k < terms_.count; ++k) {
      state.back_stress[k] =
          (committed.back_stress[k] + terms_.modulus[k] * plastic_increment * direction) /
          (1.0 + terms_.recall[k] * plastic_increment);
    }
    state.plastic_strain = committed.plastic_strain + direction * plastic_increment;
    state.equivalent_plastic_strain = committed.equivalent_plastic_strain + plastic_increment;
    effective_stress = trial_stress - youngs * direction * plastic_increment;
    // d(dp) = E sign d(eps) / D, D = -f'(dp): d sigma_bar = E (1 - E / D) d eps.
    const double resistance_slope = -consistency(plastic_increment).slope;
    effective_tangent = youngs * (1.0 - youngs / resistance_slope);
  }

  // Damage: tau = |sigma_bar| / sqrt(E) is the uniaxial energy norm.
  bool damage_grows = false;
  double damage_term = 0.0;
  double integrity = 1.0 - committed.damage;
  if (softening_) {
    const double committed_threshold = committed.damage_threshold > 0.0
                                           ? committed.damage_threshold
                                           : softening_->initial_threshold();
    if (committed.damage_threshold > 0.0)
      integrity = softening_->integrity(committed_threshold);
    const double energy_norm = std::abs(effective_stress) / std::sqrt(youngs);
    state.damage_threshold = committed_threshold;
    if (energy_norm > committed_threshold * (1.0 + kDamageTolerance)) {
      damage_grows = true;
      state.damage_threshold = energy_norm;
      // 1 - d evaluated directly (exponential_softening.hpp), never increasing
      integrity = std::min(integrity, softening_->integrity(energy_norm));
      state.damage = std::max(committed.damage, 1.0 - integrity);
      // G'(r) sigma_bar d tau with d tau = sign(sigma_bar) / sqrt(E) C_bar d eps
      damage_term = softening_->damage_slope(energy_norm) * std::abs(effective_stress) /
                    std::sqrt(youngs) * effective_tangent;
    }
  }
  response.stress = integrity * effective_stress;
  response.tangent = integrity * effective_tangent - damage_term;
  if (elastic && !damage_grows && elastic_fast_path_) {
    // Elastic fast path: no plastic increment and no damage growth leave the history as
    // committed (but for the threshold's first value, set above) and book zero dissipation
    // (record_step_dissipation would add 0 to each total), so the energy bookkeeping is
    // skipped.
    return response;
  }

  double recall_energy = 0.0;
  double hardening_energy = isotropic_.stored_energy(state.equivalent_plastic_strain);
  for (int k = 0; k < terms_.count; ++k) {
    const double alpha_squared = state.back_stress[k] * state.back_stress[k];
    recall_energy += terms_.recall[k] / terms_.modulus[k] * alpha_squared;
    hardening_energy += 0.5 / terms_.modulus[k] * alpha_squared;
  }
  record_step_dissipation(
      state, committed, softening_,
      integrity * plastic_increment * (parameters_.yield_stress + recall_energy), hardening_energy);
  return response;
}

double SteelUniaxial::free_energy(const State& state, double strain) const {
  const double elastic_strain = strain - state.plastic_strain;
  double energy = 0.5 * parameters_.youngs_modulus * elastic_strain * elastic_strain;
  energy += isotropic_.stored_energy(state.equivalent_plastic_strain);
  for (int k = 0; k < terms_.count; ++k) {
    energy += 0.5 / terms_.modulus[k] * state.back_stress[k] * state.back_stress[k];
  }
  return (1.0 - state.damage) * energy;
}

} // namespace brb::material
