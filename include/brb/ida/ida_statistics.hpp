// Summaries of a set of IDA curves: fractiles of the intensity given the demand (Vamvatsikos
// & Cornell 2002, sec. 6: "IM capacity" at each EDP level, the flatline counting as the
// collapse capacity), and the lognormal collapse fragility fitted by maximum likelihood to
// each record's collapse intensity, records that never collapsed being right-censored at
// their highest intensity (a record that survived IM is known only to collapse above it).
// FEMA P695 (2009) sec. 6.3: S_CT is the median collapse intensity, CMR = S_CT / S_MT.
#pragma once

#include <limits>
#include <span>
#include <vector>

namespace brb::ida {

/// One run of one record: its intensity, demand (e.g. peak story drift ratio) and whether it
/// collapsed (drift limit or numerical collapse: the curve's flatline).
struct CurvePoint {
  double intensity = 0.0;
  double demand = 0.0;
  bool collapsed = false;
};

/// A record's IDA curve below its flatline: its non-collapsing runs under the lowest
/// collapse (all of them when none collapsed), sorted by intensity (ties keep the order of
/// the runs). Survivals above the lowest collapse ("resurrection") are left out.
std::vector<CurvePoint> curve_below_flatline(std::span<const CurvePoint> curve);

/// The intensity at which a record's IDA curve first reaches `demand`: the curve is its
/// non-collapsing points below the lowest collapse (survivals above it, "resurrection", are
/// ignored) sorted by intensity, joined by straight lines from (0, 0); the first crossing of
/// `demand` is interpolated linearly in (intensity, demand). When the curve never reaches
/// `demand`: the highest non-collapsing intensity below the lowest collapse when the record
/// collapsed (the flatline; 0 when no run below the collapse survived), +infinity when it
/// never collapsed (capacity unknown, above every run). Demand 0 gives 0. Throws
/// std::invalid_argument for an empty curve, a demand that is negative or not finite, an
/// intensity that is not finite and > 0, or a non-collapsing demand that is not finite and
/// >= 0 (collapsed runs' demands are not used).
double intensity_at_demand(std::span<const CurvePoint> curve, double demand);

/// The p-fractile (0 < p < 1) of `values` by linear interpolation between order statistics
/// (the Hyndman & Fan 1996 type 7 definition, as numpy/R default); +infinity values sort
/// last, and any interpolation towards +infinity gives +infinity. Throws
/// std::invalid_argument on an empty span, p outside (0, 1), or a NaN or -infinity value.
double fractile(std::span<const double> values, double p);

struct FractileRow {
  double demand = 0.0;
  double p16 = 0.0; ///< intensities (+infinity when that many records never reach it)
  double p50 = 0.0;
  double p84 = 0.0;
};

/// For each demand level, the 16/50/84 % fractiles over the records of intensity_at_demand.
/// Throws std::invalid_argument when there are no curves.
std::vector<FractileRow> fractiles_given_demand(const std::vector<std::vector<CurvePoint>>& curves,
                                                std::span<const double> demands);

/// A record's collapse capacity: its lowest collapsing intensity, or, censored, the highest
/// intensity it survived without collapsing.
struct CollapseCapacity {
  double intensity = 0.0; ///< > 0
  bool censored = false;  ///< true: no collapse up to `intensity`
};

/// The capacity of one record's runs (see CollapseCapacity). Throws std::invalid_argument
/// for an empty span.
CollapseCapacity collapse_capacity(std::span<const CurvePoint> curve);

/// Lognormal fragility P(collapse | IM) = Phi(ln(IM / median) / dispersion).
struct LognormalFragility {
  double median = 0.0;     ///< theta, IM units
  double dispersion = 0.0; ///< beta, standard deviation of ln IM
  int collapses = 0;       ///< uncensored capacities used
  int censored = 0;
  /// Asymptotic standard errors of the estimates (from the observed Fisher information of
  /// the likelihood; with no censoring they are beta / sqrt(n) for ln(median) and
  /// beta / sqrt(2 n) for beta).
  double log_median_standard_error = 0.0;
  double dispersion_standard_error = 0.0;
  double probability(double intensity) const;
};

/// The maximum-likelihood lognormal fit to the capacities (uncensored: density; censored:
/// survival probability). With x = ln IM and z = (x - ln median) / beta:
///   l = sum_collapsed [-ln beta - z^2 / 2] + sum_censored ln(1 - Phi(z)) + const,
/// maximised by Newton's method with a backtracking line search in Olsen's parameters
/// (ln median / beta, 1 / beta), in which l is strictly concave (unique maximum), started from
/// the closed form of the collapses alone. Needs at least two uncensored capacities with
/// different values, and every intensity finite and > 0 (std::invalid_argument otherwise).
/// Without censoring it is the closed form: median = exp(mean ln IM), beta = population
/// standard deviation of ln IM (1/n).
LognormalFragility fit_collapse_fragility(std::span<const CollapseCapacity> capacities);

/// FEMA P695 collapse margin ratio S_CT / S_MT (S_CT: the fragility median).
inline double collapse_margin_ratio(const LognormalFragility& fragility, double mce_intensity) {
  return mce_intensity > 0.0 ? fragility.median / mce_intensity
                             : std::numeric_limits<double>::quiet_NaN();
}

} // namespace brb::ida
