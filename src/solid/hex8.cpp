// Total Lagrangian one-point hexahedron with assumed-strain hourglass stiffness (see hex8.hpp).
#include "brb/solid/hex8.hpp"

#include "brb/solid/hex_mesh.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace brb::solid {

namespace {

/// Hourglass base vectors at the nodes (Flanagan-Belytschko): eta zeta, zeta xi, xi eta, xi eta
/// zeta.
Eigen::Matrix<double, 4, 8> hourglass_base() {
  Eigen::Matrix<double, 4, 8> h;
  for (int a = 0; a < 8; ++a) {
    const double xi = kNaturalCoordinates[a][0];
    const double eta = kNaturalCoordinates[a][1];
    const double zeta = kNaturalCoordinates[a][2];
    h(0, a) = eta * zeta;
    h(1, a) = zeta * xi;
    h(2, a) = xi * eta;
    h(3, a) = xi * eta * zeta;
  }
  return h;
}

/// dN_a/dxi_m of the trilinear shape functions at natural point p (rows m, columns a).
NodeMatrix natural_derivatives(const Eigen::Vector3d& p) {
  NodeMatrix dN;
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d s(kNaturalCoordinates[a][0], kNaturalCoordinates[a][1],
                            kNaturalCoordinates[a][2]);
    const Eigen::Vector3d factor = (Eigen::Vector3d::Ones() + s.cwiseProduct(p));
    dN(0, a) = 0.125 * s[0] * factor[1] * factor[2];
    dN(1, a) = 0.125 * s[1] * factor[0] * factor[2];
    dN(2, a) = 0.125 * s[2] * factor[0] * factor[1];
  }
  return dN;
}

/// Which hourglass base functions depend on natural coordinate m (h1 = eta zeta has no xi...).
constexpr bool depends_on(int alpha, int m) {
  return alpha == 3 || alpha != m;
}

/// Mean over the element of (dh_alpha / dxi_n)^2 when h_alpha depends on xi_n: the square of
/// one other coordinate (1/3) or of two (1/9).
constexpr double mean_square_derivative(int alpha) {
  return alpha == 3 ? 1.0 / 9.0 : 1.0 / 3.0;
}

} // namespace

Hex8Reference hex8_reference(const NodeMatrix& coordinates) {
  Hex8Reference reference;
  reference.gradients.setZero();
  reference.min_jacobian = std::numeric_limits<double>::infinity();
  // 2x2x2 Gauss: exact for V and for int dN_a/dX dV = int (dN/dxi) adj(J) dxi (polynomials
  // of degree <= 2 in each natural coordinate for the trilinear map)
  const double g = 1.0 / std::sqrt(3.0);
  for (int q = 0; q < 8; ++q) {
    const Eigen::Vector3d p(g * kNaturalCoordinates[q][0], g * kNaturalCoordinates[q][1],
                            g * kNaturalCoordinates[q][2]);
    const NodeMatrix dN = natural_derivatives(p);
    const Eigen::Matrix3d jacobian = coordinates * dN.transpose(); // dX_i / dxi_m
    const double det = jacobian.determinant();
    reference.min_jacobian = std::min(reference.min_jacobian, det);
    if (!(det > 0.0))
      throw std::invalid_argument("hexahedron: the Jacobian is not positive at a Gauss point "
                                  "(an inverted or degenerate element; det = " +
                                  std::to_string(det) + " mm^3)");
    reference.volume += det;
    // dN/dX = J^-T dN/dxi, times det J
    reference.gradients += jacobian.inverse().transpose() * dN * det;
  }
  reference.gradients /= reference.volume;

  // gamma_alpha = (h_alpha - sum_j (h_alpha . X_j) b_j) / 8
  const Eigen::Matrix<double, 4, 8> h = hourglass_base();
  reference.hourglass =
      0.125 * (h - (h * coordinates.transpose()) * reference.gradients); // (4x3)(3x8)

  // centre Jacobian dX/dxi = sum_a X_a (x) xi_a / 8: half-lengths and the element's axes
  const Eigen::Matrix3d centre =
      coordinates * natural_derivatives(Eigen::Vector3d::Zero()).transpose();
  for (int m = 0; m < 3; ++m)
    reference.half_lengths[m] = centre.col(m).norm();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(centre, Eigen::ComputeFullU | Eigen::ComputeFullV);
  reference.axes = svd.matrixU() * svd.matrixV().transpose();
  return reference;
}

HourglassStiffness hex8_hourglass_stiffness(const Hex8Reference& reference, double youngs_modulus,
                                            double shear_modulus) {
  HourglassStiffness stiffness;
  const Eigen::Vector3d& a = reference.half_lengths;
  for (int alpha = 0; alpha < 4; ++alpha) {
    stiffness[alpha].setZero();
    for (int m = 0; m < 3; ++m) {
      double k = 0.0;
      if (depends_on(alpha, m)) {
        // bending mode of component m: normal strain dh/dxi_m / a_m only
        k = youngs_modulus * mean_square_derivative(alpha) / (a[m] * a[m]);
      } else {
        // shear-only mode: the two shears dh/dxi_n / a_n
        for (int n = 0; n < 3; ++n) {
          if (n != m)
            k += shear_modulus * mean_square_derivative(alpha) / (a[n] * a[n]);
        }
      }
      const Eigen::Vector3d e = reference.axes.col(m);
      stiffness[alpha] += k * reference.volume * e * e.transpose();
    }
  }
  return stiffness;
}

Eigen::Matrix3d hex8_displacement_gradient(const Hex8Reference& reference,
                                           const NodeMatrix& displacement) {
  return displacement * reference.gradients.transpose();
}

material::Vector6 green_lagrange_strain(const Eigen::Matrix3d& H) {
  const Eigen::Matrix3d twice = H + H.transpose() + H.transpose() * H; // 2 E
  material::Vector6 strain;
  strain << 0.5 * twice(0, 0), 0.5 * twice(1, 1), 0.5 * twice(2, 2), twice(1, 2), twice(0, 2),
      twice(0, 1);
  return strain;
}

void add_hex8_centre_response(const Hex8Reference& reference, const Eigen::Matrix3d& F,
                              const material::Vector6& stress,
                              const material::Matrix6& material_tangent, NodeMatrix& force,
                              ElementMatrix* tangent) {
  Eigen::Matrix3d S;
  S << stress[0], stress[5], stress[4], stress[5], stress[1], stress[3], stress[4], stress[3],
      stress[2];
  const double V = reference.volume;
  const NodeMatrix& b = reference.gradients;
  // f_a = V F S b_a (first Piola-Kirchhoff stress P = F S)
  force.noalias() += V * (F * S) * b;
  if (tangent == nullptr)
    return;
  // B_a: dE(Voigt) / dx_a (6x3), rows 11, 22, 33, 23, 13, 12
  std::array<Eigen::Matrix<double, 6, 3>, 8> B;
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d ba = b.col(a);
    Eigen::Matrix<double, 6, 3>& Ba = B[a];
    Ba.row(0) = ba[0] * F.col(0).transpose();
    Ba.row(1) = ba[1] * F.col(1).transpose();
    Ba.row(2) = ba[2] * F.col(2).transpose();
    Ba.row(3) = ba[2] * F.col(1).transpose() + ba[1] * F.col(2).transpose();
    Ba.row(4) = ba[2] * F.col(0).transpose() + ba[0] * F.col(2).transpose();
    Ba.row(5) = ba[1] * F.col(0).transpose() + ba[0] * F.col(1).transpose();
  }
  const Eigen::Matrix<double, 3, 8> Sb = S * b;
  for (int a = 0; a < 8; ++a) {
    const Eigen::Matrix<double, 3, 6> BtC = B[a].transpose() * material_tangent;
    for (int c = 0; c < 8; ++c) {
      Eigen::Matrix3d block = BtC * B[c];
      block.diagonal().array() += b.col(a).dot(Sb.col(c));
      tangent->block<3, 3>(3 * a, 3 * c) += V * block;
    }
  }
}

HourglassMatrix hex8_hourglass_displacements(const Hex8Reference& reference,
                                             const Eigen::Matrix3d& F_inverse,
                                             const NodeMatrix& displacement) {
  const HourglassMatrix g = displacement * reference.hourglass.transpose();
  return F_inverse * g;
}

void add_hex8_hourglass_forces(const Hex8Reference& reference,
                               const HourglassStiffness& stress_stiffness,
                               const Eigen::Matrix3d& F_inverse, const HourglassMatrix& q,
                               const HourglassMatrix& P, NodeMatrix& force,
                               ElementMatrix* tangent) {
  const Eigen::Matrix3d F_inverse_t = F_inverse.transpose();
  const NodeMatrix& b = reference.gradients;
  const HourglassMatrix p = F_inverse_t * P; // p_alpha = F^-T P_alpha
  // dq_alpha = F^-1 sum_b c_alpha,b dx_b with c_alpha,b = gamma_alpha,b - b_b . q_alpha
  const Eigen::Matrix<double, 4, 8> c = reference.hourglass - q.transpose() * b;
  force.noalias() += p * c; // f_b = sum_alpha c_alpha,b p_alpha
  if (tangent == nullptr)
    return;
  // d f_b / d x_c = c_b c_c F^-T (dP/dq) F^-1  (the stresses' own change)
  //               - c_c p (F^-T b_b)^T         (c_alpha,b moves with q_alpha)
  //               - c_b (F^-T b_c) p^T         (F^-T moves with F)
  const NodeMatrix Fb = F_inverse_t * b; // F^-T b_b
  for (int alpha = 0; alpha < 4; ++alpha) {
    const Eigen::Vector3d pa = p.col(alpha);
    const Eigen::Matrix3d KF = F_inverse_t * stress_stiffness[alpha] * F_inverse;
    for (int bb = 0; bb < 8; ++bb) {
      for (int cc = 0; cc < 8; ++cc) {
        const double cb = c(alpha, bb);
        const double ccoef = c(alpha, cc);
        tangent->block<3, 3>(3 * bb, 3 * cc) += cb * ccoef * KF -
                                                ccoef * pa * Fb.col(bb).transpose() -
                                                cb * Fb.col(cc) * pa.transpose();
      }
    }
  }
}

double add_hex8_hourglass_response(const Hex8Reference& reference,
                                   const HourglassStiffness& stiffness, const Eigen::Matrix3d& F,
                                   const NodeMatrix& displacement, NodeMatrix& force,
                                   ElementMatrix* tangent) {
  const Eigen::Matrix3d F_inverse = F.inverse();
  const HourglassMatrix q = hex8_hourglass_displacements(reference, F_inverse, displacement);
  HourglassMatrix P;
  double energy = 0.0;
  for (int alpha = 0; alpha < 4; ++alpha) {
    P.col(alpha) = stiffness[alpha] * q.col(alpha);
    energy += 0.5 * q.col(alpha).dot(P.col(alpha));
  }
  add_hex8_hourglass_forces(reference, stiffness, F_inverse, q, P, force, tangent);
  return energy;
}

double hex8_max_frequency(const Hex8Reference& reference, double dilatational_modulus,
                          double density) {
  return std::sqrt(8.0 * dilatational_modulus / density * reference.gradients.squaredNorm());
}

} // namespace brb::solid
