// Geometry of a bilinear quadrilateral surface face, for the node-to-surface contact
// (node_to_surface_contact.hpp): position, tangents and outward normal at natural coordinates
// (xi, eta), and the closest point projection of a point on the face by Newton.
//
// Node a of the face sits at natural coordinates (xi_a, eta_a) = (-1,-1), (1,-1), (1,1),
// (-1,1): the nodes go counter-clockwise seen from outside the body the face bounds, so the
// right-hand normal t_xi x t_eta points out of that body.
//   x(xi, eta) = sum_a N_a x_a,  N_a = (1 + xi xi_a)(1 + eta eta_a) / 4
//   t_1 = dx/dxi, t_2 = dx/deta, x_12 = d2x/dxi deta = sum_a xi_a eta_a x_a / 4 (x_11 = x_22 = 0)
// Closest point (Wriggers, Computational Contact Mechanics, 2nd ed., sec. 4.1): the point
// x(xi) where (x_s - x(xi)) . t_alpha = 0; Newton with the Hessian of 1/2 |x_s - x(xi)|^2,
//   A_ab = t_a . t_b - (x_s - x) . x_ab.
#pragma once

#include <Eigen/Core>

#include <array>

namespace brb::solid {

/// Natural coordinates of the 4 nodes of a face, in counter-clockwise order.
inline constexpr std::array<std::array<int, 2>, 4> kQuadNaturalCoordinates{
    {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};

/// Shape functions N_a and their derivatives at one natural point.
struct QuadShape {
  Eigen::Vector4d value;                ///< N_a
  Eigen::Matrix<double, 4, 2> gradient; ///< dN_a / d(xi, eta)

  static QuadShape at(const Eigen::Vector2d& natural);
};

/// The face's geometry at one natural point of its current nodes (3 x 4, counter-clockwise).
struct QuadPoint {
  Eigen::Vector2d natural = Eigen::Vector2d::Zero();
  QuadShape shape;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, 2> tangents = Eigen::Matrix<double, 3, 2>::Zero(); ///< t_1, t_2
  Eigen::Vector3d twist = Eigen::Vector3d::Zero();  ///< x_12 (zero on a parallelogram)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero(); ///< unit outward normal
  double area_density = 0.0;                        ///< |t_1 x t_2| (dA = it dxi deta)

  static QuadPoint at(const Eigen::Matrix<double, 3, 4>& nodes, const Eigen::Vector2d& natural);
};

struct QuadProjection {
  bool converged = false;
  bool inside = false; ///< |xi|, |eta| <= 1 + tolerance
  double excess = 0.0; ///< max(|xi|, |eta|) - 1: how far beyond the face's edges (natural)
  QuadPoint point;
  double gap = 0.0; ///< (x_s - x) . n, positive outside the face's body
};

/// Closest point of `point` on the (unbounded extension of the) bilinear face by Newton from
/// the centre; at most 25 iterations, converged when the correction is below 1e-12 in natural
/// coordinates. inside: the point lies on the face itself, |xi|, |eta| <= 1 + 1e-9 (the
/// tolerance lets a node on the common edge of two faces project on both).
QuadProjection project_on_quad(const Eigen::Matrix<double, 3, 4>& nodes,
                               const Eigen::Vector3d& point);

/// Area of the face by 2 x 2 Gauss points (exact for a flat face; the bilinear map's area
/// density is a polynomial of degree <= 2 per direction only on flat faces).
double quad_area(const Eigen::Matrix<double, 3, 4>& nodes);

} // namespace brb::solid
