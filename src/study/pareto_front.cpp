#include "brb/study/pareto_front.hpp"

#include <cmath>

namespace brb::study {

std::vector<bool> pareto_front(const std::vector<TimeErrorPoint>& points) {
  // O(n^2): a matrix has tens of settings.
  std::vector<bool> on_front(points.size(), false);
  const auto finite = [](const TimeErrorPoint& p) {
    return std::isfinite(p.time) && std::isfinite(p.error);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i]))
      continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      if (j == i || !finite(points[j]))
        continue;
      const TimeErrorPoint& p = points[i];
      const TimeErrorPoint& q = points[j];
      dominated = q.time <= p.time && q.error <= p.error && (q.time < p.time || q.error < p.error);
    }
    on_front[i] = !dominated;
  }
  return on_front;
}

} // namespace brb::study
