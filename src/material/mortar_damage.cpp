// Mortar / grout: isotropic scalar damage with exponential softening
// (BRB_SOURCE_FACTS section 3, DESIGN.md section 3).
//
// Equations implemented (Mandel notation inside, Voigt at the interface):
//   (M1) sigma0 = E0 : eps                                         effective stress
//   (M2) nu0 = sqrt(sigma0 : E0^-1 : sigma0) = sqrt(sigma0 : eps)  energy norm
//   (M3) theta = sum <sigma0_i> / sum |sigma0_i|   (theta = 1 when sigma0 = 0)
//   (M4) tau = w(theta) nu0,  w = theta + (1 - theta) / n,  n = fc / ft
//   (M5) r = max(r_committed, tau), r_committed = r0 = ft / sqrt(E) before any loading
//   (M6) d = G(r) (exponential_softening.hpp), never decreasing; the integrity 1 - d is
//        evaluated directly as (r0 / r) exp(A (1 - r / r0)), not as 1 - G(r)
//   (M7) sigma = (1 - d) sigma0
//   (M8) on damage loading (tau > r_committed):
//          C = (1 - d) E0 - G'(r) sigma0 (x) dtau/deps
//        dtau/deps = w sigma0 / nu0 + (1 - 1/n) nu0 E0 : dtheta/dsigma0
//        dtheta/dsigma0 = sum_i dtheta/dsigma0_i  v_i (x) v_i
//        (a sum of functions of the eigenvalues: differentiable for repeated eigenvalues
//        too, except where a principal stress crosses zero, a kink of <.> and |.|)
//   (M9) dissipated energy += psi0 (d_new - d_old), psi0 = 1/2 sigma0 : eps at the new
//        strain; free energy = (1 - d) psi0.
#include "brb/material/mortar_damage.hpp"

#include "brb/material/parameter_error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace brb::material {
namespace {

std::string describe(const std::string& expectation, double given) {
  std::ostringstream message;
  message << expectation << ", got " << given;
  return message.str();
}

const MortarParameters& validated(const MortarParameters& parameters) {
  parameters.validate();
  return parameters;
}

/// Ratio n = fc / ft of (M4).
double strength_ratio(const MortarParameters& parameters) {
  return parameters.compressive_strength / parameters.tensile_strength;
}

/// r_committed of (M5): 0 in the state means "never loaded", i.e. r0.
double committed_threshold(const MortarState& committed, const ExponentialSoftening& softening) {
  return committed.damage_threshold > 0.0 ? committed.damage_threshold
                                          : softening.initial_threshold();
}

/// 1 - d of a state, from its threshold r (the history variable, d = G(r)).
double state_integrity(const MortarState& state, const ExponentialSoftening& softening) {
  return state.damage_threshold > 0.0 ? softening.integrity(state.damage_threshold)
                                      : 1.0 - state.damage;
}

/// The symmetric 3x3 tensor of a Mandel 6-vector (Voigt order 11, 22, 33, 23, 13, 12).
Eigen::Matrix3d tensor_from_mandel(const Vector6& mandel) {
  const double s23 = mandel[3] / kSqrt2;
  const double s13 = mandel[4] / kSqrt2;
  const double s12 = mandel[5] / kSqrt2;
  Eigen::Matrix3d tensor;
  tensor << mandel[0], s12, s13, //
      s12, mandel[1], s23,       //
      s13, s23, mandel[2];
  return tensor;
}

/// Principal decomposition of a Mandel stress. The iterative solver is used, not
/// computeDirect: the closed-form cubic loses half the digits at a double eigenvalue, and
/// a uniaxial stress state has one (0, 0), which shifted theta by ~1e-8 and broke the
/// round-off agreement of the condensed 3D law with the uniaxial law.
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal_decomposition(const Vector6& stress,
                                                                       int options) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor_from_mandel(stress), options);
}

/// Mandel 6-vector of the dyad v (x) v.
Vector6 mandel_dyad(const Eigen::Vector3d& v) {
  Vector6 dyad;
  dyad << v[0] * v[0], v[1] * v[1], v[2] * v[2], kSqrt2 * v[1] * v[2], kSqrt2 * v[0] * v[2],
      kSqrt2 * v[0] * v[1];
  return dyad;
}

/// theta of (M3) from the principal values.
double tension_fraction(const Eigen::Vector3d& principal) {
  const double positive_sum = principal.cwiseMax(0.0).sum();
  const double absolute_sum = principal.cwiseAbs().sum();
  return absolute_sum > 0.0 ? positive_sum / absolute_sum : 1.0;
}

/// theta (M3) and its gradient dtheta/dsigma0 (M8) in Mandel form.
/// With P = sum <s_i>, N = sum <-s_i>, theta = P / (P + N):
///   dtheta/ds_i = N / (P + N)^2 for s_i > 0,  P / (P + N)^2 for s_i < 0,
/// and 0 is taken at s_i = 0 (a kink: any value between the one-sided limits is a
/// subgradient).
struct TensionFraction {
  double value = 1.0;
  Vector6 gradient = Vector6::Zero();
};

TensionFraction tension_fraction_with_gradient(const Vector6& effective_stress) {
  const auto eigen = principal_decomposition(effective_stress, Eigen::ComputeEigenvectors);
  const Eigen::Vector3d& principal = eigen.eigenvalues();
  const double positive_sum = principal.cwiseMax(0.0).sum();
  const double negative_sum = (-principal).cwiseMax(0.0).sum();
  const double absolute_sum = positive_sum + negative_sum;
  TensionFraction result;
  if (!(absolute_sum > 0.0)) {
    return result; // sigma0 = 0: theta = 1 by convention, gradient 0
  }
  result.value = positive_sum / absolute_sum;
  const double inverse_square = 1.0 / (absolute_sum * absolute_sum);
  for (int i = 0; i < 3; ++i) {
    double slope = 0.0;
    if (principal[i] > 0.0) {
      slope = negative_sum * inverse_square;
    } else if (principal[i] < 0.0) {
      slope = positive_sum * inverse_square;
    }
    if (slope != 0.0) {
      result.gradient += slope * mandel_dyad(eigen.eigenvectors().col(i));
    }
  }
  return result;
}

/// Principal values only (the cheap path when no tangent correction is needed).
Eigen::Vector3d principal_values(const Vector6& effective_stress) {
  return principal_decomposition(effective_stress, Eigen::EigenvaluesOnly).eigenvalues();
}

/// w(theta) of (M4).
double norm_weight(double theta, double strength_ratio) {
  return theta + (1.0 - theta) / strength_ratio;
}

} // namespace

void MortarParameters::validate() const {
  if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0.0)) {
    throw ParameterError("E",
                         describe("Young's modulus E must be finite and > 0 MPa", youngs_modulus));
  }
  if (!(poissons_ratio > -1.0 && poissons_ratio < 0.5)) {
    throw ParameterError("nu",
                         describe("Poisson's ratio nu must satisfy -1 < nu < 0.5", poissons_ratio));
  }
  if (!(std::isfinite(tensile_strength) && tensile_strength > 0.0)) {
    throw ParameterError(
        "ft", describe("tensile strength ft must be finite and > 0 MPa", tensile_strength));
  }
  if (!(std::isfinite(compressive_strength) && compressive_strength > 0.0)) {
    throw ParameterError(
        "fc", describe("compressive strength fc must be finite and > 0 MPa", compressive_strength));
  }
  if (!(compressive_strength >= tensile_strength)) {
    std::ostringstream message;
    message << "compressive strength fc must be >= tensile strength ft = " << tensile_strength
            << " MPa, got " << compressive_strength;
    throw ParameterError("fc", message.str());
  }
  if (!(std::isfinite(fracture_energy) && fracture_energy > 0.0)) {
    throw ParameterError(
        "Gf", describe("fracture energy Gf must be finite and > 0 N/mm", fracture_energy));
  }
}

// ---------------------------------------------------------------------------------------
// 3D law

MortarDamage3D::MortarDamage3D(const MortarParameters& parameters, double characteristic_length,
                               LongElementRule rule)
    : parameters_(validated(parameters)), elasticity_{parameters.youngs_modulus,
                                                      parameters.poissons_ratio},
      softening_(ExponentialSoftening::from_fracture_energy(
          parameters.tensile_strength, parameters.youngs_modulus, parameters.fracture_energy,
          characteristic_length, rule)) {}

MortarDamage3D::Response MortarDamage3D::evaluate(const State& committed,
                                                  const Vector6& strain) const {
  const Matrix6 stiffness = elasticity_.stiffness();
  const Vector6 mandel_strain = mandel_from_voigt_strain(strain);
  const Vector6 effective_stress = stiffness * mandel_strain;                // (M1)
  const double energy_density = 0.5 * effective_stress.dot(mandel_strain);   // psi0
  const double energy_norm = std::sqrt(std::max(0.0, 2.0 * energy_density)); // (M2)
  const double threshold = committed_threshold(committed, softening_);
  const double n = strength_ratio(parameters_);

  Response response;
  response.state = committed;

  // Elastic fast path: w <= 1 (n >= 1), so nu0 <= r_committed implies tau <= r_committed
  // without any eigenvalue computation.
  const bool loading =
      energy_norm > threshold &&
      norm_weight(tension_fraction(principal_values(effective_stress)), n) * energy_norm >
          threshold; // (M4), (M5)

  if (!loading) {
    const double integrity = state_integrity(committed, softening_); // (M7), d unchanged
    response.stress = voigt_stress_from_mandel(integrity * effective_stress);
    response.tangent = voigt_tangent_from_mandel(integrity * stiffness);
    response.effective_stress = voigt_stress_from_mandel(effective_stress);
    response.effective_tangent = voigt_tangent_from_mandel(stiffness);
    return response;
  }

  // Damage loading: recompute theta together with its gradient (M8).
  const TensionFraction fraction = tension_fraction_with_gradient(effective_stress);
  const double weight = norm_weight(fraction.value, n);
  // tau (M4); the max only guards r against a round-off difference between the two
  // eigenvalue computations (M5).
  const double norm = std::max(threshold, weight * energy_norm);
  const double integrity =
      std::min(state_integrity(committed, softening_), softening_.integrity(norm)); // (M6)
  const double damage = std::max(committed.damage, 1.0 - integrity);

  // dtau/deps (Mandel) = w sigma0 / nu0 + (1 - 1/n) nu0 E0 : dtheta/dsigma0   (M8)
  const Vector6 norm_gradient = weight / energy_norm * effective_stress +
                                (1.0 - 1.0 / n) * energy_norm * (stiffness * fraction.gradient);
  const Matrix6 tangent = integrity * stiffness - softening_.damage_slope(norm) * effective_stress *
                                                      norm_gradient.transpose(); // (M8)

  response.stress = voigt_stress_from_mandel(integrity * effective_stress); // (M7)
  response.tangent = voigt_tangent_from_mandel(tangent);
  response.effective_stress = voigt_stress_from_mandel(effective_stress);
  response.effective_tangent = voigt_tangent_from_mandel(stiffness);
  response.state.damage_threshold = norm;
  response.state.damage = damage;
  // (M9) on the loading branch psi0 = tau^2 / (2 w^2): the released energy is the closed-form
  // integral of psi0 dG from the old to the new threshold, divided by w^2.
  response.state.dissipated_energy +=
      softening_.released_energy(threshold, norm) / (weight * weight);
  return response;
}

double MortarDamage3D::free_energy(const State& state, const Vector6& strain) const {
  const Vector6 mandel_strain = mandel_from_voigt_strain(strain);
  const double energy_density = 0.5 * mandel_strain.dot(elasticity_.stiffness() * mandel_strain);
  return state_integrity(state, softening_) * energy_density; // (M9)
}

// ---------------------------------------------------------------------------------------
// Uniaxial collapse: sigma0 = E eps, theta = 1 (tension) or 0 (compression), so (M4) gives
// tau = |sigma0| / sqrt(E) in tension and |sigma0| / (n sqrt(E)) in compression.

MortarUniaxial::MortarUniaxial(const MortarParameters& parameters, double characteristic_length,
                               LongElementRule rule)
    : parameters_(validated(parameters)),
      softening_(ExponentialSoftening::from_fracture_energy(
          parameters.tensile_strength, parameters.youngs_modulus, parameters.fracture_energy,
          characteristic_length, rule)) {}

MortarUniaxial::Response MortarUniaxial::evaluate(const State& committed, double strain) const {
  const double modulus = parameters_.youngs_modulus;
  const double effective_stress = modulus * strain;                              // (M1)
  const double weight = strain >= 0.0 ? 1.0 : 1.0 / strength_ratio(parameters_); // w(theta)
  const double root_modulus = std::sqrt(modulus);
  const double norm = weight * root_modulus * std::abs(strain); // tau (M2), (M4)
  const double threshold = committed_threshold(committed, softening_);

  Response response;
  response.state = committed;
  if (!(norm > threshold)) {
    const double integrity = state_integrity(committed, softening_);
    response.stress = integrity * effective_stress; // (M7)
    response.tangent = integrity * modulus;
    return response;
  }

  const double integrity =
      std::min(state_integrity(committed, softening_), softening_.integrity(norm)); // (M6)
  const double damage = std::max(committed.damage, 1.0 - integrity);
  // dtau/deps = w sqrt(E) sign(eps); theta is constant on each side of eps = 0.
  const double norm_slope = weight * root_modulus * (strain > 0.0 ? 1.0 : -1.0);
  response.stress = integrity * effective_stress; // (M7)
  response.tangent =
      integrity * modulus - softening_.damage_slope(norm) * effective_stress * norm_slope; // (M8)
  response.state.damage_threshold = norm;
  response.state.damage = damage;
  // (M9) on the loading branch psi0 = tau^2 / (2 w^2): the released energy is the closed-form
  // integral of psi0 dG from the old to the new threshold, divided by w^2.
  response.state.dissipated_energy +=
      softening_.released_energy(threshold, norm) / (weight * weight);
  return response;
}

double MortarUniaxial::free_energy(const State& state, double strain) const {
  return state_integrity(state, softening_) * 0.5 * parameters_.youngs_modulus * strain *
         strain; // (M9)
}

} // namespace brb::material
