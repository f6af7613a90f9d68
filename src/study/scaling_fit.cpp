#include "brb/study/scaling_fit.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <vector>

namespace brb::study {

PowerLawFit fit_power_law(std::span<const double> sizes, std::span<const double> costs) {
  if (sizes.size() != costs.size())
    throw std::invalid_argument("fit_power_law: as many sizes as costs are needed");
  if (sizes.size() < 2)
    throw std::invalid_argument("fit_power_law: at least two points are needed");
  const auto n = static_cast<double>(sizes.size());
  std::vector<double> x, y;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    if (!(sizes[k] > 0.0 && std::isfinite(sizes[k]) && costs[k] > 0.0 && std::isfinite(costs[k])))
      throw std::invalid_argument("fit_power_law: sizes and costs must be positive and finite");
    x.push_back(std::log(sizes[k]));
    y.push_back(std::log(costs[k]));
  }
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    mean_x += x[k] / n;
    mean_y += y[k] / n;
  }
  // ordinary least squares on the centred logarithms: b = S_xy / S_xx, a = mean_y - b mean_x
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxx += (x[k] - mean_x) * (x[k] - mean_x);
    sxy += (x[k] - mean_x) * (y[k] - mean_y);
    syy += (y[k] - mean_y) * (y[k] - mean_y);
  }
  if (!(sxx > 0.0))
    throw std::invalid_argument("fit_power_law: the sizes must not all be equal");
  PowerLawFit fit;
  fit.exponent = sxy / sxx;
  fit.intercept = mean_y - fit.exponent * mean_x;
  fit.r_squared = syy > 0.0 ? sxy * sxy / (sxx * syy) : 1.0;
  return fit;
}

double median(std::span<const double> values) {
  if (values.empty())
    throw std::invalid_argument("median of no values");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t middle = sorted.size() / 2;
  return sorted.size() % 2 == 1 ? sorted[middle] : 0.5 * (sorted[middle - 1] + sorted[middle]);
}

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

} // namespace brb::study
