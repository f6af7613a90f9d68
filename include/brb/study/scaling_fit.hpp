// Cost-scaling helpers of the benchmarks (issue 9): the least-squares power law of a cost
// against a size, and how the benchmarks measure a cost (process CPU time, median of repeats).
#pragma once

#include <span>

namespace brb::study {

/// log(cost) = intercept + exponent log(size), fitted by least squares on the logarithms.
struct PowerLawFit {
  double intercept = 0.0;
  double exponent = 0.0;
  double r_squared = 0.0; ///< of the fit on the logarithms (1: every point on the line)
};

/// Fits the power law through (size_k, cost_k). Throws std::invalid_argument for fewer than two
/// points, sizes and costs of different lengths, a size or cost that is not positive and
/// finite, or sizes that are all equal.
PowerLawFit fit_power_law(std::span<const double> sizes, std::span<const double> costs);

/// The median (mean of the two middle values for an even count). Throws
/// std::invalid_argument for no values.
double median(std::span<const double> values);

/// CPU time of this process so far (s): what a run costs on a machine shared with other jobs
/// (the analyses are single-threaded).
double process_cpu_seconds();

} // namespace brb::study
