// The exact response of a damped linear single-degree-of-freedom oscillator to a ground
// acceleration that is linear between samples (Nigam & Jennings 1969, "Calculation of response
// spectra from strong-motion earthquake records", BSSA 59(2); Chopra, Dynamics of Structures,
// sec. 5.2 "Interpolation of excitation"), and the response spectrum built on it.
//
// Per unit mass, with u the displacement relative to the ground:
//     u'' + 2 zeta omega u' + omega^2 u = p(t) = -a_g(t),   omega = 2 pi / T.
// Over a step h the state x = (u, u') obeys x' = M x + (0, 1) p with M = [0 1; -omega^2
// -2 zeta omega], so for p linear over the step the exact map is
//     x_{i+1} = e^{Mh} x_i + h phi1(Mh) b p_i + h phi2(Mh) b (p_{i+1} - p_i),   b = (0, 1),
// phi1(z) = (e^z - 1)/z, phi2(z) = (e^z - 1 - z)/z^2. Its entries are Chopra's coefficients
// (Table 5.2.1 with m = 1, k = omega^2):
//     u_{i+1}  = A  u_i + B  u'_i + C  p_i + D  p_{i+1}
//     u'_{i+1} = A' u_i + B' u'_i + C' p_i + D' p_{i+1}
// Chopra's closed forms of C, D, C', D' subtract terms of order 1 to leave terms of order
// (omega h)^2, which loses digits as omega h -> 0 (a relative error near 1e-10 at omega h =
// 0.006, e.g. T = 1 s and dt = 0.001 s). Here each coefficient comes from phi1 and phi2 at the
// complex eigenvalue z = h lambda, lambda = omega (-zeta + i sqrt(1 - zeta^2)): a 2x2 real
// matrix function is f(Mh) = Re f(z) I + (Im f(z) / Im z)(Mh - Re z I), and Re f(z) and
// Im f(z)/Im z come from the Taylor series when |z| = omega h < 1 (no subtraction) and from
// the closed forms above otherwise (no cancellation there). The map is therefore exact to
// round-off for any dt; it is unconditionally stable.
#pragma once

#include "brb/io/ground_motion.hpp"

#include <span>
#include <vector>

namespace brb::analysis {

/// A damped linear oscillator per unit mass.
struct LinearOscillator {
  double period = 1.0;        ///< natural period T, s (> 0)
  double damping_ratio = 0.0; ///< zeta, 0 <= zeta < 1 (underdamped)
};

/// Displacement relative to the ground and its rate.
struct OscillatorState {
  double displacement = 0.0;
  double velocity = 0.0;
};

/// Chopra's Table 5.2.1 coefficients (m = 1, k = omega^2, p = -a_g): see the top of the file.
struct RecurrenceCoefficients {
  double A = 0.0, B = 0.0, C = 0.0, D = 0.0;
  double A_prime = 0.0, B_prime = 0.0, C_prime = 0.0, D_prime = 0.0;
};

/// The exact one-step map of `oscillator` over a step `dt` (s > 0). Throws
/// std::invalid_argument for T <= 0, zeta outside [0, 1) or dt <= 0.
RecurrenceCoefficients recurrence_coefficients(const LinearOscillator& oscillator, double dt);

/// The state one step later, for ground accelerations `ground_now` at the start and
/// `ground_next` at the end of the step (any consistent units; mm/s^2 in brb).
OscillatorState advance(const RecurrenceCoefficients& step, const OscillatorState& state,
                        double ground_now, double ground_next);

/// Largest magnitudes over the sample times.
struct SdofPeaks {
  double displacement = 0.0;          ///< max |u|
  double velocity = 0.0;              ///< max |u'|
  double absolute_acceleration = 0.0; ///< max |u'' + a_g|
};

/// Histories at the sample times t_i = i dt (the first is the initial state), and their peaks.
struct SdofResponse {
  std::vector<double> displacement;          ///< u, relative to the ground
  std::vector<double> velocity;              ///< u', relative to the ground
  std::vector<double> absolute_acceleration; ///< u'' + a_g = -(2 zeta omega u' + omega^2 u)
  SdofPeaks peaks;
};

/// The response to the ground acceleration samples `ground` (at t_i = i dt, linear between
/// them) from `initial`. The record ends at its last sample: no free vibration is added.
SdofResponse sdof_response(std::span<const double> ground, double dt,
                           const LinearOscillator& oscillator, const OscillatorState& initial = {});

/// The peaks of sdof_response without storing the histories.
SdofPeaks sdof_peaks(std::span<const double> ground, double dt, const LinearOscillator& oscillator,
                     const OscillatorState& initial = {});

/// Pseudo-spectral acceleration Sa = omega^2 max|u| of an oscillator at rest when the record
/// starts, in the record's units (mm/s^2); period 0 gives the peak ground acceleration (a rigid
/// oscillator follows the ground). max|u| is that of the continuous response to the linearly
/// interpolated record: |u| is sampled at exact substeps no longer than T / 400 inside each
/// record step (peak missed by at most 3.1e-5 relative; at most 2000 substeps per step), not
/// only at the record's samples, which miss up to 1 - cos(omega dt / 2) of it. Throws
/// std::invalid_argument for a negative period or zeta outside [0, 1).
double spectral_acceleration(const io::GroundMotion& motion, double period, double damping_ratio);

/// spectral_acceleration at each of `periods`.
std::vector<double> response_spectrum(const io::GroundMotion& motion,
                                      std::span<const double> periods, double damping_ratio);

/// `per_decade` periods per decade from `shortest` to `longest` (both included when `longest`
/// is a whole number of steps away): T_k = shortest 10^(k / per_decade).
std::vector<double> log_spaced_periods(double shortest, double longest, int per_decade);

} // namespace brb::analysis
