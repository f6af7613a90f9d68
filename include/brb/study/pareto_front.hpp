// The Pareto front of a set of (run time, error) points: the points no other point beats in
// both, i.e. the settings worth choosing. A point p is dominated when another point q has
// q.time <= p.time and q.error <= p.error with at least one strict. Points with a time or an
// error that is not finite (a failed run, an unknown error) are never on the front.
#pragma once

#include <vector>

namespace brb::study {

struct TimeErrorPoint {
  double time = 0.0;  ///< s
  double error = 0.0; ///< relative
};

/// One flag per point, in order: true when the point is on the front. Equal points (same
/// time and error) are all on it when they are not dominated.
std::vector<bool> pareto_front(const std::vector<TimeErrorPoint>& points);

} // namespace brb::study
