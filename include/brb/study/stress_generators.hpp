// Deterministic generators of the stress cases (issue 9). Randomness comes from
// std::mt19937_64, whose output sequence the C++ standard fixes; uniform numbers are taken
// from its raw output (the top 53 bits over 2^53), not from std::uniform_real_distribution,
// whose algorithm is left to the library. So a seed gives the same case with any compiler.
#pragma once

#include "brb/io/ground_motion.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/study/stress_case.hpp"

#include <cstdint>
#include <random>
#include <vector>

namespace brb::study {

/// A uniform number in [0, 1) from the engine's next output: (output >> 11) x 2^-53.
double unit_uniform(std::mt19937_64& engine);

/// Turning points (mm) of a random deformation history with `reversals` reversals and
/// amplitudes up to `max_amplitude` (mm), from the seed. Distribution: the first leg goes
/// into tension when the first uniform number u0 < 1/2, else into compression; then the
/// legs alternate in direction (each turning point is a reversal) and each turning point
/// is uniform between the previous one and the limit ahead:
///   going up:   t_k = t_{k-1} + u_k (A - t_{k-1}),
///   going down: t_k = t_{k-1} - u_k (A + t_{k-1}),   u_k uniform in [0, 1), t_0 = 0,
/// so every t_k lies in (-A, A), legs range from nearly nothing (a reversal right after a
/// reversal) to nearly 2 A. The last point returns to 0. Throws std::invalid_argument for
/// reversals < 1 or a max_amplitude that is not > 0.
std::vector<double> random_turning_points(std::uint64_t seed, int reversals, double max_amplitude);

/// The points of a deformation history through `turning_points` (mm) in legs of equal steps
/// of at most `max_step` (mm), starting at 0 (io::history_protocol).
std::vector<double> history_points(const std::vector<double>& turning_points, double max_step);

/// The nominal yield deformation dy (mm) and yield force P_y (N) of a brace (the values
/// `brb cyclic` prints: series flexibility of the zones between the outer nodes).
struct BraceYield {
  double deformation = 0.0;
  double force = 0.0;
  double yielding_length = 0.0; ///< mm
  /// mm: deformation of the elastic end zones (connection, transition) at P_y.
  double end_zone_deformation = 0.0;
};
BraceYield brace_yield(const model::BraceSpec& spec);

/// The deformation (mm, negative) at which the yielding core's mean strain reaches
/// -core_strain: core_strain x L_y, plus the end zones' elastic shortening at 1.5 P_y (an
/// upper bound of the force a hardened core carries there), so the core gets at least there.
double compression_target(const BraceYield& yield, double core_strain);

/// `brace` at `fidelity` with `core_elements` elements along the yielding core (the other
/// counts kept): the cheap `full` models of the short suite use 4.
model::BraceSpec brace_variant(model::BraceSpec brace, model::Fidelity fidelity, int core_elements);

/// Near-singular braces (issue 9): the casing of `brace` (required) with a clearance of
/// `gap` mm per side (1e-6: contact closes at once, the penalty springs start at the knee).
model::BraceSpec with_gap(model::BraceSpec brace, double gap);
/// ... with a Coulomb coefficient `friction` (1.0: friction as large as the bearing force).
model::BraceSpec with_friction(model::BraceSpec brace, double friction);
/// ... with the casing tube (outer size and wall) scaled so that the casing assembly's Euler
/// load pi^2 E I / L_y^2 (model::casing_assembly_flexural_rigidity: tube + fill + core,
/// weaker axis) is `euler_ratio` x P_y, found by bisection on the scale to 1e-6 of the
/// ratio. Throws std::invalid_argument when no scale gets there (the tube cannot shrink
/// below the core's opening, or a steel-less casing).
model::BraceSpec with_casing_euler_ratio(model::BraceSpec brace, double euler_ratio);
/// P_E / P_y of the casing assembly (as model::choose_auto_fidelity computes it).
double casing_euler_ratio(const model::BraceSpec& brace);

/// The frame case: `frame` with braces at `braces`, under the first `duration` s of `motion`
/// (mm/s^2; the whole record when duration <= 0) times `scale`.
FrameStress frame_stress(const model::FrameSpec& frame, const std::string& source,
                         frame::BraceOverride braces, const io::GroundMotion& motion, double scale,
                         double duration);

} // namespace brb::study
