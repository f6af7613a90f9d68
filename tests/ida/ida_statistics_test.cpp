// IDA statistics: IM given EDP on hand-made curves, type 7 fractiles against hand-computed
// (numpy default) values, and the censored lognormal collapse fragility against its closed
// form, against synthetic lognormal samples and against an independent likelihood written
// here.
#include "brb/ida/ida_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace brb::ida {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ----- intensity_at_demand -------------------------------------------------------------------

// Runs out of order; the curve (0,0) (0.2,0.004) (0.4,0.008) (0.6,0.02), flatline: collapse at
// 0.8.
const std::vector<CurvePoint> kCollapsingCurve = {
    {0.4, 0.008, false}, {0.8, 0.5, true}, {0.2, 0.004, false}, {0.6, 0.02, false}};

TEST(IntensityAtDemand, InterpolatesLinearlyFromTheOrigin) {
  EXPECT_NEAR(intensity_at_demand(kCollapsingCurve, 0.002), 0.1, 1e-15);
  EXPECT_NEAR(intensity_at_demand(kCollapsingCurve, 0.006), 0.3, 1e-15);
  // 0.4 + (0.014 - 0.008) / (0.02 - 0.008) * 0.2 = 0.5
  EXPECT_NEAR(intensity_at_demand(kCollapsingCurve, 0.014), 0.5, 1e-15);
  EXPECT_NEAR(intensity_at_demand(kCollapsingCurve, 0.008), 0.4, 1e-15);
  EXPECT_EQ(intensity_at_demand(kCollapsingCurve, 0.0), 0.0);
}

TEST(IntensityAtDemand, FlatlineIsTheHighestSurvivalBelowTheCollapse) {
  EXPECT_EQ(intensity_at_demand(kCollapsingCurve, 0.03), 0.6);
  EXPECT_EQ(intensity_at_demand(kCollapsingCurve, 10.0), 0.6);
}

TEST(IntensityAtDemand, NeverCollapsedAndNeverReachedIsInfinite) {
  const std::vector<CurvePoint> curve = {{0.2, 0.004, false}, {0.4, 0.008, false}};
  EXPECT_EQ(intensity_at_demand(curve, 0.01), kInf);
  EXPECT_NEAR(intensity_at_demand(curve, 0.005), 0.25, 1e-15);
}

TEST(IntensityAtDemand, TakesTheFirstCrossingOfAWeavingCurve) {
  // The demand falls between 0.2 and 0.4 (weaving, V&C 2002 fig. 3): 0.008 is first reached at
  // 0.008 / 0.01 * 0.2 = 0.16, not on the later segments.
  const std::vector<CurvePoint> curve = {
      {0.2, 0.01, false}, {0.4, 0.006, false}, {0.6, 0.02, false}};
  EXPECT_NEAR(intensity_at_demand(curve, 0.008), 0.16, 1e-15);
  // 0.015 is first reached between 0.4 and 0.6: 0.4 + (0.015 - 0.006) / 0.014 * 0.2.
  EXPECT_NEAR(intensity_at_demand(curve, 0.015), 0.4 + 0.009 / 0.014 * 0.2, 1e-15);
}

TEST(IntensityAtDemand, IgnoresSurvivalsAboveTheFirstCollapse) {
  // Resurrection: survival at 0.7 above the collapse at 0.5. The flatline stays at 0.2.
  const std::vector<CurvePoint> curve = {{0.2, 0.004, false}, {0.5, 1.0, true}, {0.7, 0.05, false}};
  EXPECT_EQ(intensity_at_demand(curve, 0.03), 0.2);
}

TEST(IntensityAtDemand, EveryRunCollapsedGivesZero) {
  const std::vector<CurvePoint> curve = {{0.1, 1.0, true}, {0.05, 1.0, true}};
  EXPECT_EQ(intensity_at_demand(curve, 0.01), 0.0);
}

TEST(IntensityAtDemand, RejectsBadInput) {
  EXPECT_THROW(intensity_at_demand({}, 0.01), std::invalid_argument);
  EXPECT_THROW(intensity_at_demand(kCollapsingCurve, -0.01), std::invalid_argument);
  const std::vector<CurvePoint> nan_demand = {{0.2, std::nan(""), false}};
  EXPECT_THROW(intensity_at_demand(nan_demand, 0.01), std::invalid_argument);
  const std::vector<CurvePoint> zero_intensity = {{0.0, 0.0, false}};
  EXPECT_THROW(intensity_at_demand(zero_intensity, 0.01), std::invalid_argument);
}

// ----- fractile (Hyndman & Fan 1996 type 7, numpy.quantile's default "linear") ---------------

// Type 7: h = (n - 1) p, Q = x_(floor h) + (h - floor h)(x_(floor h + 1) - x_(floor h)), 0-based
// order statistics. By hand:
//   {1,2,3,4}:       p 0.16 -> h 0.48 -> 1.48; p 0.5 -> h 1.5 -> 2.5; p 0.84 -> h 2.52 -> 3.52
//   {10,...,50}:     p 0.16 -> h 0.64 -> 16.4; p 0.5 -> h 2 -> 30;    p 0.84 -> h 3.36 -> 43.6
// (numpy.quantile([1, 2, 3, 4], [0.16, 0.5, 0.84]) = [1.48, 2.5, 3.52].)
TEST(Fractile, Type7AgainstHandComputedValues) {
  const std::vector<double> four = {3.0, 1.0, 4.0, 2.0};
  EXPECT_NEAR(fractile(four, 0.16), 1.48, 1e-14);
  EXPECT_NEAR(fractile(four, 0.5), 2.5, 1e-14);
  EXPECT_NEAR(fractile(four, 0.84), 3.52, 1e-14);
  const std::vector<double> five = {50.0, 40.0, 30.0, 20.0, 10.0};
  EXPECT_NEAR(fractile(five, 0.16), 16.4, 1e-13);
  EXPECT_EQ(fractile(five, 0.5), 30.0);
  EXPECT_NEAR(fractile(five, 0.84), 43.6, 1e-13);
  const std::vector<double> one = {7.0};
  EXPECT_EQ(fractile(one, 0.16), 7.0);
  EXPECT_EQ(fractile(one, 0.84), 7.0);
}

// {1, 2, 3, inf, inf}: p 0.5 -> h 2, exactly x_(2) = 3; p 0.84 -> h 3.36, between 3 and inf:
// inf; p 0.16 -> h 0.64 -> 1.64.
TEST(Fractile, InfinitiesSortLast) {
  const std::vector<double> values = {kInf, 1.0, kInf, 3.0, 2.0};
  EXPECT_EQ(fractile(values, 0.5), 3.0);
  EXPECT_EQ(fractile(values, 0.84), kInf);
  EXPECT_NEAR(fractile(values, 0.16), 1.64, 1e-15);
}

TEST(Fractile, RejectsBadInput) {
  const std::vector<double> values = {1.0, 2.0};
  EXPECT_THROW(fractile({}, 0.5), std::invalid_argument);
  EXPECT_THROW(fractile(values, 0.0), std::invalid_argument);
  EXPECT_THROW(fractile(values, 1.0), std::invalid_argument);
  EXPECT_THROW(fractile(values, std::nan("")), std::invalid_argument);
  const std::vector<double> with_nan = {1.0, std::nan("")};
  EXPECT_THROW(fractile(with_nan, 0.5), std::invalid_argument);
}

// Three records with straight curves IM = 20 d, 30 d, 50 d up to d = 0.02; the first two
// collapse (flatlines 0.4 and 0.6), the third never does. Type 7 with n = 3: h = 0.32, 1, 1.68.
//   d = 0.01: {0.2, 0.3, 0.5}  -> 0.2 + 0.32 * 0.1 = 0.232, 0.3, 0.3 + 0.68 * 0.2 = 0.436
//   d = 0.03: {0.4, 0.6, inf}  -> 0.4 + 0.32 * 0.2 = 0.464, 0.6, inf
TEST(FractilesGivenDemand, CombinesCurvesAndFlatlines) {
  const std::vector<std::vector<CurvePoint>> curves = {
      {{0.2, 0.01, false}, {0.4, 0.02, false}, {0.6, 1.0, true}},
      {{0.3, 0.01, false}, {0.6, 0.02, false}, {0.9, 1.0, true}},
      {{0.5, 0.01, false}, {1.0, 0.02, false}},
  };
  const std::vector<double> demands = {0.01, 0.03};
  const std::vector<FractileRow> rows = fractiles_given_demand(curves, demands);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].demand, 0.01);
  EXPECT_NEAR(rows[0].p16, 0.232, 1e-14);
  EXPECT_NEAR(rows[0].p50, 0.3, 1e-14);
  EXPECT_NEAR(rows[0].p84, 0.436, 1e-14);
  EXPECT_NEAR(rows[1].p16, 0.464, 1e-14);
  EXPECT_NEAR(rows[1].p50, 0.6, 1e-14);
  EXPECT_EQ(rows[1].p84, kInf);
  EXPECT_THROW(fractiles_given_demand({}, demands), std::invalid_argument);
}

// ----- collapse capacity --------------------------------------------------------------------

TEST(CollapseCapacity, LowestCollapseOrCensoredAtTheHighestRun) {
  const CollapseCapacity collapsed = collapse_capacity(kCollapsingCurve);
  EXPECT_EQ(collapsed.intensity, 0.8);
  EXPECT_FALSE(collapsed.censored);
  const std::vector<CurvePoint> two = {{0.9, 1.0, true}, {0.7, 1.0, true}, {0.5, 0.01, false}};
  EXPECT_EQ(collapse_capacity(two).intensity, 0.7);
  const std::vector<CurvePoint> survived = {{0.5, 0.01, false}, {1.5, 0.03, false}};
  const CollapseCapacity censored = collapse_capacity(survived);
  EXPECT_EQ(censored.intensity, 1.5);
  EXPECT_TRUE(censored.censored);
  EXPECT_THROW(collapse_capacity({}), std::invalid_argument);
}

// ----- collapse fragility -------------------------------------------------------------------

// Capacities 0.5, 1, 2: ln IM = -ln 2, 0, ln 2, mean 0 -> median 1; population deviation
// ln 2 sqrt(2/3). Standard errors (no censoring) beta / sqrt(3) and beta / sqrt(6).
TEST(CollapseFragility, ClosedFormWithoutCensoring) {
  const std::vector<CollapseCapacity> capacities = {{2.0, false}, {0.5, false}, {1.0, false}};
  const LognormalFragility fit = fit_collapse_fragility(capacities);
  const double beta = std::numbers::ln2 * std::sqrt(2.0 / 3.0);
  EXPECT_NEAR(fit.median, 1.0, 1e-15);
  EXPECT_NEAR(fit.dispersion, beta, 1e-15);
  EXPECT_EQ(fit.collapses, 3);
  EXPECT_EQ(fit.censored, 0);
  EXPECT_NEAR(fit.log_median_standard_error, beta / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(fit.dispersion_standard_error, beta / std::sqrt(6.0), 1e-14);
  // P(collapse) at the median is 1/2, one beta above it Phi(1) = 0.8413447460685429.
  EXPECT_NEAR(fit.probability(1.0), 0.5, 1e-15);
  EXPECT_NEAR(fit.probability(std::exp(beta)), 0.8413447460685429, 1e-14);
  EXPECT_EQ(fit.probability(0.0), 0.0);
  // FEMA P695: CMR = S_CT / S_MT.
  EXPECT_NEAR(collapse_margin_ratio(fit, 0.4), 2.5, 1e-14);
  EXPECT_TRUE(std::isnan(collapse_margin_ratio(fit, 0.0)));
}

/// Standard normal samples from a fixed-seed std::mt19937_64 (whose output sequence the C++
/// standard fixes) by the Box-Muller transform (Box & Muller 1958), both of its outputs, so the
/// samples do not depend on the library's distribution classes.
class NormalSamples {
public:
  explicit NormalSamples(std::uint64_t seed) : engine_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = uniform_open();
    const double u2 = uniform_open();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

private:
  /// Uniform in (0, 1): the top 53 bits, offset by half a unit so that 0 never occurs.
  double uniform_open() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

constexpr double kTrueMedian = 1.2; // g
constexpr double kTrueBeta = 0.4;

/// n lognormal capacities (median 1.2, beta 0.4); those above `censor_at` are censored there,
/// as a run budget ending the hunt at that intensity would.
std::vector<CollapseCapacity> synthetic_capacities(int n, double censor_at, std::uint64_t seed) {
  NormalSamples normal(seed);
  std::vector<CollapseCapacity> capacities;
  for (int i = 0; i < n; ++i) {
    const double capacity = kTrueMedian * std::exp(kTrueBeta * normal.next());
    capacities.push_back(capacity > censor_at ? CollapseCapacity{censor_at, true}
                                              : CollapseCapacity{capacity, false});
  }
  return capacities;
}

/// The log-likelihood written directly in (mu, beta), independently of the library's (a, b)
/// form: sum over collapses of ln[phi(z) / (beta IM)] plus sum over censored of ln[1 - Phi(z)],
/// z = (ln IM - mu) / beta.
double log_likelihood(const std::vector<CollapseCapacity>& capacities, double mu, double beta) {
  double value = 0.0;
  for (const CollapseCapacity& c : capacities) {
    const double z = (std::log(c.intensity) - mu) / beta;
    if (c.censored)
      value += std::log(0.5 * std::erfc(z / std::numbers::sqrt2));
    else
      value += -0.5 * z * z - std::log(beta * c.intensity * std::sqrt(2.0 * std::numbers::pi));
  }
  return value;
}

/// Checks `fit` against the independent likelihood: its gradient (central differences) is ~0,
/// and the standard errors are those of the inverse of the finite-difference Hessian (the
/// observed information).
void expect_maximum_likelihood(const std::vector<CollapseCapacity>& capacities,
                               const LognormalFragility& fit) {
  const double mu = std::log(fit.median);
  const double beta = fit.dispersion;
  const auto l = [&](double m, double b) { return log_likelihood(capacities, m, b); };
  const double h = 1e-4;
  const double d_mu = (l(mu + h, beta) - l(mu - h, beta)) / (2 * h);
  const double d_beta = (l(mu, beta + h) - l(mu, beta - h)) / (2 * h);
  const double n = static_cast<double>(capacities.size());
  // The curvature is ~n / beta^2, so a gradient of 1e-6 n moves the maximum by ~1e-7 beta^2.
  EXPECT_NEAR(d_mu, 0.0, 1e-6 * n);
  EXPECT_NEAR(d_beta, 0.0, 1e-6 * n);
  const double l0 = l(mu, beta);
  const double h_mm = (l(mu + h, beta) - 2 * l0 + l(mu - h, beta)) / (h * h);
  const double h_bb = (l(mu, beta + h) - 2 * l0 + l(mu, beta - h)) / (h * h);
  const double h_mb =
      (l(mu + h, beta + h) - l(mu + h, beta - h) - l(mu - h, beta + h) + l(mu - h, beta - h)) /
      (4 * h * h);
  // Covariance = (-H)^-1.
  const double det = h_mm * h_bb - h_mb * h_mb;
  EXPECT_NEAR(fit.log_median_standard_error, std::sqrt(-h_bb / det),
              1e-4 * fit.log_median_standard_error);
  EXPECT_NEAR(fit.dispersion_standard_error, std::sqrt(-h_mm / det),
              1e-4 * fit.dispersion_standard_error);
}

// Without censoring the estimates' standard errors are beta / sqrt(n) for ln(median) and
// beta / sqrt(2 n) for beta (asymptotic, normal theory); the estimates must lie within 3 of
// them (with the true beta) of the truth.
TEST(CollapseFragility, RecoversUncensoredSyntheticSamples) {
  for (const int n : {40, 400}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const std::vector<CollapseCapacity> capacities = synthetic_capacities(n, kInf, 20260601);
    const LognormalFragility fit = fit_collapse_fragility(capacities);
    EXPECT_EQ(fit.collapses, n);
    EXPECT_EQ(fit.censored, 0);
    const double se_mu = kTrueBeta / std::sqrt(n);
    const double se_beta = kTrueBeta / std::sqrt(2.0 * n);
    EXPECT_NEAR(std::log(fit.median), std::log(kTrueMedian), 3.0 * se_mu);
    EXPECT_NEAR(fit.dispersion, kTrueBeta, 3.0 * se_beta);
    expect_maximum_likelihood(capacities, fit);
  }
}

// Censored at IM = median e^(beta / 2) (31 % of the records survive the whole hunt, Phi(-0.5)
// = 0.3085). The standard errors are those of the observed information of the censored
// likelihood (checked against the independent likelihood's finite-difference Hessian); the
// estimates lie within 3 of them of the truth. The naive fit to the collapses alone is biased
// low: it drops the strongest records. Its expected ln-median shift is -beta phi(0.5) /
// Phi(0.5) = -0.204 (truncated normal mean), more than 3 standard errors at n = 400.
TEST(CollapseFragility, CensoredMaximumLikelihoodCorrectsTheBias) {
  const double censor_at = kTrueMedian * std::exp(0.5 * kTrueBeta);
  for (const int n : {40, 400}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const std::vector<CollapseCapacity> capacities = synthetic_capacities(n, censor_at, 20260602);
    const LognormalFragility fit = fit_collapse_fragility(capacities);
    EXPECT_EQ(fit.collapses + fit.censored, n);
    EXPECT_GT(fit.censored, n / 5);
    expect_maximum_likelihood(capacities, fit);
    EXPECT_NEAR(std::log(fit.median), std::log(kTrueMedian), 3.0 * fit.log_median_standard_error);
    EXPECT_NEAR(fit.dispersion, kTrueBeta, 3.0 * fit.dispersion_standard_error);
    // Censoring loses information: the standard errors exceed the uncensored ones.
    EXPECT_GT(fit.log_median_standard_error, kTrueBeta / std::sqrt(n) * 0.9);

    std::vector<CollapseCapacity> collapses_only;
    for (const CollapseCapacity& c : capacities) {
      if (!c.censored)
        collapses_only.push_back(c);
    }
    const LognormalFragility naive = fit_collapse_fragility(collapses_only);
    EXPECT_LT(naive.median, fit.median);
    EXPECT_LT(naive.dispersion, fit.dispersion);
    if (n == 400) {
      EXPECT_GT(std::log(kTrueMedian) - std::log(naive.median),
                3.0 * fit.log_median_standard_error);
    }
  }
}

// Half the records censored at the true median: still a unique maximum (the likelihood is
// concave in (mu / beta, 1 / beta)), found from the uncensored start far from it.
TEST(CollapseFragility, HeavyCensoringStillConverges) {
  const std::vector<CollapseCapacity> capacities = synthetic_capacities(40, kTrueMedian, 20260603);
  const LognormalFragility fit = fit_collapse_fragility(capacities);
  expect_maximum_likelihood(capacities, fit);
  EXPECT_NEAR(std::log(fit.median), std::log(kTrueMedian), 3.0 * fit.log_median_standard_error);
  EXPECT_NEAR(fit.dispersion, kTrueBeta, 3.0 * fit.dispersion_standard_error);
}

TEST(CollapseFragility, DegenerateInputThrows) {
  EXPECT_THROW(fit_collapse_fragility({}), std::invalid_argument);
  const std::vector<CollapseCapacity> one = {{1.0, false}, {2.0, true}, {3.0, true}};
  EXPECT_THROW(fit_collapse_fragility(one), std::invalid_argument);
  const std::vector<CollapseCapacity> equal = {{1.0, false}, {1.0, false}, {2.0, true}};
  EXPECT_THROW(fit_collapse_fragility(equal), std::invalid_argument);
  const std::vector<CollapseCapacity> zero = {{0.0, false}, {1.0, false}, {2.0, false}};
  EXPECT_THROW(fit_collapse_fragility(zero), std::invalid_argument);
  const std::vector<CollapseCapacity> infinite = {{kInf, true}, {1.0, false}, {2.0, false}};
  EXPECT_THROW(fit_collapse_fragility(infinite), std::invalid_argument);
}

} // namespace
} // namespace brb::ida
