#include "brb/ida/ida_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace brb::ida {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void check_curve(std::span<const CurvePoint> curve, const char* function) {
  if (curve.empty())
    throw std::invalid_argument(std::string(function) + ": the curve has no runs");
  for (const CurvePoint& point : curve) {
    if (!(std::isfinite(point.intensity) && point.intensity > 0.0)) {
      throw std::invalid_argument(std::string(function) +
                                  ": a run's intensity must be a finite number > 0, got " +
                                  std::to_string(point.intensity));
    }
    if (!point.collapsed && !(std::isfinite(point.demand) && point.demand >= 0.0)) {
      throw std::invalid_argument(std::string(function) +
                                  ": a non-collapsing run's demand must be a finite number >= "
                                  "0, got " +
                                  std::to_string(point.demand) + " at intensity " +
                                  std::to_string(point.intensity));
    }
  }
}

std::optional<double> lowest_collapse_of(std::span<const CurvePoint> curve) {
  std::optional<double> lowest;
  for (const CurvePoint& point : curve) {
    if (point.collapsed && (!lowest || point.intensity < *lowest))
      lowest = point.intensity;
  }
  return lowest;
}

/// The non-collapsing points under `collapse` (all when there is none), by intensity (ties
/// keep their order of the runs).
std::vector<CurvePoint> below_collapse(std::span<const CurvePoint> curve,
                                       std::optional<double> collapse) {
  std::vector<CurvePoint> points;
  for (const CurvePoint& point : curve) {
    if (!point.collapsed && (!collapse || point.intensity < *collapse))
      points.push_back(point);
  }
  std::stable_sort(points.begin(), points.end(), [](const CurvePoint& a, const CurvePoint& b) {
    return a.intensity < b.intensity;
  });
  return points;
}

// ---------------------------------------------------------------------------------------
// The censored lognormal likelihood. With x = ln IM, mu = ln(median), beta the dispersion and
// z = (x - mu) / beta, a record that collapsed at x contributes the density of ln IM and one
// censored at x (no collapse up to it) the probability of collapsing above it:
//     l(mu, beta) = sum_collapsed [-ln beta - z_i^2 / 2] + sum_censored ln Q(z_j) + const,
// Q(z) = 1 - Phi(z). In Olsen's (1978, "Note on the uniqueness of the maximum likelihood
// estimator for the Tobit model", Econometrica 46(5)) parameters a = mu / beta, b = 1 / beta,
// z = b x - a is linear, so
//     l(a, b) = sum_collapsed [ln b - (b x_i - a)^2 / 2] + sum_censored ln Q(b x_j - a)
// is strictly concave (ln b and -(.)^2 are, Q is log-concave): Newton's method with a
// backtracking line search converges to the unique maximum from any start.

constexpr double kInverseSqrt2Pi = 0.39894228040143267794; // 1 / sqrt(2 pi)

/// Past this z, erfc and exp(-z^2/2) underflow; Q and the hazard come from the asymptotic
/// series of Mills' ratio (Abramowitz & Stegun 26.2.12), whose terms are < 1e-12 there.
constexpr double kTailSeriesFrom = 30.0;

/// Q(z) / phi(z) ~ (1/z)(1 - 1/z^2 + 3/z^4 - 15/z^6 + 105/z^8) for large z.
double mills_ratio_asymptotic(double z) {
  const double w = 1.0 / (z * z);
  return (1.0 + w * (-1.0 + w * (3.0 + w * (-15.0 + w * 105.0)))) / z;
}

/// ln Q(z).
double log_upper_tail(double z) {
  if (z < kTailSeriesFrom)
    return std::log(0.5 * std::erfc(z / std::numbers::sqrt2));
  return -0.5 * z * z + std::log(kInverseSqrt2Pi * mills_ratio_asymptotic(z));
}

/// The hazard h(z) = phi(z) / Q(z) = -d ln Q / dz.
double hazard(double z) {
  if (z < kTailSeriesFrom)
    return kInverseSqrt2Pi * std::exp(-0.5 * z * z) / (0.5 * std::erfc(z / std::numbers::sqrt2));
  return 1.0 / mills_ratio_asymptotic(z);
}

struct LogCapacities {
  std::vector<double> collapsed; ///< ln IM of the collapses
  std::vector<double> censored;  ///< ln IM of the censoring intensities
};

/// Value, gradient and Hessian of l in (a, b) (see above); d/dz ln Q = -h, d^2/dz^2 ln Q =
/// -h (h - z).
struct Expansion {
  double value = 0.0;
  double ga = 0.0, gb = 0.0;
  double haa = 0.0, hab = 0.0, hbb = 0.0;
};

double log_likelihood_ab(const LogCapacities& data, double a, double b) {
  double value = 0.0;
  for (const double x : data.collapsed) {
    const double r = b * x - a;
    value += std::log(b) - 0.5 * r * r;
  }
  for (const double x : data.censored)
    value += log_upper_tail(b * x - a);
  return value;
}

Expansion expand_ab(const LogCapacities& data, double a, double b) {
  Expansion e;
  e.value = log_likelihood_ab(data, a, b);
  for (const double x : data.collapsed) {
    const double r = b * x - a;
    e.ga += r;
    e.gb += 1.0 / b - r * x;
    e.haa -= 1.0;
    e.hab += x;
    e.hbb -= 1.0 / (b * b) + x * x;
  }
  for (const double x : data.censored) {
    const double z = b * x - a;
    const double h = hazard(z);
    const double slope = h * (h - z); // h'(z), in (0, 1)
    e.ga += h;
    e.gb -= h * x;
    e.haa -= slope;
    e.hab += slope * x;
    e.hbb -= slope * x * x;
  }
  return e;
}

struct NormalEstimate {
  double mean = 0.0;
  double deviation = 0.0; ///< population (1/n) standard deviation
};

NormalEstimate closed_form(const std::vector<double>& x) {
  const auto n = static_cast<double>(x.size());
  double sum = 0.0;
  for (const double v : x)
    sum += v;
  const double mean = sum / n;
  double squares = 0.0;
  for (const double v : x)
    squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / n)};
}

/// Newton's method on the concave l(a, b), from the uncensored closed form, with the step
/// halved until b stays positive and the Armijo condition holds (Nocedal & Wright 2006,
/// alg. 3.1).
NormalEstimate maximise_likelihood(const LogCapacities& data, const NormalEstimate& start) {
  double a = start.mean / start.deviation;
  double b = 1.0 / start.deviation;
  constexpr int kMaxIterations = 200;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Expansion e = expand_ab(data, a, b);
    // Newton step d = -H^{-1} g (H negative definite).
    const double det = e.haa * e.hbb - e.hab * e.hab;
    const double da = -(e.hbb * e.ga - e.hab * e.gb) / det;
    const double db = -(-e.hab * e.ga + e.haa * e.gb) / det;
    const double decrement = e.ga * da + e.gb * db; // g^T d = -g^T H^{-1} g >= 0
    // Near the maximum the predicted gain decrement / 2 falls below the round-off of l, where
    // a line search can no longer tell better from worse; the quadratic model is exact there
    // to far better than that, so full Newton steps are taken until the step is at round-off.
    if (decrement <= 1e-12 * (1.0 + std::abs(e.value)) && b + db > 0.5 * b) {
      a += da;
      b += db;
      if (std::abs(da) <= 1e-13 * (1.0 + std::abs(a)) && std::abs(db) <= 1e-13 * b)
        return {a / b, 1.0 / b};
      continue;
    }
    double t = 1.0;
    while (!(b + t * db > 0.0))
      t *= 0.5;
    for (int halving = 0; halving < 60; ++halving) {
      if (log_likelihood_ab(data, a + t * da, b + t * db) >= e.value + 1e-4 * t * decrement)
        break;
      t *= 0.5;
    }
    a += t * da;
    b += t * db;
  }
  throw std::runtime_error("collapse fragility: the maximum-likelihood iteration did not "
                           "converge in 200 Newton steps");
}

/// Standard errors of (mu, beta) from the observed information -d^2 l / d(mu, beta)^2 at the
/// maximum. There the gradient vanishes, so the Hessian in (mu, beta) is J^T H_ab J with J the
/// Jacobian of (a, b) = (mu / beta, 1 / beta): J = [[1/beta, -mu/beta^2], [0, -1/beta^2]].
void set_standard_errors(const LogCapacities& data, const NormalEstimate& estimate,
                         LognormalFragility& fit) {
  const double mu = estimate.mean;
  const double beta = estimate.deviation;
  const Expansion e = expand_ab(data, mu / beta, 1.0 / beta);
  const double j11 = 1.0 / beta, j12 = -mu / (beta * beta), j22 = -1.0 / (beta * beta);
  // I = -J^T H J, with J = [[j11, j12], [0, j22]].
  const double i11 = -(j11 * j11 * e.haa);
  const double i12 = -(j11 * (e.haa * j12 + e.hab * j22));
  const double i22 = -(j12 * j12 * e.haa + 2.0 * j12 * j22 * e.hab + j22 * j22 * e.hbb);
  const double det = i11 * i22 - i12 * i12;
  fit.log_median_standard_error = std::sqrt(i22 / det);
  fit.dispersion_standard_error = std::sqrt(i11 / det);
}

} // namespace

std::vector<CurvePoint> curve_below_flatline(std::span<const CurvePoint> curve) {
  return below_collapse(curve, lowest_collapse_of(curve));
}

double intensity_at_demand(std::span<const CurvePoint> curve, double demand) {
  check_curve(curve, "intensity_at_demand");
  if (!(std::isfinite(demand) && demand >= 0.0)) {
    throw std::invalid_argument("intensity_at_demand: the demand must be a finite number >= 0, "
                                "got " +
                                std::to_string(demand));
  }
  const std::optional<double> collapse = lowest_collapse_of(curve);
  const std::vector<CurvePoint> points = below_collapse(curve, collapse);
  // Segments from (0, 0) through the points; the first whose end reaches the demand.
  double previous_intensity = 0.0;
  double previous_demand = 0.0;
  if (demand <= previous_demand)
    return 0.0;
  for (const CurvePoint& point : points) {
    if (point.demand >= demand) {
      const double fraction = (demand - previous_demand) / (point.demand - previous_demand);
      return previous_intensity + fraction * (point.intensity - previous_intensity);
    }
    previous_intensity = point.intensity;
    previous_demand = point.demand;
  }
  if (!collapse)
    return kInfinity;
  return points.empty() ? 0.0 : points.back().intensity;
}

double fractile(std::span<const double> values, double p) {
  if (values.empty())
    throw std::invalid_argument("fractile: no values");
  if (!(p > 0.0 && p < 1.0))
    throw std::invalid_argument("fractile: p must lie in (0, 1), got " + std::to_string(p));
  std::vector<double> sorted(values.begin(), values.end());
  for (const double v : sorted) {
    if (std::isnan(v) || v == -kInfinity)
      throw std::invalid_argument("fractile: a value is NaN or -infinity");
  }
  std::sort(sorted.begin(), sorted.end());
  // Hyndman & Fan (1996) type 7: h = (n - 1) p, Q = x_(floor h) + (h - floor h)(x_(floor h + 1)
  // - x_(floor h)), 0-based order statistics.
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const double floor_h = std::floor(h);
  const auto lower = static_cast<std::size_t>(floor_h);
  const double fraction = h - floor_h;
  if (fraction == 0.0 || lower + 1 >= sorted.size())
    return sorted[lower];
  const double low = sorted[lower];
  const double high = sorted[lower + 1];
  if (high == kInfinity)
    return kInfinity; // part of the way towards +infinity is +infinity
  return low + fraction * (high - low);
}

std::vector<FractileRow> fractiles_given_demand(const std::vector<std::vector<CurvePoint>>& curves,
                                                std::span<const double> demands) {
  if (curves.empty())
    throw std::invalid_argument("fractiles_given_demand: no curves");
  std::vector<FractileRow> rows;
  rows.reserve(demands.size());
  std::vector<double> capacities(curves.size());
  for (const double demand : demands) {
    for (std::size_t r = 0; r < curves.size(); ++r)
      capacities[r] = intensity_at_demand(curves[r], demand);
    rows.push_back({demand, fractile(capacities, 0.16), fractile(capacities, 0.50),
                    fractile(capacities, 0.84)});
  }
  return rows;
}

CollapseCapacity collapse_capacity(std::span<const CurvePoint> curve) {
  if (curve.empty())
    throw std::invalid_argument("collapse_capacity: the curve has no runs");
  if (const std::optional<double> collapse = lowest_collapse_of(curve))
    return {*collapse, false};
  double highest = 0.0;
  for (const CurvePoint& point : curve)
    highest = std::max(highest, point.intensity);
  return {highest, true};
}

double LognormalFragility::probability(double intensity) const {
  if (!(intensity > 0.0))
    return 0.0;
  const double z = std::log(intensity / median) / dispersion;
  return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

LognormalFragility fit_collapse_fragility(std::span<const CollapseCapacity> capacities) {
  LogCapacities data;
  for (const CollapseCapacity& capacity : capacities) {
    if (!(std::isfinite(capacity.intensity) && capacity.intensity > 0.0)) {
      throw std::invalid_argument("collapse fragility: a capacity must be a finite intensity > "
                                  "0, got " +
                                  std::to_string(capacity.intensity));
    }
    (capacity.censored ? data.censored : data.collapsed).push_back(std::log(capacity.intensity));
  }
  const bool distinct = data.collapsed.size() >= 2 &&
                        std::any_of(data.collapsed.begin(), data.collapsed.end(),
                                    [&](double x) { return x != data.collapsed.front(); });
  if (!distinct) {
    std::ostringstream message;
    message << "collapse fragility: needs at least two collapses at different intensities, got "
            << data.collapsed.size() << " collapse(s) and " << data.censored.size()
            << " censored record(s)";
    throw std::invalid_argument(message.str());
  }

  const NormalEstimate uncensored = closed_form(data.collapsed);
  const NormalEstimate estimate =
      data.censored.empty() ? uncensored : maximise_likelihood(data, uncensored);
  LognormalFragility fit;
  fit.median = std::exp(estimate.mean);
  fit.dispersion = estimate.deviation;
  fit.collapses = static_cast<int>(data.collapsed.size());
  fit.censored = static_cast<int>(data.censored.size());
  set_standard_errors(data, estimate, fit);
  return fit;
}

} // namespace brb::ida
