// Contact search of the node-to-surface contact: the master faces sorted into buckets along
// the axis in which the master surface is longest (a brace's axis), so a slave node looks
// only at the faces of its own bucket however far the core slides along the casing.
//
// Guarantee. At build, face f spans [lo_f, hi_f] along the axis; it is listed in every
// bucket that meets [lo_f - m, hi_f + m], m = half_width + search_distance, half_width = w/2
// the bucket width's half. As long as no master node has moved by more than w/2 since the
// build (the owner checks it and rebuilds), every point within search_distance of face f
// lies in a bucket that lists f. Points outside the covered range have no candidate.
//
// Cost: build O(F (1 + (h + 2 m) / w)), F faces, h a face's extent along the axis;
// candidates(p) O(1) and returns the faces of one bucket (about the faces of one station
// round the perimeter times (1 + (h + 2 m) / w)).
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace brb::solid {

using QuadFace = std::array<int, 4>;

class FaceBuckets {
public:
  FaceBuckets() = default;

  /// Sorts `faces` (node indices into the columns of `positions`, the current coordinates)
  /// into buckets. The axis is the one of largest extent of the faces' nodes; the width w is
  /// the largest extent of a face along it, at least search_distance (> 0).
  void build(const Eigen::Matrix3Xd& positions, const std::vector<QuadFace>& faces,
             double search_distance);

  /// The faces whose search box may contain `point` (empty outside the covered range).
  const std::vector<int>& candidates(const Eigen::Vector3d& point) const;

  int axis() const { return axis_; }
  double width() const { return width_; }
  int bucket_count() const { return static_cast<int>(buckets_.size()); }

private:
  int axis_ = 0;
  double origin_ = 0.0;
  double width_ = 1.0;
  std::vector<std::vector<int>> buckets_;
  std::vector<int> empty_;
};

} // namespace brb::solid
