// Calibration of a brace's core steel on a laboratory record (issue 4): the steel parameters
// (fy, two Chaboche back-stresses, Voce isotropic saturation) that minimise the normalised RMS
// force error of a fast axial model of the brace driven through the record's deformation.
//
// Fast model (AxialBraceIdealisation): the yielding core in series with the elastic end
// zones. The end zones (transition, connection) stay elastic, so for a deformation delta the
// core strain eps solves
//     delta = eps L_y + N f_e,   N = A_c sigma(eps),   f_e = sum over end zones 2 L_i / (E A_i),
// with sigma the closed-form uniaxial steel law (SteelUniaxial): one scalar, monotonic
// equation per point, solved by safeguarded Newton. No buckling, contact or friction: the
// axial steel response only, a few milliseconds per history.
#pragma once

#include "brb/material/steel_parameters.hpp"
#include "brb/model/brace_spec.hpp"

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace brb::validation {

/// The brace seen axially: core area and yielding length, and the flexibility of its end
/// zones.
struct AxialBraceIdealisation {
  double core_area = 0.0;            ///< A_c (mm^2)
  double yielding_length = 0.0;      ///< L_y (mm)
  double end_zone_flexibility = 0.0; ///< sum 2 L_i / (E A_i) over transition and connection (mm/N)
  double youngs_modulus = 0.0;       ///< E (MPa)

  static AxialBraceIdealisation of(const model::BraceSpec& brace);
  /// Axial deformation at first yield for a yield stress fy (MPa): fy A_c (L_y / (E A_c) +
  /// f_e), the same series sum as BraceModel::yield_deformation.
  double yield_deformation(double yield_stress) const;
};

/// Axial force (N) of the fast model at each deformation (mm) of the history, from the virgin
/// state (damage is switched off: calibration targets the hysteresis, not fracture).
/// Throws std::runtime_error if the scalar equation of a point cannot be solved.
std::vector<double> fast_brace_forces(const material::SteelParameters& steel,
                                      const AxialBraceIdealisation& brace,
                                      std::span<const double> deformation);

/// The parameters calibrated and their bounds. fy in [0.7, 1.5] x the starting fy (linear);
/// the others on a logarithmic scale: C1 in [100, 2e5] MPa, gamma1 in [1, 2000],
/// C2 in [10, 2e4] MPa, gamma2 in [0.1, 200], Q in [0.1, 400] MPa, b in [0.1, 100].
/// E, nu, H_kin and H_iso are kept from the starting parameters.
struct CalibrationBounds {
  static constexpr int kCount = 7; ///< fy, C1, gamma1, C2, gamma2, Q, b
  double lower[kCount];
  double upper[kCount];
  bool logarithmic[kCount];

  static CalibrationBounds for_start(const material::SteelParameters& start);
};

/// Which test points the objective uses.
enum class CalibrationSide {
  all,     ///< every compared point
  tension, ///< points where the test force is >= 0: the compression side of a real brace
           ///< carries friction and contact forces that the fast model has not got
};

struct CalibrationOptions {
  CalibrationSide side = CalibrationSide::tension;
  int max_evaluations = 3000; ///< 0: evaluate the starting parameters only
  int restarts = 3;           ///< fresh simplices around the best point after convergence
};

struct CalibrationResult {
  material::SteelParameters steel;
  double start_objective = 0.0; ///< normalised RMS error of the starting parameters
  double objective = 0.0;       ///< the same for the calibrated ones (on `side`)
  double error_all = 0.0;       ///< normalised RMS error over all compared points
  double error_tension = 0.0;   ///< over the tension-side points
  int evaluations = 0;
  std::vector<double> model_force; ///< calibrated fast-model force at every history point
};

/// With options.max_evaluations == 0, evaluates `start` unchanged. Otherwise calibrates `start`'s
/// fy, Chaboche and Voce terms (two back-stresses and one Voce term in the result, whatever `start`
/// has) so that the fast model of `brace` driven through `deformation` matches `test_force` at the
/// points where `compared` is true, by minimising the normalised RMS force error
/// (record_comparison.hpp) with Nelder-Mead (nelder_mead). Deterministic: the start is `start`'s fy
/// and fixed mid-range hardening values.
CalibrationResult
calibrate_steel(const material::SteelParameters& start, const AxialBraceIdealisation& brace,
                std::span<const double> deformation, std::span<const double> test_force,
                const std::vector<bool>& compared, const CalibrationOptions& options);

/// Result of nelder_mead.
struct SimplexMinimum {
  std::vector<double> point;
  double value = 0.0;
  int evaluations = 0;
};

/// Unconstrained Nelder-Mead minimisation of `objective` (Nelder & Mead 1965, with the
/// standard coefficients: reflection 1, expansion 2, contraction 1/2, shrink 1/2, as in
/// Lagarias et al. 1998) from `start`, initial simplex `start + step e_i`. Stops when the
/// simplex's values agree within `value_tolerance` (absolute) or after `max_evaluations`;
/// then restarts up to `restarts` times from a fresh simplex around the best point (a
/// collapsed simplex is a known failure mode of the method). Bounds are handled by the
/// caller through a transformation (calibrate_steel: logistic maps). Deterministic.
SimplexMinimum nelder_mead(const std::function<double(const std::vector<double>&)>& objective,
                           std::vector<double> start, double step, double value_tolerance,
                           int max_evaluations, int restarts);

} // namespace brb::validation
