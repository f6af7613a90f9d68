// Central finite differences for checking consistent tangents.
#pragma once

#include <Eigen/Core>

namespace brb::test {

/// Jacobian of f: R^n -> R^m at x by central differences with step h per component.
template <class Function, class Vector>
Eigen::MatrixXd central_difference_jacobian(const Function& f, const Vector& x, double step) {
  const auto f0 = f(x);
  Eigen::MatrixXd jacobian(f0.size(), x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    Vector forward = x;
    Vector backward = x;
    forward[j] += step;
    backward[j] -= step;
    jacobian.col(j) = (f(forward) - f(backward)) / (2.0 * step);
  }
  return jacobian;
}

/// ||A - B|| / ||B|| (Frobenius).
inline double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

} // namespace brb::test
