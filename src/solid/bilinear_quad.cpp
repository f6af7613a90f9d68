// Geometry of a bilinear quadrilateral face (see bilinear_quad.hpp).
#include "brb/solid/bilinear_quad.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>

namespace brb::solid {

QuadShape QuadShape::at(const Eigen::Vector2d& natural) {
  QuadShape shape;
  for (int a = 0; a < 4; ++a) {
    const double xa = kQuadNaturalCoordinates[a][0];
    const double ea = kQuadNaturalCoordinates[a][1];
    const double along_xi = 1.0 + natural.x() * xa;
    const double along_eta = 1.0 + natural.y() * ea;
    shape.value[a] = 0.25 * along_xi * along_eta;
    shape.gradient(a, 0) = 0.25 * xa * along_eta;
    shape.gradient(a, 1) = 0.25 * ea * along_xi;
  }
  return shape;
}

QuadPoint QuadPoint::at(const Eigen::Matrix<double, 3, 4>& nodes, const Eigen::Vector2d& natural) {
  QuadPoint point;
  point.natural = natural;
  point.shape = QuadShape::at(natural);
  point.position = nodes * point.shape.value;
  point.tangents = nodes * point.shape.gradient;
  point.twist.setZero();
  for (int a = 0; a < 4; ++a)
    point.twist +=
        0.25 * kQuadNaturalCoordinates[a][0] * kQuadNaturalCoordinates[a][1] * nodes.col(a);
  const Eigen::Vector3d cross = point.tangents.col(0).cross(point.tangents.col(1));
  point.area_density = cross.norm();
  point.normal = point.area_density > 0.0 ? Eigen::Vector3d(cross / point.area_density)
                                          : Eigen::Vector3d::Zero();
  return point;
}

QuadProjection project_on_quad(const Eigen::Matrix<double, 3, 4>& nodes,
                               const Eigen::Vector3d& point) {
  constexpr int kMaxIterations = 25;
  constexpr double kTolerance = 1e-12;
  constexpr double kInsideTolerance = 1e-9;
  QuadProjection projection;
  Eigen::Vector2d natural = Eigen::Vector2d::Zero();
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const QuadPoint here = QuadPoint::at(nodes, natural);
    const Eigen::Vector3d offset = point - here.position;
    const Eigen::Vector2d residual = here.tangents.transpose() * offset;
    Eigen::Matrix2d hessian = here.tangents.transpose() * here.tangents;
    const double twist_term = offset.dot(here.twist);
    hessian(0, 1) -= twist_term;
    hessian(1, 0) -= twist_term;
    if (!(hessian.determinant() > 0.0))
      return projection; // not a minimum: far from a strongly warped face
    const Eigen::Vector2d correction = hessian.inverse() * residual;
    natural += correction;
    if (!natural.allFinite() || natural.cwiseAbs().maxCoeff() > 1e3)
      return projection;
    if (correction.cwiseAbs().maxCoeff() < kTolerance) {
      projection.converged = true;
      break;
    }
  }
  if (!projection.converged)
    return projection;
  projection.point = QuadPoint::at(nodes, natural);
  projection.gap = (point - projection.point.position).dot(projection.point.normal);
  projection.excess = natural.cwiseAbs().maxCoeff() - 1.0;
  projection.inside = projection.excess <= kInsideTolerance;
  return projection;
}

double quad_area(const Eigen::Matrix<double, 3, 4>& nodes) {
  const double g = 1.0 / std::sqrt(3.0);
  double area = 0.0;
  for (const double xi : {-g, g})
    for (const double eta : {-g, g})
      area += QuadPoint::at(nodes, Eigen::Vector2d(xi, eta)).area_density;
  return area;
}

} // namespace brb::solid
