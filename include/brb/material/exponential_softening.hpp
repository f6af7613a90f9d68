// Exponential damage softening regularised by the characteristic length (Oliver et al.
// 1990; BRB_SOURCE_FACTS sections 2 and 3), shared by the steel and the mortar law.
//
//   d = G(r) = 1 - (r0 / r) exp(A (1 - r / r0)),   r0 = f / sqrt(E),
//   A = 1 / (Gf E / (lc f^2) - 1/2),
//
// so that a material point that softens completely dissipates Gf / lc per unit volume
// through damage (integral of psi0 dd with psi0 = r^2 / 2 on the loading branch), whatever
// the element size. A > 0 needs lc < 2 Gf E / f^2.
#pragma once

#include <cmath>

namespace brb::material {

/// What to do when lc is too long for the softening (A <= 0: snap-back at the point).
enum class LongElementRule {
  reject,         ///< throw ParameterError on "lc" (input files: the user chose lc)
  lower_strength, ///< lower the onset stress to sqrt(Gf E / lc) (A = 2), keeping Gf / lc
};

class ExponentialSoftening {
public:
  /// onset_stress f > 0, E > 0, fracture_energy Gf > 0 (N/mm), characteristic_length lc > 0 (mm).
  static ExponentialSoftening from_fracture_energy(double onset_stress, double youngs_modulus,
                                                   double fracture_energy,
                                                   double characteristic_length,
                                                   LongElementRule rule);

  /// The longest lc for which A > 0: 2 Gf E / f^2.
  static double max_characteristic_length(double onset_stress, double youngs_modulus,
                                          double fracture_energy) {
    return 2.0 * fracture_energy * youngs_modulus / (onset_stress * onset_stress);
  }

  double initial_threshold() const { return initial_threshold_; }
  double softening_parameter() const { return softening_parameter_; }
  /// The onset stress actually used (lower than asked when the fallback rule applied).
  double onset_stress() const { return onset_stress_; }
  /// True when the lower_strength rule changed the onset stress; callers warn once.
  bool strength_lowered() const { return strength_lowered_; }

  /// Integrity 1 - G(r) = (r0 / r) exp(A (1 - r / r0)), evaluated directly: 1 - G(r)
  /// cancels to exactly 0 once d rounds to 1, which would leave a point with no stiffness.
  double integrity(double threshold) const {
    const double ratio = threshold / initial_threshold_;
    return std::exp(softening_parameter_ * (1.0 - ratio)) / ratio;
  }

  /// Residual strength (1 - G(r)) r / r0 = exp(A (1 - r / r0)) as a fraction of the onset
  /// stress: 1 up to the peak (r <= r0, or r = 0 for a state never loaded), then falling. On the
  /// loading branch the stress is (1 - d) E eps with r = sqrt(E) eps, so this is sigma / f.
  /// Unlike d it is objective: with A ~ lc f^2 / (Gf E) for lc well below the longest, the
  /// softening branch is sigma / f = exp(-f w / Gf) in the crack opening w = (eps - eps0) lc,
  /// whatever the element size, while d at the same w grows with 1 / lc.
  double residual_strength(double threshold) const {
    if (threshold <= initial_threshold_)
      return 1.0;
    return std::exp(softening_parameter_ * (1.0 - threshold / initial_threshold_));
  }

  /// G(r) for r >= r0 (0 at r0, tends to 1).
  double damage(double threshold) const { return 1.0 - integrity(threshold); }

  /// Energy released per unit volume while the threshold grows from r_from to r_to on the
  /// loading branch (psi0 = r^2 / 2 there): the integral of r^2/2 dG, in closed form
  ///   I(r) = -r0 exp(A (1 - r/r0)) (r/2 + r0/A),  I(inf) - I(r0) = Gf / lc.
  /// Exact for any step size (a rectangle rule psi0(r_to) dG over-counts large steps).
  double released_energy(double from, double to) const {
    const auto primitive = [this](double r) {
      return -initial_threshold_ * std::exp(softening_parameter_ * (1.0 - r / initial_threshold_)) *
             (0.5 * r + initial_threshold_ / softening_parameter_);
    };
    return primitive(to) - primitive(from);
  }

  /// dG/dr = (r0 / r) exp(A (1 - r/r0)) (1/r + A/r0).
  double damage_slope(double threshold) const {
    const double ratio = threshold / initial_threshold_;
    return std::exp(softening_parameter_ * (1.0 - ratio)) / ratio *
           (1.0 / threshold + softening_parameter_ / initial_threshold_);
  }

private:
  double initial_threshold_ = 0.0;
  double softening_parameter_ = 0.0;
  double onset_stress_ = 0.0;
  bool strength_lowered_ = false;
};

} // namespace brb::material
