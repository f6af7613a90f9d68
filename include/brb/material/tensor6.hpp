// Symmetric second-order tensors as 6-vectors, and isotropic elasticity.
//
// Public interfaces use Voigt order (11, 22, 33, 23, 13, 12) with engineering shear
// strains (gamma_ij = 2 eps_ij) and plain shear stresses, as every FE code does.
// Inside 3D laws we use Mandel notation (shear components times sqrt(2)), in which the
// double contraction A:B is the Euclidean dot product and fourth-order tensors are
// ordinary 6x6 matrices; the conversions below are the only place the factors live.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace brb::material {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

inline constexpr double kSqrt2 = 1.41421356237309504880;
inline constexpr double kSqrtTwoThirds = 0.81649658092772603273;   // sqrt(2/3)
inline constexpr double kSqrtThreeHalves = 1.22474487139158904910; // sqrt(3/2)

/// Mandel vector of the identity tensor.
inline Vector6 identity6() {
  Vector6 one = Vector6::Zero();
  one.head<3>().setOnes();
  return one;
}

/// Deviatoric projector P = I - (1/3) 1 (x) 1 in Mandel form.
inline Matrix6 deviatoric_projector() {
  const Vector6 one = identity6();
  return Matrix6::Identity() - one * one.transpose() / 3.0;
}

inline double trace6(const Vector6& t) {
  return t[0] + t[1] + t[2];
}

inline Vector6 deviator(const Vector6& t) {
  Vector6 dev = t;
  dev.head<3>().array() -= trace6(t) / 3.0;
  return dev;
}

/// Voigt strain (engineering shear) -> Mandel strain.
inline Vector6 mandel_from_voigt_strain(const Vector6& voigt) {
  Vector6 mandel = voigt;
  mandel.tail<3>() /= kSqrt2;
  return mandel;
}

/// Voigt stress -> Mandel stress.
inline Vector6 mandel_from_voigt_stress(const Vector6& voigt) {
  Vector6 mandel = voigt;
  mandel.tail<3>() *= kSqrt2;
  return mandel;
}

/// Mandel stress -> Voigt stress.
inline Vector6 voigt_stress_from_mandel(const Vector6& mandel) {
  Vector6 voigt = mandel;
  voigt.tail<3>() /= kSqrt2;
  return voigt;
}

/// Mandel strain -> Voigt strain (engineering shear).
inline Vector6 voigt_strain_from_mandel(const Vector6& mandel) {
  Vector6 voigt = mandel;
  voigt.tail<3>() *= kSqrt2;
  return voigt;
}

/// d(sigma_voigt)/d(eps_voigt) from d(sigma_mandel)/d(eps_mandel):
/// sigma_V,i = sigma_M,i / s_i and eps_M,j = eps_V,j / s_j with s = 1 or sqrt(2).
inline Matrix6 voigt_tangent_from_mandel(const Matrix6& mandel) {
  Matrix6 voigt = mandel;
  voigt.bottomRows<3>() /= kSqrt2;
  voigt.rightCols<3>() /= kSqrt2;
  return voigt;
}

/// Isotropic linear elasticity from Young's modulus E and Poisson's ratio nu.
struct IsotropicElasticity {
  double youngs_modulus = 0.0;
  double poissons_ratio = 0.0;

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poissons_ratio)); }
  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poissons_ratio)); }

  /// E0 in Mandel form: 3K (1/3 1(x)1) + 2G P.
  Matrix6 stiffness() const {
    const Vector6 one = identity6();
    return bulk_modulus() * one * one.transpose() + 2.0 * shear_modulus() * deviatoric_projector();
  }

  /// E0^-1 applied to a Mandel stress: dev/(2G) + tr/(9K) 1.
  Vector6 compliance_times(const Vector6& stress) const {
    Vector6 strain = deviator(stress) / (2.0 * shear_modulus());
    strain.head<3>().array() += trace6(stress) / (9.0 * bulk_modulus());
    return strain;
  }

  /// Energy norm sqrt(sigma : E0^-1 : sigma) of a Mandel stress.
  double energy_norm(const Vector6& stress) const {
    return std::sqrt(stress.dot(compliance_times(stress)));
  }
};

} // namespace brb::material
