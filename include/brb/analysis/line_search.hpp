// The projected-residual line search of a Newton step du from u (Crisfield, "Non-linear
// Finite Element Analysis of Solids and Structures", vol. 1, sec. 9.3; OpenSees' LineSearch
// algorithms): s(eta) = du . r(u + eta du), r the out-of-balance force. With r = -dPi/du for a
// potential Pi, s(eta) = -dPi(u + eta du)/d eta, so the root of s on (0, 1) is the step to
// the potential's least value along du (for dissipative laws, the incremental potential's).
//
// Why it is here: at a contact face or a friction link that changes state inside the step,
// the residual norm has a kink at the scale of the face's penetration (about 3e-4 mm for a
// plate core bearing 1.6 kN on mortar, a bearing stiffness of 5e6 N/mm), so backtracking on
// the residual norm fails down to 1/64 of the step while s(eta) stays continuous and changes
// sign where the potential is least. StaticAnalysis::newton uses it when backtracking has
// failed (README, "Passing limit points").
#pragma once

#include <cmath>

namespace brb::analysis {

/// Root of s(eta) on (0, 1), given s(0) = start_slope > 0 > s(1) = full_slope, by the
/// Illinois variant of regula falsi (an end kept twice in a row has its value halved, so the
/// bracket shrinks from both sides). `evaluate(eta, s)` takes the step eta (the caller's
/// trial state is then at it) and returns false if that state cannot be evaluated. Accepts
/// the first eta with |s(eta)| <= 0.5 s(0) (Crisfield's tolerance; OpenSees' default is 0.8),
/// within `max_evaluations`. Returns false, without calling `evaluate`, when s does not change
/// sign over the step (the least potential is not inside it, or du is not a descent direction:
/// s(0) <= 0), and false when an evaluation fails or no eta is accepted in time; the trial
/// state is then at the last eta tried.
template <class Evaluate>
bool projected_line_search(double start_slope, double full_slope, const Evaluate& evaluate,
                           int max_evaluations = 8) {
  if (!(start_slope > 0.0) || !(full_slope < 0.0))
    return false;
  double low = 0.0, high = 1.0;
  double low_slope = start_slope, high_slope = full_slope;
  int kept_side = 0; // +1: the last two evaluations replaced the low end; -1: the high end
  for (int evaluation = 0; evaluation < max_evaluations; ++evaluation) {
    const double step = high - high_slope * (high - low) / (high_slope - low_slope);
    double slope = 0.0;
    if (!evaluate(step, slope) || !std::isfinite(slope))
      return false;
    if (std::abs(slope) <= 0.5 * start_slope)
      return true;
    if (slope > 0.0) {
      low = step;
      low_slope = slope;
      if (kept_side == 1)
        high_slope *= 0.5;
      kept_side = 1;
    } else {
      high = step;
      high_slope = slope;
      if (kept_side == -1)
        low_slope *= 0.5;
      kept_side = -1;
    }
  }
  return false;
}

} // namespace brb::analysis
