#include "brb/analysis/sdof_exact.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace brb::analysis {
namespace {

/// Terms of the Taylor series of phi1, phi2 for |z| < 1: the last, |z|^25 / 25!, is below
/// 1e-25 of the sum.
constexpr int kSeriesTerms = 26;

/// Re f(z) and Im f(z) / Im z of a function f with real Taylor coefficients, for z in the
/// upper half plane; then f(Mh) = real I + imaginary_over_im_z (Mh - Re z I).
struct RealMatrixFunction {
  double real = 0.0;
  double imaginary_over_im_z = 0.0;
};

struct PhiFunctions {
  RealMatrixFunction phi1; ///< (e^z - 1)/z
  RealMatrixFunction phi2; ///< (e^z - 1 - z)/z^2
};

/// phi1, phi2 by their Taylor series sum_j z^j / (j + k)!. With w_j = z^j and
/// q_j = Im(w_j) / Im(z), Im(w_{j+1}) = Re(w_j) Im z + Im(w_j) Re z gives the division-free
/// recurrence q_{j+1} = Re(w_j) + q_j Re z, q_0 = 0, so Im phi / Im z needs no subtraction.
PhiFunctions phi_series(std::complex<double> z) {
  PhiFunctions phi;
  std::complex<double> power = 1.0; // z^j
  double ratio = 0.0;               // Im(z^j) / Im(z)
  double factorial_1 = 1.0;         // (j + 1)!
  double factorial_2 = 2.0;         // (j + 2)!
  for (int j = 0; j < kSeriesTerms; ++j) {
    phi.phi1.real += power.real() / factorial_1;
    phi.phi1.imaginary_over_im_z += ratio / factorial_1;
    phi.phi2.real += power.real() / factorial_2;
    phi.phi2.imaginary_over_im_z += ratio / factorial_2;
    ratio = power.real() + ratio * z.real();
    power *= z;
    factorial_1 *= static_cast<double>(j + 2);
    factorial_2 *= static_cast<double>(j + 3);
  }
  return phi;
}

/// phi1, phi2 by their closed forms, accurate for |z| >= 1 (no cancellation beyond a few
/// ulps). Im z = omega h sqrt(1 - zeta^2) > 0 here.
PhiFunctions phi_closed_form(std::complex<double> z) {
  const std::complex<double> phi1 = (std::exp(z) - 1.0) / z;
  const std::complex<double> phi2 = (phi1 - 1.0) / z;
  return {{phi1.real(), phi1.imag() / z.imag()}, {phi2.real(), phi2.imag() / z.imag()}};
}

void check_oscillator(const LinearOscillator& oscillator) {
  if (!(oscillator.period > 0.0) || !std::isfinite(oscillator.period)) {
    throw std::invalid_argument("linear oscillator: the period must be > 0 s, got " +
                                std::to_string(oscillator.period));
  }
  if (!(oscillator.damping_ratio >= 0.0 && oscillator.damping_ratio < 1.0)) {
    throw std::invalid_argument("linear oscillator: the damping ratio must be in [0, 1), got " +
                                std::to_string(oscillator.damping_ratio));
  }
}

double circular_frequency(const LinearOscillator& oscillator) {
  return 2.0 * std::numbers::pi / oscillator.period;
}

/// Runs the recurrence over the record, calling visit(u, u', absolute acceleration) at every
/// sample, the initial one included.
template <class Visit>
void integrate(std::span<const double> ground, double dt, const LinearOscillator& oscillator,
               const OscillatorState& initial, Visit&& visit) {
  const RecurrenceCoefficients step = recurrence_coefficients(oscillator, dt);
  const double omega = circular_frequency(oscillator);
  const double omega_squared = omega * omega;
  const double damping = 2.0 * oscillator.damping_ratio * omega;
  OscillatorState state = initial;
  for (std::size_t i = 0; i < ground.size(); ++i) {
    if (i > 0)
      state = advance(step, state, ground[i - 1], ground[i]);
    // u'' + a_g = -(2 zeta omega u' + omega^2 u): the equation of motion.
    visit(state.displacement, state.velocity,
          -(damping * state.velocity + omega_squared * state.displacement));
  }
}

/// Points per natural period at which spectral_acceleration samples |u|: a harmonic's peak
/// falls at most half a spacing from a sample, so it is missed by at most 1 - cos(pi / 400)
/// = 3.1e-5 (relative).
constexpr double kPeakSamplesPerPeriod = 400.0;
/// At most this many substeps per record step (periods below dt * 400 / 2000 = dt / 5 are
/// sampled more coarsely; such stiff oscillators follow the ground).
constexpr double kMaxSubsteps = 2000.0;

/// max |u| of the oscillator at rest at the start, over substeps dt / m <= T / 400 of each
/// record step. The ground acceleration is linear between record samples, so interpolating it
/// at the substeps changes nothing in the excitation and the exact map stays exact: the peak
/// is that of the continuous response to within the sampling bound above. Sampling at the
/// record's own steps only misses up to 1 - cos(omega dt / 2) (5 % at T = 0.2 s, dt = 0.02 s;
/// 3.4 % measured for elCentro, tests/ida/spectral_acceleration_test.cpp).
double continuous_peak_displacement(std::span<const double> ground, double dt,
                                    const LinearOscillator& oscillator) {
  const double substeps =
      std::clamp(std::ceil(dt * kPeakSamplesPerPeriod / oscillator.period), 1.0, kMaxSubsteps);
  const auto count = static_cast<int>(substeps);
  const RecurrenceCoefficients step = recurrence_coefficients(oscillator, dt / substeps);
  OscillatorState state;
  double peak = 0.0;
  for (std::size_t i = 1; i < ground.size(); ++i) {
    const double start = ground[i - 1];
    const double rise = ground[i] - start;
    double now = start;
    for (int j = 1; j <= count; ++j) {
      const double next = j == count ? ground[i] : start + rise * (j / substeps);
      state = advance(step, state, now, next);
      peak = std::max(peak, std::abs(state.displacement));
      now = next;
    }
  }
  return peak;
}

} // namespace

RecurrenceCoefficients recurrence_coefficients(const LinearOscillator& oscillator, double dt) {
  check_oscillator(oscillator);
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument("linear oscillator: the time step must be > 0 s");
  const double zeta = oscillator.damping_ratio;
  const double omega = circular_frequency(oscillator);
  const double h = dt;
  const double omega_h = omega * h;
  const double root = std::sqrt(1.0 - zeta * zeta);
  const std::complex<double> z(-zeta * omega_h, root * omega_h); // h lambda

  // e^{Mh}: Re e^z = e^{-zeta omega h} cos(omega_D h), Im e^z / Im z = e^{..} sin(x)/x.
  const double decay = std::exp(z.real());
  const double damped_angle = z.imag();
  const double exp_real = decay * std::cos(damped_angle);
  const double exp_ratio =
      damped_angle == 0.0 ? decay : decay * std::sin(damped_angle) / damped_angle;
  const PhiFunctions phi = std::abs(z) < 1.0 ? phi_series(z) : phi_closed_form(z);

  // f(Mh) = Re f I + (Im f / Im z) h (M + zeta omega I), M + zeta omega I = [zeta omega, 1;
  // -omega^2, -zeta omega].
  const double zeta_omega_h = zeta * omega_h;
  RecurrenceCoefficients c;
  c.A = exp_real + exp_ratio * zeta_omega_h;
  c.B = exp_ratio * h;
  c.A_prime = -exp_ratio * h * omega * omega;
  c.B_prime = exp_real - exp_ratio * zeta_omega_h;
  // Forcing: (Gamma0 - Gamma1) p_i + Gamma1 p_{i+1}, Gamma_k = h phi_k(Mh) b.
  const double s1 = phi.phi1.imaginary_over_im_z;
  const double s2 = phi.phi2.imaginary_over_im_z;
  c.C = h * h * (s1 - s2);
  c.D = h * h * s2;
  c.C_prime = h * ((phi.phi1.real - phi.phi2.real) - zeta_omega_h * (s1 - s2));
  c.D_prime = h * (phi.phi2.real - zeta_omega_h * s2);
  return c;
}

OscillatorState advance(const RecurrenceCoefficients& step, const OscillatorState& state,
                        double ground_now, double ground_next) {
  const double p_now = -ground_now; // p = -a_g per unit mass
  const double p_next = -ground_next;
  return {step.A * state.displacement + step.B * state.velocity + step.C * p_now + step.D * p_next,
          step.A_prime * state.displacement + step.B_prime * state.velocity + step.C_prime * p_now +
              step.D_prime * p_next};
}

SdofResponse sdof_response(std::span<const double> ground, double dt,
                           const LinearOscillator& oscillator, const OscillatorState& initial) {
  SdofResponse response;
  response.displacement.reserve(ground.size());
  response.velocity.reserve(ground.size());
  response.absolute_acceleration.reserve(ground.size());
  integrate(ground, dt, oscillator, initial, [&](double u, double v, double a) {
    response.displacement.push_back(u);
    response.velocity.push_back(v);
    response.absolute_acceleration.push_back(a);
    response.peaks.displacement = std::max(response.peaks.displacement, std::abs(u));
    response.peaks.velocity = std::max(response.peaks.velocity, std::abs(v));
    response.peaks.absolute_acceleration =
        std::max(response.peaks.absolute_acceleration, std::abs(a));
  });
  return response;
}

SdofPeaks sdof_peaks(std::span<const double> ground, double dt, const LinearOscillator& oscillator,
                     const OscillatorState& initial) {
  SdofPeaks peaks;
  integrate(ground, dt, oscillator, initial, [&](double u, double v, double a) {
    peaks.displacement = std::max(peaks.displacement, std::abs(u));
    peaks.velocity = std::max(peaks.velocity, std::abs(v));
    peaks.absolute_acceleration = std::max(peaks.absolute_acceleration, std::abs(a));
  });
  return peaks;
}

double spectral_acceleration(const io::GroundMotion& motion, double period, double damping_ratio) {
  if (!(period >= 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("spectral acceleration: the period must be >= 0 s, got " +
                                std::to_string(period));
  }
  if (period == 0.0) {
    check_oscillator({1.0, damping_ratio});
    return motion.peak_acceleration();
  }
  const LinearOscillator oscillator{period, damping_ratio};
  const double omega = circular_frequency(oscillator);
  return omega * omega * continuous_peak_displacement(motion.acceleration, motion.dt, oscillator);
}

std::vector<double> response_spectrum(const io::GroundMotion& motion,
                                      std::span<const double> periods, double damping_ratio) {
  std::vector<double> spectrum;
  spectrum.reserve(periods.size());
  for (const double period : periods)
    spectrum.push_back(spectral_acceleration(motion, period, damping_ratio));
  return spectrum;
}

std::vector<double> log_spaced_periods(double shortest, double longest, int per_decade) {
  if (!(shortest > 0.0) || !(longest >= shortest) || per_decade < 1) {
    throw std::invalid_argument("log_spaced_periods: expected 0 < shortest <= longest and at "
                                "least one period per decade");
  }
  // The count is rounded so that a longest period a whole number of steps away is included
  // despite the rounding of log10.
  const double steps = std::log10(longest / shortest) * per_decade;
  const auto count = static_cast<int>(std::floor(steps + 1e-9)) + 1;
  std::vector<double> periods;
  periods.reserve(static_cast<std::size_t>(count));
  // 10^(log10 T0 + k / n): whole decades from a power of ten come out exact (0.01, 0.1, ...).
  const double first_exponent = std::log10(shortest);
  for (int k = 0; k < count; ++k) {
    periods.push_back(std::pow(10.0, first_exponent + static_cast<double>(k) / per_decade));
  }
  return periods;
}

} // namespace brb::analysis
