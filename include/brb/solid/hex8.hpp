// The 8-node hexahedron of the 3D continuum model: total Lagrangian, one-point (centre)
// integration with an assumed-strain, objective hourglass stiffness.
//
// Formulation and why.
// - Total Lagrangian with the Green-Lagrange strain E = (F^T F - I) / 2 and the second
//   Piola-Kirchhoff stress S = law(E): the small-strain laws of material/ see a strain that
//   is exactly invariant under rigid rotations, so large rotations (buckling) are exact and
//   no stress-rate (Jaumann, Hughes-Winget) update is needed; the tangent is exact
//   (Bathe, Finite Element Procedures, sec. 6.2.3; Belytschko, Liu, Moran, Nonlinear Finite
//   Elements, Box 4.2). For the elastic law this is the St Venant-Kirchhoff material.
// - One-point integration with the Flanagan-Belytschko mean gradients
//   b_a = (1/V) int dN_a/dX dV (Flanagan & Belytschko 1981, IJNME 17), so F at the centre is
//   the exact volume average of F: a linear displacement field gives a uniform F and zero
//   hourglass forces on any distorted mesh (the patch test), and full integration's shear
//   locking (the cantilever with 4 elements through the depth) does not arise.
// - Hourglass modes (h1 = eta zeta, h2 = zeta xi, h3 = xi eta, h4 = xi eta zeta) are measured
//   by the Flanagan-Belytschko vectors gamma_alpha = (h_alpha - sum_j (h_alpha . X_j) b_j) / 8,
//   orthogonal to every linear field of X. Their stiffness follows the assumed-strain idea of
//   Belytschko & Bindeman (1993, CMAME 105, "ASQBI"): in the element's axes (m = 1..3,
//   half-lengths a_m), a mode alpha of the displacement component m whose h depends on xi_m
//   is a bending mode and carries only its normal-strain energy with Young's modulus
//   (incompatible modes relax the transverse strains: the linear part of a beam's bending
//   stress is E kappa y), k = E V <(dh/dxi_m)^2> / a_m^2; a mode whose h does not depend on
//   xi_m only shears, k = G V sum_{n != m} <(dh/dxi_n)^2> / a_n^2. <.> is the mean over the
//   element: 1/3 for h = xi_j xi_k, 1/9 for xi eta zeta. For a rectangular element in pure
//   bending the element energy is then exact.
// - Objectivity of the hourglass part: the hourglass displacements are pulled back by the
//   centre deformation gradient, q_alpha = F^-1 g_alpha with g_alpha = sum_a gamma_alpha,a x_a,
//   and the stored energy is U_hg = 1/2 sum_alpha q_alpha . K_alpha q_alpha: zero for every
//   linear field (rigid rotations included), invariant under superposed rotations, and its
//   force and tangent are its exact derivatives (so the tangent is consistent and the
//   hourglass energy is conservative). The moduli are the elastic ones also when the law
//   yields (a stiffness-form control): the linear part of the strain inside an element stays
//   elastic, which overstiffens bending after yield unless the mesh has several elements
//   through the thickness.
#pragma once

#include "brb/material/tensor6.hpp"

#include <Eigen/Core>

#include <array>

namespace brb::solid {

using NodeMatrix = Eigen::Matrix<double, 3, 8>;      ///< one column per node
using ElementMatrix = Eigen::Matrix<double, 24, 24>; ///< node-major: 3 a + i

/// Reference (undeformed) geometry of one element, computed once.
struct Hex8Reference {
  double volume = 0.0;                   ///< V (mm^3)
  NodeMatrix gradients;                  ///< b_a = (1/V) int dN_a/dX dV (1/mm), column a
  Eigen::Matrix<double, 4, 8> hourglass; ///< gamma_alpha,a (rows alpha)
  Eigen::Matrix3d axes;         ///< element axes (columns, orthonormal): polar factor of dX/dxi
  Eigen::Vector3d half_lengths; ///< a_m = |dX/dxi_m| at the centre (mm)
  double min_jacobian = 0.0;    ///< smallest det(dX/dxi) at the 2x2x2 Gauss points
};

/// Reference geometry from the 8 node coordinates (order of hex_mesh.hpp). Throws
/// std::invalid_argument when the Jacobian is not positive at a Gauss point (an inverted or
/// degenerate element).
Hex8Reference hex8_reference(const NodeMatrix& coordinates);

/// Hourglass stiffness of the element, one 3x3 matrix per mode alpha in reference axes:
/// K_alpha = sum_m k_m,alpha e_m e_m^T with the assumed-strain moduli of the header.
using HourglassStiffness = std::array<Eigen::Matrix3d, 4>;
HourglassStiffness hex8_hourglass_stiffness(const Hex8Reference& reference, double youngs_modulus,
                                            double shear_modulus);

/// Centre displacement gradient H = sum_a u_a (x) b_a (F = I + H) from the nodal
/// displacements: the strain is formed from H itself (F - I would round H to 1e-16 absolute,
/// a stress noise of E x 1e-16 that stalls Newton at about 1e-9 N on a bar).
Eigen::Matrix3d hex8_displacement_gradient(const Hex8Reference& reference,
                                           const NodeMatrix& displacement);

/// Green-Lagrange strain E = (H + H^T + H^T H) / 2 of the displacement gradient H = F - I,
/// Voigt (11, 22, 33, 23, 13, 12) with engineering shears. (From H, not as (F^T F - I) / 2,
/// whose subtraction of 1 would cost the strain its relative precision: 1e-12 at 1e-4.)
material::Vector6 green_lagrange_strain(const Eigen::Matrix3d& displacement_gradient);

/// Adds the centre-point internal forces V P b_a (P = F S) to `force` and, when `tangent`
/// is not null, V [B_a^T C B_b + (b_a . S b_b) I] (material + geometric) to it.
/// stress: S in Voigt; material_tangent: dS/dE in Voigt (engineering shear strains).
void add_hex8_centre_response(const Hex8Reference& reference, const Eigen::Matrix3d& F,
                              const material::Vector6& stress,
                              const material::Matrix6& material_tangent, NodeMatrix& force,
                              ElementMatrix* tangent);

/// Hourglass displacements and the generalised hourglass stresses conjugate to them, one
/// column per mode alpha, in reference axes.
using HourglassMatrix = Eigen::Matrix<double, 3, 4>;

/// The objective hourglass displacements q_alpha = F^-1 g_alpha, g_alpha = sum_a
/// gamma_alpha,a u_a, from the centre's F^-1 (F_inverse; the caller's, as the forces need it
/// too). g_alpha is formed from the nodal displacements (sum_a gamma_alpha,a X_a = 0 exactly),
/// so that its round-off does not grow with the element's distance from the origin.
HourglassMatrix hex8_hourglass_displacements(const Hex8Reference& reference,
                                             const Eigen::Matrix3d& F_inverse,
                                             const NodeMatrix& displacement);

/// Adds the nodal forces of the hourglass stresses P (column alpha conjugate to q_alpha, so
/// the power is sum_alpha P_alpha . dq_alpha/dt): f_b = sum_alpha c_alpha,b F^-T P_alpha with
/// c_alpha,b = gamma_alpha,b - b_b . q_alpha, at the centre's F^-1 (F_inverse). When
/// `tangent` is not null, adds d f / d x for
/// stresses whose derivative is dP_alpha / dq_alpha = stress_stiffness[alpha] (K_alpha in the
/// elastic stiffness form, where P = K q; SolidModel's tangent form passes its loading or
/// unloading stiffness).
void add_hex8_hourglass_forces(const Hex8Reference& reference,
                               const HourglassStiffness& stress_stiffness,
                               const Eigen::Matrix3d& F_inverse, const HourglassMatrix& q,
                               const HourglassMatrix& P, NodeMatrix& force, ElementMatrix* tangent);

/// The elastic stiffness form: P_alpha = K_alpha q_alpha. Adds the hourglass forces (and
/// their exact tangent when `tangent` is not null) and returns the stored hourglass energy
/// U_hg = 1/2 sum_alpha q_alpha . K_alpha q_alpha of the element.
double add_hex8_hourglass_response(const Hex8Reference& reference,
                                   const HourglassStiffness& stiffness, const Eigen::Matrix3d& F,
                                   const NodeMatrix& displacement, NodeMatrix& force,
                                   ElementMatrix* tangent);

/// Upper bound of the element's highest circular frequency for the one-point element with
/// lumped mass rho V / 8 per node (Flanagan & Belytschko 1981, eq. 4.4):
///   w_max^2 <= 8 (lambda + 2 mu) / rho * sum_a |b_a|^2,
/// so the central-difference step 2 / w_max is stable for the element.
double hex8_max_frequency(const Hex8Reference& reference, double dilatational_modulus,
                          double density);

} // namespace brb::solid
