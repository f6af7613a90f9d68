// The exact piecewise-linear SDOF solution (Nigam-Jennings; Chopra sec. 5.2) against closed-form
// solutions of the equation of motion u'' + 2 zeta omega u' + omega^2 u = -a_g(t), for steps
// from omega dt = 1e-4 (where Chopra's closed-form coefficients lose digits) to omega dt = 20.
#include "brb/analysis/sdof_exact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace brb::analysis {
namespace {

constexpr double kPi = std::numbers::pi;
/// The recurrence must equal the closed forms to this fraction of the response's scale.
constexpr double kExactTolerance = 1e-12;

struct Case {
  double omega_dt;
  double zeta;
};

std::string case_name(const Case& c);

void PrintTo(const Case& c, std::ostream* out) {
  *out << "w dt " << c.omega_dt << ", zeta " << c.zeta;
}

std::string case_name(const Case& c) {
  std::string name = "wdt" + std::to_string(c.omega_dt) + "_zeta" + std::to_string(c.zeta);
  std::replace(name.begin(), name.end(), '.', 'p');
  std::replace(name.begin(), name.end(), '-', 'm');
  return name;
}

constexpr double kPeriod = 0.8; // s

double omega_of(double period) {
  return 2.0 * kPi / period;
}

/// Steps covering three periods, at most 2000 (round-off then stays far below 1e-12).
std::size_t sample_count(double omega_dt) {
  return static_cast<std::size_t>(std::min(2000.0, std::ceil(3.0 * 2.0 * kPi / omega_dt))) + 1;
}

double largest_magnitude(const std::vector<double>& values) {
  double largest = 0.0;
  for (const double value : values)
    largest = std::max(largest, std::abs(value));
  return largest;
}

const std::vector<Case> kCases{Case{1e-4, 0.05}, Case{1e-3, 0.0}, Case{6e-3, 0.05},
                               Case{0.05, 0.02}, Case{0.3, 0.05}, Case{0.999, 0.1},
                               Case{1.001, 0.1}, Case{2.0, 0.0},  Case{2.0, 0.3},
                               Case{7.0, 0.05},  Case{20.0, 0.5}};

class ExactAtAnyStep : public ::testing::TestWithParam<Case> {
protected:
  double omega() const { return omega_of(kPeriod); }
  double dt() const { return GetParam().omega_dt / omega(); }
  double zeta() const { return GetParam().zeta; }
  double omega_d() const { return omega() * std::sqrt(1.0 - zeta() * zeta()); }
  LinearOscillator oscillator() const { return {kPeriod, zeta()}; }
};

TEST_P(ExactAtAnyStep, FreeVibrationFromInitialConditionsThroughAZeroRecord) {
  // u = e^{-zeta w t}(u0 cos wd t + (v0 + zeta w u0)/wd sin wd t) (Chopra eq. 2.2.4) and its
  // derivative u' = e^{-zeta w t}(v0 cos wd t - (zeta w v0 + w^2 u0)/wd sin wd t).
  const double u0 = 12.5;  // mm
  const double v0 = -80.0; // mm/s
  const std::size_t count = sample_count(GetParam().omega_dt);
  const std::vector<double> zero_record(count, 0.0);
  const SdofResponse response = sdof_response(zero_record, dt(), oscillator(), {u0, v0});
  ASSERT_EQ(response.displacement.size(), count);

  std::vector<double> u(count), v(count);
  const double w = omega();
  const double wd = omega_d();
  for (std::size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) * dt();
    const double decay = std::exp(-zeta() * w * t);
    u[i] = decay * (u0 * std::cos(wd * t) + (v0 + zeta() * w * u0) / wd * std::sin(wd * t));
    v[i] = decay * (v0 * std::cos(wd * t) - (zeta() * w * v0 + w * w * u0) / wd * std::sin(wd * t));
  }
  const double u_scale = largest_magnitude(u);
  const double v_scale = largest_magnitude(v);
  for (std::size_t i = 0; i < count; ++i) {
    ASSERT_NEAR(response.displacement[i], u[i], kExactTolerance * u_scale) << "sample " << i;
    ASSERT_NEAR(response.velocity[i], v[i], kExactTolerance * v_scale) << "sample " << i;
  }
  EXPECT_NEAR(response.peaks.displacement, u_scale, kExactTolerance * u_scale);
  EXPECT_NEAR(response.peaks.velocity, v_scale, kExactTolerance * v_scale);
}

TEST_P(ExactAtAnyStep, StepGroundAcceleration) {
  // a_g = a for t >= 0 from rest (the samples are exactly this constant):
  // u = -a/w^2 (1 - e^{-zeta w t}(cos wd t + zeta/sqrt(1-zeta^2) sin wd t)) (Chopra eq. 4.3.2),
  // u' = -(a/wd) e^{-zeta w t} sin wd t, and the absolute acceleration u'' + a with
  // u'' = -(a/wd) e^{-zeta w t}(wd cos wd t - zeta w sin wd t).
  const double a = 0.3 * 9806.65; // mm/s^2
  const std::size_t count = sample_count(GetParam().omega_dt);
  const std::vector<double> record(count, a);
  const SdofResponse response = sdof_response(record, dt(), oscillator());

  const double w = omega();
  const double wd = omega_d();
  const double root = std::sqrt(1.0 - zeta() * zeta());
  const double u_scale = a / (w * w);
  const double v_scale = a / wd;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) * dt();
    const double decay = std::exp(-zeta() * w * t);
    const double u =
        -a / (w * w) * (1.0 - decay * (std::cos(wd * t) + zeta() / root * std::sin(wd * t)));
    const double v = -a / wd * decay * std::sin(wd * t);
    // u'' = d/dt of u' = -(a/wd) e^{..}(wd cos wd t - zeta w sin wd t); absolute = u'' + a.
    const double absolute =
        a - a / wd * decay * (wd * std::cos(wd * t) - zeta() * w * std::sin(wd * t));
    ASSERT_NEAR(response.displacement[i], u, kExactTolerance * u_scale) << "sample " << i;
    ASSERT_NEAR(response.velocity[i], v, kExactTolerance * v_scale) << "sample " << i;
    // -(2 zeta w u' + w^2 u) adds two terms each exact to 1e-12 a.
    ASSERT_NEAR(response.absolute_acceleration[i], absolute, 2.0 * kExactTolerance * a)
        << "sample " << i;
  }
}

TEST_P(ExactAtAnyStep, LinearRampOfGroundAcceleration) {
  // a_g = r t from rest: u = -(r/w^2)(t - 2 zeta/w) + e^{-zeta w t}(C1 cos wd t + C2 sin wd t)
  // with C1 = -2 zeta r / w^3, C2 = r (1 - 2 zeta^2) / (w^2 wd) (u(0) = u'(0) = 0), derived by
  // substituting the particular solution a t + b into the equation of motion.
  const double r = 5000.0; // mm/s^3
  const std::size_t count = sample_count(GetParam().omega_dt);
  std::vector<double> record(count);
  for (std::size_t i = 0; i < count; ++i)
    record[i] = r * static_cast<double>(i) * dt();
  const SdofResponse response = sdof_response(record, dt(), oscillator());

  const double w = omega();
  const double wd = omega_d();
  const double z = zeta();
  const double c1 = -2.0 * z * r / (w * w * w);
  const double c2 = r * (1.0 - 2.0 * z * z) / (w * w * wd);
  std::vector<double> u(count), v(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) * dt();
    const double decay = std::exp(-z * w * t);
    const double c = std::cos(wd * t);
    const double s = std::sin(wd * t);
    u[i] = -(r / (w * w)) * (t - 2.0 * z / w) + decay * (c1 * c + c2 * s);
    v[i] = -r / (w * w) + decay * ((-z * w * c1 + wd * c2) * c + (-z * w * c2 - wd * c1) * s);
  }
  const double u_scale = largest_magnitude(u);
  const double v_scale = largest_magnitude(v);
  for (std::size_t i = 0; i < count; ++i) {
    ASSERT_NEAR(response.displacement[i], u[i], kExactTolerance * u_scale) << "sample " << i;
    ASSERT_NEAR(response.velocity[i], v[i], kExactTolerance * v_scale) << "sample " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(StepsAndDamping, ExactAtAnyStep, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return case_name(info.param);
                         });

TEST(RecurrenceCoefficients, EqualChoprasTable521WhereItsFormsAreAccurate) {
  // Chopra, Dynamics of Structures, Table 5.2.1 (m = 1, k = w^2), evaluated as printed. Its
  // C, D, C', D' subtract terms of order 1 to leave order (w dt)^2, so they carry a relative
  // round-off of about 1e-16 / (w dt)^2 (5e-8 at w dt = 1e-4): compared for w dt >= 0.05.
  for (const Case& tested : kCases) {
    if (tested.omega_dt < 0.05)
      continue;
    const double w = omega_of(kPeriod);
    const double h = tested.omega_dt / w;
    const double z = tested.zeta;
    const double q = std::sqrt(1.0 - z * z);
    const double wd = w * q;
    const double e = std::exp(-z * w * h);
    const double s = std::sin(wd * h);
    const double c = std::cos(wd * h);
    const double k = w * w;
    const RecurrenceCoefficients chopra{
        e * (z / q * s + c),
        e * s / wd,
        (2.0 * z / (w * h) +
         e * (((1.0 - 2.0 * z * z) / (wd * h) - z / q) * s - (1.0 + 2.0 * z / (w * h)) * c)) /
            k,
        (1.0 - 2.0 * z / (w * h) +
         e * ((2.0 * z * z - 1.0) / (wd * h) * s + 2.0 * z / (w * h) * c)) /
            k,
        -e * (w / q * s),
        e * (c - z / q * s),
        (-1.0 / h + e * ((w / q + z / (h * q)) * s + c / h)) / k,
        (1.0 - e * (z / q * s + c)) / (k * h)};
    const RecurrenceCoefficients exact = recurrence_coefficients({kPeriod, z}, h);
    // Scales: A, B' ~ 1; B ~ min(dt, 1/w); A' ~ min(w^2 dt, w); C, D ~ min(dt^2, 1/w^2);
    // C', D' ~ min(dt, 1/w).
    const double tolerance = kExactTolerance;
    const double force_scale = std::min(h * h, 1.0 / k);
    const double rate_scale = std::min(h, 1.0 / w);
    SCOPED_TRACE(case_name(tested));
    EXPECT_NEAR(exact.A, chopra.A, tolerance);
    EXPECT_NEAR(exact.B, chopra.B, tolerance * rate_scale);
    EXPECT_NEAR(exact.C, chopra.C, tolerance * force_scale);
    EXPECT_NEAR(exact.D, chopra.D, tolerance * force_scale);
    EXPECT_NEAR(exact.A_prime, chopra.A_prime, tolerance * std::min(k * h, w));
    EXPECT_NEAR(exact.B_prime, chopra.B_prime, tolerance);
    EXPECT_NEAR(exact.C_prime, chopra.C_prime, tolerance * rate_scale);
    EXPECT_NEAR(exact.D_prime, chopra.D_prime, tolerance * rate_scale);
  }
}

TEST(RecurrenceCoefficients, SmallStepsFollowTheTaylorSeriesOfTheUndampedForms) {
  // zeta = 0, x = w dt: Chopra's C = (sin x / x - cos x)/w^2 and D = (1 - sin x / x)/w^2 expand
  // to C = dt^2 (1/3 - x^2/30 + x^4/840 - ...), D = dt^2 (1/6 - x^2/120 + x^4/5040 - ...); the
  // next terms are below 1e-16 relative for x <= 1e-3, where the printed forms lose 1e-10.
  for (const double x : {1e-6, 1e-4, 1e-3}) {
    const double w = omega_of(kPeriod);
    const double h = x / w;
    const RecurrenceCoefficients exact = recurrence_coefficients({kPeriod, 0.0}, h);
    const double c_series = h * h * (1.0 / 3.0 - x * x / 30.0 + x * x * x * x / 840.0);
    const double d_series = h * h * (1.0 / 6.0 - x * x / 120.0 + x * x * x * x / 5040.0);
    EXPECT_NEAR(exact.C, c_series, 1e-14 * c_series) << "w dt " << x;
    EXPECT_NEAR(exact.D, d_series, 1e-14 * d_series) << "w dt " << x;
  }
}

TEST(SpectralAcceleration, StepLoadGivesTheDynamicAmplificationOfTheFirstPeak) {
  // For a step a, the largest |u| is at the first peak t = pi / wd:
  // |u|max = (a/w^2)(1 + e^{-zeta pi / sqrt(1 - zeta^2)}), so Sa = a (1 + e^{...}) (2a undamped).
  for (const double zeta : {0.0, 0.05, 0.2}) {
    const double period = 0.5;
    const double w = omega_of(period);
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    io::GroundMotion motion;
    motion.dt = kPi / wd / 50.0; // a sample on the peak
    motion.acceleration.assign(200, 1000.0);
    const double expected = 1000.0 * (1.0 + std::exp(-zeta * kPi / std::sqrt(1.0 - zeta * zeta)));
    EXPECT_NEAR(spectral_acceleration(motion, period, zeta), expected, 1e-10 * expected)
        << "zeta " << zeta;
  }
}

TEST(SpectralAcceleration, PeriodZeroIsThePeakGroundAcceleration) {
  io::GroundMotion motion{"test", 0.01, {0.0, 120.0, -340.5, 200.0, 0.0}};
  EXPECT_EQ(spectral_acceleration(motion, 0.0, 0.05), 340.5);
  const std::vector<double> periods{0.0, 0.0};
  EXPECT_EQ(response_spectrum(motion, periods, 0.05), (std::vector<double>{340.5, 340.5}));
}

TEST(SpectralAcceleration, RejectsInvalidOscillators) {
  io::GroundMotion motion{"test", 0.01, {0.0, 1.0, 0.0}};
  EXPECT_THROW(spectral_acceleration(motion, -0.1, 0.05), std::invalid_argument);
  EXPECT_THROW(spectral_acceleration(motion, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(spectral_acceleration(motion, 0.0, -0.01), std::invalid_argument);
  EXPECT_THROW(recurrence_coefficients({1.0, 0.05}, 0.0), std::invalid_argument);
  EXPECT_THROW(recurrence_coefficients({0.0, 0.05}, 0.01), std::invalid_argument);
}

TEST(LogSpacedPeriods, HundredPerDecadeFromTenMillisecondsToTenSeconds) {
  const std::vector<double> periods = log_spaced_periods(0.01, 10.0, 100);
  ASSERT_EQ(periods.size(), 301u);
  EXPECT_EQ(periods.front(), 0.01);
  EXPECT_EQ(periods.back(), 10.0);
  EXPECT_EQ(periods[100], 0.1);
  EXPECT_EQ(periods[200], 1.0);
  for (std::size_t k = 1; k < periods.size(); ++k)
    EXPECT_NEAR(periods[k] / periods[k - 1], std::pow(10.0, 0.01), 1e-13);
}

} // namespace
} // namespace brb::analysis
