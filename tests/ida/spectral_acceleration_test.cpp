// Acceptance of issue 7: the intensity measure Sa(T, 5 %) that scales the IDA records, from
// the exact piecewise-linear (Nigam-Jennings) integration of brb::analysis, against an
// independent integration written here: Newmark's average-acceleration method (Newmark 1959;
// Chopra, Dynamics of Structures, Table 5.4.2 with gamma = 1/2, beta = 1/4) on the linearly
// interpolated record, each record step cut into m substeps with dt / m <= T / 400, for each
// of the 10 shared AT2 records at T = 0.2, 0.5, 1.0 and 2.0 s. Issue 7 asks 0.5 %.
//
// Expected error of the reference: average acceleration lengthens the period by (omega h)^2 /
// 12 = 2e-5 at omega h = 2 pi / 400 and has no numerical damping, so it integrates an
// oscillator whose period is 2e-5 longer: a relative change of Sa of about 2e-5 times
// d ln Sa / d ln T, i.e. 1e-4 or less.
#include "brb/analysis/sdof_exact.hpp"
#include "brb/io/ground_motion.hpp"
#include "support/shared_records.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

namespace brb {
namespace {

constexpr double kDamping = 0.05;

/// max |u| of u'' + 2 zeta omega u' + omega^2 u = -a_g(t) from rest, a_g linear between the
/// record's samples, by Newmark's average acceleration with m substeps per record step
/// (dt / m <= T / 400), over every substep point.
double newmark_peak_displacement(std::span<const double> ground, double dt, double period) {
  const double omega = 2.0 * std::numbers::pi / period;
  const double stiffness = omega * omega;
  const double damping = 2.0 * kDamping * omega;
  const auto substeps = static_cast<int>(std::ceil(dt / (period / 400.0)));
  const double h = dt / substeps;
  // Chopra Table 5.4.2 (m = 1): a1 = 4/h^2 + 2c/h, a2 = 4/h + c, a3 = 1, k_hat = k + a1.
  const double a1 = 4.0 / (h * h) + 2.0 * damping / h;
  const double a2 = 4.0 / h + damping;
  const double k_hat = stiffness + a1;
  double u = 0.0, v = 0.0;
  double a = -ground[0]; // u'' at rest: -a_g(0)
  double peak = 0.0;
  for (std::size_t i = 0; i + 1 < ground.size(); ++i) {
    for (int j = 1; j <= substeps; ++j) {
      const double s = static_cast<double>(j) / substeps;
      const double load = -((1.0 - s) * ground[i] + s * ground[i + 1]);
      const double u_next = (load + a1 * u + a2 * v + a) / k_hat;
      const double du = u_next - u;
      const double v_next = 2.0 / h * du - v;
      const double a_next = 4.0 / (h * h) * du - 4.0 / h * v - a;
      u = u_next;
      v = v_next;
      a = a_next;
      peak = std::max(peak, std::abs(u));
    }
  }
  return peak;
}

// Issue 7's tolerance is 0.5 %. The expected agreement is far better: the reference's period
// error (2e-5) times d ln Sa / d ln T (a few), plus both peak samplings (3e-5 each), so the
// largest difference is also held to 1e-3 (measured: 9.9e-5, RSN753_LOMAP_CLS000 at T = 1 s).
TEST(SpectralAcceleration, SharedRecordsAgreeWithAnIndependentNewmarkIntegration) {
  const auto records = test::shared_at2_records();
  ASSERT_EQ(records.size(), 10u);
  double largest = 0.0;
  for (const auto& file : records) {
    const io::GroundMotion motion = io::read_peer_at2(file);
    for (const double period : {0.2, 0.5, 1.0, 2.0}) {
      const double omega = 2.0 * std::numbers::pi / period;
      const double exact = analysis::spectral_acceleration(motion, period, kDamping);
      const double reference =
          omega * omega * newmark_peak_displacement(motion.acceleration, motion.dt, period);
      EXPECT_NEAR(exact / reference, 1.0, 0.005) << motion.name << " T = " << period;
      largest = std::max(largest, std::abs(exact / reference - 1.0));
    }
  }
  EXPECT_LT(largest, 1e-3);
}

// A step a_g = a from rest, undamped: u = -(a / omega^2)(1 - cos omega t) (Chopra eq. 4.3.2),
// |u| peaks at t = T / 2 with 2 a / omega^2, so Sa = 2 a. With dt = T / 5 the peak falls
// halfway between samples 2 and 3, where the samples alone give (1 - cos(4 pi / 5)) a =
// 1.809 a; the continuous peak is 2 a to the sampling bound 1 - cos(pi / 400) = 3.1e-5.
TEST(SpectralAcceleration, PeakBetweenRecordSamplesIsFound) {
  const double period = 0.5;
  io::GroundMotion motion;
  motion.dt = period / 5.0;
  motion.acceleration.assign(6, 1000.0); // up to t = T
  EXPECT_NEAR(analysis::spectral_acceleration(motion, period, 0.0), 2000.0, 2000.0 * 3.1e-5);
}

} // namespace
} // namespace brb
