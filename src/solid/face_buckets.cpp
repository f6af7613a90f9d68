// Buckets of master faces along the surface's longest axis (see face_buckets.hpp).
#include "brb/solid/face_buckets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace brb::solid {

void FaceBuckets::build(const Eigen::Matrix3Xd& positions, const std::vector<QuadFace>& faces,
                        double search_distance) {
  buckets_.clear();
  if (faces.empty())
    return;

  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  double longest_edge = 0.0;
  for (const QuadFace& face : faces)
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector3d x = positions.col(face[a]);
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
      longest_edge = std::max(longest_edge, (x - positions.col(face[(a + 1) % 4])).norm());
    }
  (high - low).maxCoeff(&axis_);

  double width = search_distance;
  std::vector<std::array<double, 2>> spans(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int node : faces[f]) {
      lo = std::min(lo, positions(axis_, node));
      hi = std::max(hi, positions(axis_, node));
    }
    spans[f] = {lo, hi};
    width = std::max(width, hi - lo);
  }
  // every face normal to the axis (a flat surface across it): one face's size as the width
  width_ = width > 0.0 ? width : std::max(longest_edge, 1.0);

  const double margin = 0.5 * width_ + search_distance;
  origin_ = low[axis_] - margin;
  const double covered = high[axis_] + margin - origin_;
  const int count = std::max(1, static_cast<int>(std::ceil(covered / width_)));
  buckets_.assign(static_cast<std::size_t>(count), {});
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int first = std::clamp(
        static_cast<int>(std::floor((spans[f][0] - margin - origin_) / width_)), 0, count - 1);
    const int last = std::clamp(
        static_cast<int>(std::floor((spans[f][1] + margin - origin_) / width_)), 0, count - 1);
    for (int b = first; b <= last; ++b)
      buckets_[static_cast<std::size_t>(b)].push_back(static_cast<int>(f));
  }
}

const std::vector<int>& FaceBuckets::candidates(const Eigen::Vector3d& point) const {
  if (buckets_.empty())
    return empty_;
  const double position = (point[axis_] - origin_) / width_;
  if (!(position >= 0.0 && position < static_cast<double>(buckets_.size())))
    return empty_;
  return buckets_[static_cast<std::size_t>(position)];
}

} // namespace brb::solid
