#include "brb/element/rotation.hpp"

#include <cmath>

namespace brb::element {
namespace {

// Below this angle the trigonometric ratios are replaced by their Taylor series, which
// are exact to round-off there (next terms ~ t^8).
constexpr double kSmallAngle = 1e-2;

/// c(t) = 1/t^2 - (1 + cos t)/(2 t sin t) = 1/12 + t^2/720 + t^4/30240 + t^6/1209600 + ...
double jacobian_coefficient(double t) {
  if (t < kSmallAngle) {
    const double t2 = t * t;
    return 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0 + t2 * t2 * t2 / 1209600.0;
  }
  return 1.0 / (t * t) - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
}

/// c'(t) / t, from c'(t) = -2/t^3 + csc^2(t/2) / (4 t) + cot(t/2) / (2 t^2).
double jacobian_coefficient_rate(double t) {
  if (t < kSmallAngle) {
    const double t2 = t * t;
    return 1.0 / 360.0 + t2 / 7560.0 + t2 * t2 / 201600.0;
  }
  const double half = 0.5 * t;
  const double cosecant = 1.0 / std::sin(half);
  const double cotangent = std::cos(half) * cosecant;
  const double rate =
      -2.0 / (t * t * t) + cosecant * cosecant / (4.0 * t) + cotangent / (2.0 * t * t);
  return rate / t;
}

} // namespace

Matrix3 skew(const Vector3& v) {
  Matrix3 s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

Matrix3 rotation_from_vector(const Vector3& theta) {
  const double t = theta.norm();
  const Matrix3 k = skew(theta);
  double a, b; // sin t / t, (1 - cos t) / t^2
  if (t < kSmallAngle) {
    const double t2 = t * t;
    a = 1.0 - t2 / 6.0 + t2 * t2 / 120.0;
    b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
  } else {
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / (t * t);
  }
  return Matrix3::Identity() + a * k + b * k * k;
}

Vector3 vector_from_rotation(const Matrix3& r) {
  // Shepperd: take the largest of (w, x, y, z)^2 to avoid cancellation.
  const double trace = r.trace();
  double w, x, y, z;
  if (trace >= r(0, 0) && trace >= r(1, 1) && trace >= r(2, 2)) {
    w = 0.5 * std::sqrt(1.0 + trace);
    x = (r(2, 1) - r(1, 2)) / (4.0 * w);
    y = (r(0, 2) - r(2, 0)) / (4.0 * w);
    z = (r(1, 0) - r(0, 1)) / (4.0 * w);
  } else if (r(0, 0) >= r(1, 1) && r(0, 0) >= r(2, 2)) {
    x = 0.5 * std::sqrt(1.0 + 2.0 * r(0, 0) - trace);
    w = (r(2, 1) - r(1, 2)) / (4.0 * x);
    y = (r(0, 1) + r(1, 0)) / (4.0 * x);
    z = (r(0, 2) + r(2, 0)) / (4.0 * x);
  } else if (r(1, 1) >= r(2, 2)) {
    y = 0.5 * std::sqrt(1.0 + 2.0 * r(1, 1) - trace);
    w = (r(0, 2) - r(2, 0)) / (4.0 * y);
    x = (r(0, 1) + r(1, 0)) / (4.0 * y);
    z = (r(1, 2) + r(2, 1)) / (4.0 * y);
  } else {
    z = 0.5 * std::sqrt(1.0 + 2.0 * r(2, 2) - trace);
    w = (r(1, 0) - r(0, 1)) / (4.0 * z);
    x = (r(0, 2) + r(2, 0)) / (4.0 * z);
    y = (r(1, 2) + r(2, 1)) / (4.0 * z);
  }
  if (w < 0.0) { // same rotation, angle in [0, pi]
    w = -w;
    x = -x;
    y = -y;
    z = -z;
  }
  const Vector3 axis_part(x, y, z);
  const double sine_half = axis_part.norm();
  if (sine_half < 1e-12)
    return 2.0 * axis_part; // 2 asin(s) / s -> 2
  const double angle = 2.0 * std::atan2(sine_half, w);
  return angle / sine_half * axis_part;
}

Matrix3 inverse_left_jacobian(const Vector3& theta) {
  const Matrix3 k = skew(theta);
  return Matrix3::Identity() - 0.5 * k + jacobian_coefficient(theta.norm()) * k * k;
}

Matrix3 inverse_left_jacobian_transpose_derivative(const Vector3& theta, const Vector3& moment) {
  // g = J^-T m = m + 1/2 theta x m + c(t) theta x (theta x m),
  // theta x (theta x m) = theta (theta . m) - m (theta . theta).
  const double t = theta.norm();
  const Vector3 double_cross = theta * theta.dot(moment) - moment * theta.squaredNorm();
  const Matrix3 double_cross_rate = theta.dot(moment) * Matrix3::Identity() +
                                    theta * moment.transpose() - 2.0 * moment * theta.transpose();
  return -0.5 * skew(moment) + jacobian_coefficient(t) * double_cross_rate +
         jacobian_coefficient_rate(t) * double_cross * theta.transpose();
}

} // namespace brb::element
