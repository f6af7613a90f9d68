// The `auto` fidelity of a brace in a frame (DESIGN.md section 4): the cheapest level whose
// error stays within a stated bound for the brace. `auto` takes `truss` only where the truss is
// known to be accurate (the run-time-against-error study, issue 9, found it within the bound
// below wherever it picks it) and `full` wherever the brace could show what a truss cannot
// (global buckling, casing failure, friction overstrength in compression):
//   truss when all hold, else full:
//   1. the brace has a casing with a steel tube (a bare core buckles; a mortar-only casing
//      can crack and crush: BRB_SOURCE_FACTS section 6, small BRB cases 1 and 4);
//   2. the casing assembly's Euler load P_E = pi^2 E I / L_y^2 (tube + fill + core, about the
//      weaker axis, pinned over the yielding length) is at least kEulerMargin x P_y.
//      kEulerMargin = 1.5 x 1.5: Watanabe et al. (1988) ask P_E / P_y >= 1.5 of the
//      restrainer; the 1.5 on top covers the adjusted compression strength beta omega P_y
//      of AISC 341 qualified braces (typically 1.3-1.6);
//   3. friction coefficient <= 0.15 (the source's 0.1 and common unbonding layers): the
//      truss's steel law is symmetric, and friction raises the compression force.
// Measured (bench/PARETO.md, `brb bench pareto`, session 17): `auto` = truss on Girona D3,
// Girona D1 (a case not used to derive the rule), brbf3 and brbf9, full on the small BRB's case
// 3 (no tube; not used to derive it). Against the finest full setting of each, the worst of loop
// energy, peak forces, beta (components) or peak drift, residual drift, brace CID (frames):
// 1.94 % (D3, against 64 core elements), 1.16 % (D1), 1.92 % (brbf3, its 16-element braces at dt
// 0.005 s), 2.14 % (brbf9, its 16-element braces; the story-2 peak drift: near it, at t = 1.84 s,
// the 16-element story-2 brace's compression dips 2.7 % below the 4-element brace's in a jump to a
// higher buckling mode, which a truss cannot show), 0.03 % (case 3): kAutoErrorBound = 2.5 %. It
// was 2 % while brbf9's reference was its 4-element braces (truss 0.47 % off them), before its
// 16-element run completed.
#pragma once

#include "brb/model/brace_spec.hpp"

#include <string>

namespace brb::model {

struct FidelityChoice {
  Fidelity fidelity = Fidelity::full;
  std::string reason;       ///< which condition decided, with its numbers
  double euler_ratio = 0.0; ///< P_E / P_y (0 without casing)
};

inline constexpr double kEulerMargin = 2.25;
inline constexpr double kTrussFrictionLimit = 0.15;
/// The stated error bound of `auto` against the finest `full` setting, on every metric of the
/// run-time-against-error study (bench/PARETO.md; measured above).
inline constexpr double kAutoErrorBound = 0.025;

/// E I (N mm^2) of casing tube + mortar fill + core about the weaker section axis,
/// from their fiber meshes.
double casing_assembly_flexural_rigidity(const BraceSpec& spec);

/// The rule above for a brace whose fidelity is `auto`.
FidelityChoice choose_auto_fidelity(const BraceSpec& spec);

} // namespace brb::model
