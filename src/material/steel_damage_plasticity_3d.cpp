#include "brb/material/steel_damage_plasticity_3d.hpp"

#include "steel_return_map.hpp"

#include <cmath>

namespace brb::material {

SteelDamagePlasticity3D::SteelDamagePlasticity3D(const SteelParameters& parameters,
                                                 double characteristic_length, LongElementRule rule)
    : parameters_(parameters) {
  parameters_.validate();
  elasticity_ = {parameters_.youngs_modulus, parameters_.poissons_ratio};
  terms_ = HardeningTerms::from(parameters_);
  isotropic_ = {parameters_.yield_stress, parameters_.isotropic_hardening,
                parameters_.voce_saturation, parameters_.voce_rate};
  softening_ = steel_softening(parameters_, characteristic_length, rule);
}

SteelDamagePlasticity3D::Response SteelDamagePlasticity3D::evaluate(const State& committed,
                                                                    const Vector6& strain) const {
  Response response;
  State& state = response.state;
  state = committed;

  const double shear = elasticity_.shear_modulus();
  const double bulk = elasticity_.bulk_modulus();
  const Vector6 one = identity6();
  const Vector6 total_strain = mandel_from_voigt_strain(strain);
  const double volumetric_strain = trace6(total_strain); // plastic flow is isochoric

  // Elastic predictor in effective-stress space.
  const Vector6 deviatoric_trial = 2.0 * shear * deviator(total_strain - committed.plastic_strain);
  Vector6 relative_trial = deviatoric_trial;
  for (int k = 0; k < terms_.count; ++k)
    relative_trial -= committed.back_stress[k];
  const double yield_radius = isotropic_.radius(committed.equivalent_plastic_strain);
  const double trial_function = kSqrtThreeHalves * relative_trial.norm() - yield_radius;

  Vector6 effective_stress;
  Matrix6 effective_tangent;
  double plastic_increment = 0.0;
  if (trial_function <= kYieldTolerance * parameters_.yield_stress) {
    effective_stress = bulk * volumetric_strain * one + deviatoric_trial;
    effective_tangent = elasticity_.stiffness();
  } else {
    // Backward-Euler return with Armstrong-Frederick back-stresses:
    //   alpha_k = (alpha_k^n + sqrt(2/3) C_k dp n) / (1 + gamma_k dp),
    // so s - sum alpha_k is parallel to beta(dp) = s_trial - sum alpha_k^n / (1 + gamma_k dp)
    // and the consistency condition is one scalar equation in dp (see steel_return_map.hpp).
    const auto beta_of = [&](double increment) {
      Vector6 beta = deviatoric_trial;
      for (int k = 0; k < terms_.count; ++k) {
        beta -= committed.back_stress[k] / (1.0 + terms_.recall[k] * increment);
      }
      return beta;
    };
    const auto beta_rate_of = [&](double increment) {
      Vector6 rate = Vector6::Zero();
      for (int k = 0; k < terms_.count; ++k) {
        const double factor = 1.0 + terms_.recall[k] * increment;
        rate += terms_.recall[k] * committed.back_stress[k] / (factor * factor);
      }
      return rate;
    };
    const auto consistency = [&](double increment) {
      const Vector6 beta = beta_of(increment);
      const double beta_norm = beta.norm();
      const HardeningResistance resistance = hardening_resistance(
          terms_, isotropic_, 3.0 * shear, committed.equivalent_plastic_strain, increment);
      ReturnMapEquation equation;
      equation.residual = kSqrtThreeHalves * beta_norm - resistance.value;
      equation.slope =
          kSqrtThreeHalves * beta.dot(beta_rate_of(increment)) / beta_norm - resistance.slope;
      return equation;
    };
    plastic_increment = solve_return_map(consistency, trial_function, 3.0 * shear);

    const Vector6 beta = beta_of(plastic_increment);
    const double beta_norm = beta.norm();
    const Vector6 flow = beta / beta_norm; // unit normal n (Mandel)
    for (int k = 0; k < terms_.count; ++k) {
      state.back_stress[k] = (committed.back_stress[k] +
                              kSqrtTwoThirds * terms_.modulus[k] * plastic_increment * flow) /
                             (1.0 + terms_.recall[k] * plastic_increment);
    }
    state.plastic_strain = committed.plastic_strain + kSqrtThreeHalves * plastic_increment * flow;
    state.equivalent_plastic_strain = committed.equivalent_plastic_strain + plastic_increment;
    const double sqrt6_shear = 2.0 * kSqrtThreeHalves * shear;
    effective_stress =
        bulk * volumetric_strain * one + deviatoric_trial - sqrt6_shear * plastic_increment * flow;

    // Consistent tangent: differentiate s = s_tr - sqrt(6) G dp n with n = beta/|beta|,
    // d(dp) = g . d(eps), g = sqrt(6) G n / D, D = -d(consistency)/d(dp).
    const double resistance_slope = -consistency(plastic_increment).slope;
    const Vector6 increment_gradient = sqrt6_shear / resistance_slope * flow;
    const Vector6 beta_rate = beta_rate_of(plastic_increment);
    const Vector6 beta_rate_normal_free = beta_rate - flow.dot(beta_rate) * flow;
    const Matrix6 deviatoric = deviatoric_projector();
    effective_tangent =
        bulk * one * one.transpose() + 2.0 * shear * deviatoric -
        sqrt6_shear * (flow * increment_gradient.transpose() +
                       plastic_increment / beta_norm *
                           (2.0 * shear * (deviatoric - flow * flow.transpose()) +
                            beta_rate_normal_free * increment_gradient.transpose()));
  }

  // Damage on the effective-stress energy norm tau = sqrt(sigma_bar : E0^-1 : sigma_bar).
  const Vector6 compliant_strain = elasticity_.compliance_times(effective_stress);
  const double elastic_energy = 0.5 * effective_stress.dot(compliant_strain); // psi0
  bool damage_loading = false;
  double damage_slope = 0.0;
  double integrity = 1.0 - committed.damage;
  if (softening_) {
    const double committed_threshold = committed.damage_threshold > 0.0
                                           ? committed.damage_threshold
                                           : softening_->initial_threshold();
    if (committed.damage_threshold > 0.0)
      integrity = softening_->integrity(committed_threshold);
    const double energy_norm = std::sqrt(2.0 * elastic_energy);
    state.damage_threshold = committed_threshold;
    if (energy_norm > committed_threshold * (1.0 + kDamageTolerance)) {
      damage_loading = true;
      state.damage_threshold = energy_norm;
      // 1 - d evaluated directly (exponential_softening.hpp), never increasing
      integrity = std::min(integrity, softening_->integrity(energy_norm));
      state.damage = std::max(committed.damage, 1.0 - integrity);
      damage_slope = softening_->damage_slope(energy_norm);
    }
  }
  Matrix6 tangent = integrity * effective_tangent;
  if (damage_loading) {
    // d sigma = (1-d) C_bar d eps - G'(r) sigma_bar (x) d tau, d tau = (E0^-1 sigma_bar) . C_bar d
    // eps / tau
    const double energy_norm = state.damage_threshold;
    tangent -= damage_slope / energy_norm * effective_stress *
               (compliant_strain.transpose() * effective_tangent);
  }
  response.stress = voigt_stress_from_mandel(integrity * effective_stress);
  response.tangent = voigt_tangent_from_mandel(tangent);
  response.effective_stress = voigt_stress_from_mandel(effective_stress);
  response.effective_tangent = voigt_tangent_from_mandel(effective_tangent);

  // Dissipation of the step (>= 0 term by term, see DissipatedEnergy).
  double recall_energy = 0.0;
  double hardening_energy = isotropic_.stored_energy(state.equivalent_plastic_strain);
  for (int k = 0; k < terms_.count; ++k) {
    const double alpha_squared = state.back_stress[k].squaredNorm();
    recall_energy += 1.5 * terms_.recall[k] / terms_.modulus[k] * alpha_squared;
    hardening_energy += 0.75 / terms_.modulus[k] * alpha_squared;
  }
  record_step_dissipation(
      state, committed, softening_,
      integrity * plastic_increment * (parameters_.yield_stress + recall_energy), hardening_energy);
  return response;
}

double SteelDamagePlasticity3D::free_energy(const State& state, const Vector6& strain) const {
  const Vector6 elastic_strain = mandel_from_voigt_strain(strain) - state.plastic_strain;
  double energy = 0.5 * elastic_strain.dot(elasticity_.stiffness() * elastic_strain);
  energy += isotropic_.stored_energy(state.equivalent_plastic_strain);
  for (int k = 0; k < terms_.count; ++k) {
    energy += 0.75 / terms_.modulus[k] * state.back_stress[k].squaredNorm();
  }
  return (1.0 - state.damage) * energy;
}

} // namespace brb::material
