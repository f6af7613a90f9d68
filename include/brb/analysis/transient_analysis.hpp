// TransientAnalysis: nonlinear time-history analysis of a Model on the equations of a
// DofMap, in relative coordinates under uniform ground acceleration:
//   M a + C v + f_int(u) = f_static - M sum_c r_c a_g,c(t)
// (r_c: influence vector of component c). Implicit Newmark (average acceleration,
// gamma = 1/2, beta = 1/4) or HHT-alpha (Hilber, Hughes, Taylor 1977; alpha in [-1/3, 0],
// gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4), Newton-Raphson with a backtracking line
// search. A failed step is retried: halved substeps down to a floor, then the other
// algorithms (modified Newton on the tangent of the committed state, then Broyden-type
// secant updates of its inverse);
// every fallback is recorded. Nothing is committed until a (sub)step converges.
//
// Static load steps (gravity, before the dynamic run) use the same equations without
// inertia and damping; their load is then held as f_static.
//
// Energy (relative formulation, Uang & Bertero 1990), integrated by the trapezoidal rule
// over converged steps: input E_I = -sum_c int (M r_c a_g,c)^T du, kinetic 1/2 v^T M v,
// damping int v^T C du, element stored + dissipated energy, static work int f_static^T du.
//   error = E_I + W_static - (kinetic + damping + stored + dissipated)
#pragma once

#include "brb/model/assembler.hpp"
#include "brb/model/dof_map.hpp"
#include "brb/model/model.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace brb::analysis {

enum class TimeIntegrator { newmark, hht };

struct TransientSettings {
  TimeIntegrator integrator = TimeIntegrator::newmark;
  double hht_alpha = 0.0; ///< in [-1/3, 0]; 0 is Newmark average acceleration
  int max_iterations = 25;
  /// Converged when |residual|_inf <= tolerance * (largest element force + largest
  /// inertia/damping/external force + 1 N + round-off floor) after at least one Newton
  /// correction (so a linear system is solved to round-off, never accepted at its predictor).
  /// Plus a round-off floor per equation: position_round_off x sum_j |K_ij| x length_j
  /// (length_j: the model's size for a translation, 1 rad for a rotation), the force that
  /// the positions' relative round-off makes through the element tangent T^T K T.
  double relative_force_tolerance = 1e-8;
  double position_round_off = 1e-14;
  bool line_search = true;
  int max_halvings = 8; ///< substep floor: dt / 2^max_halvings
  /// At the floor: iterations allowed to modified Newton and to the Broyden update.
  int fallback_iterations = 200;
};

/// A uniform ground acceleration component along a global direction.
struct GroundAcceleration {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX(); ///< unit vector
  double dt = 0.01;                                     ///< s
  std::vector<double> acceleration;                     ///< mm/s^2
  /// Linear interpolation between samples; zero before 0 and after the last sample.
  double at(double time) const;
};

/// Viscous damping C = mass_factor M + stiffness_factor K0 (K0: tangent of the initial
/// state, of the elements with include_in_stiffness_damping true), or modal damping.
struct DampingSpec {
  double mass_factor = 0.0;      ///< a0 (1/s)
  double stiffness_factor = 0.0; ///< a1 (s)
  /// Per model element: whether it contributes to K0 (e.g. false for the braces). Empty:
  /// all elements.
  std::vector<bool> include_in_stiffness_damping;
  /// Modal damping instead: C = M (sum_i 2 xi_i w_i phi_i phi_i^T) M over the first
  /// modal_ratios.size() modes (mass-normalised shapes of the initial state). Empty: Rayleigh.
  std::vector<double> modal_ratios;
};

/// Rayleigh coefficients giving ratios xi_i, xi_j at circular frequencies w_i, w_j (rad/s):
/// a0 = 2 w_i w_j (xi_i w_j - xi_j w_i) / (w_j^2 - w_i^2), a1 = 2 (xi_j w_j - xi_i w_i) / (w_j^2 -
/// w_i^2).
std::pair<double, double> rayleigh_coefficients(double w_i, double xi_i, double w_j, double xi_j);

struct FallbackRecord {
  double time = 0.0;  ///< s, start of the step that needed it
  std::string what;   ///< "substeps of 1/4 of the step", "modified Newton (committed tangent)",
                      ///< "Broyden" (prefixed "static load: " in load steps)
  std::string reason; ///< why the previous attempt failed
};

struct TransientStepReport {
  bool converged = false;
  int iterations = 0;
  int substeps = 1;
  std::string failure; ///< when not converged: the last reason
};

struct TransientEnergy {
  double input = 0.0;       ///< ground input E_I (N mm)
  double static_work = 0.0; ///< work of the held static loads
  double kinetic = 0.0;
  double damping = 0.0;
  double stored = 0.0;
  double dissipated = 0.0;
  /// The elements' integration misfit (ElementEnergy::integration_misfit: the trapezoidal work
  /// of their laws' stresses at the integration points less the laws' own stored and
  /// dissipated energy, the laws' time discretisation), set apart from the error.
  double integration_misfit = 0.0;
  /// Gross input: the sum over (sub)steps of |input step| + |static work step| (N mm), a
  /// monotone scale for the balance (the net input oscillates and can pass through zero).
  double gross_input = 0.0;
  /// E_I + W_static - kinetic - damping - stored - dissipated - integration_misfit (N mm; see
  /// the .cpp for what it measures).
  double absolute_error() const {
    return input + static_work - kinetic - damping - stored - dissipated - integration_misfit;
  }
  /// |absolute_error()| / gross_input (0 before any input).
  double relative_error() const {
    return gross_input > 0.0 ? std::abs(absolute_error()) / gross_input : 0.0;
  }
};

class TransientAnalysis {
public:
  /// Evaluates the elements at the undeformed configuration (the committed start; their
  /// energies there are the zero of the balance). Throws std::invalid_argument for settings
  /// out of range (hht_alpha outside [-1/3, 0], max_iterations < 1, max_halvings < 0, a
  /// tolerance <= 0); an element that cannot evaluate the start makes every step fail with
  /// its reason.
  TransientAnalysis(model::Model& model, model::DofMap map, TransientSettings settings = {});
  TransientAnalysis(const TransientAnalysis&) = delete; // the assembler refers to map_
  TransientAnalysis& operator=(const TransientAnalysis&) = delete;

  /// Static load control from the current held load to held + `load` (full DOF vector,
  /// N and N mm) in `steps` equal increments (each with the same substepping); the total
  /// is then held during the dynamic run. Throws nothing; reports failure.
  TransientStepReport apply_static_load(const Eigen::VectorXd& load, int steps);

  /// Drops the held static load at the committed state (a sudden release, e.g. free
  /// vibration from a statically displaced state): the next step starts with the
  /// out-of-balance force as inertia. Releasing does no work.
  void remove_static_load();

  /// Builds C at the committed state. Throws std::invalid_argument for an
  /// include_in_stiffness_damping of the wrong size or negative factors or ratios, and
  /// std::runtime_error when the committed tangent cannot be assembled or (modal damping)
  /// modal_analysis fails.
  void set_damping(const DampingSpec& damping);
  /// Throws std::invalid_argument for dt <= 0 or a direction that is not a unit vector.
  void add_ground_acceleration(GroundAcceleration component);

  /// Advances the time by dt (s) with the fallbacks above.
  TransientStepReport step(double dt);

  double time() const { return time_; }
  const model::DofMap& dof_map() const { return map_; }
  /// Full-DOF vectors of the committed state: displacement (translation, rotation vector),
  /// relative velocity and relative acceleration (T times the equations' values).
  Eigen::VectorXd displacement() const;
  Eigen::VectorXd velocity() const;
  Eigen::VectorXd acceleration() const;
  /// Ground acceleration vector (global, mm/s^2) at the committed time.
  Eigen::Vector3d ground_acceleration() const;
  /// Internal forces of the committed state on every full DOF (reactions at supports).
  const Eigen::VectorXd& internal_force() const { return committed_full_force_; }
  const std::vector<element::NodeConfiguration>& nodes() const { return committed_nodes_; }
  const TransientEnergy& energy() const { return energy_; }
  const std::vector<FallbackRecord>& fallbacks() const { return fallbacks_; }

  /// Tangent (T^T K T) and mass (T^T M T) of the committed state, for modal analysis.
  Eigen::SparseMatrix<double> tangent();
  const Eigen::SparseMatrix<double>& mass() const { return mass_; }
  /// The damping matrix C on the equations (empty pattern until set_damping).
  const Eigen::SparseMatrix<double>& damping() const { return damping_; }

private:
  /// What one Newton-type attempt of a (sub)step solves (defined in the .cpp).
  struct Increment;
  struct Attempt {
    bool converged = false;
    int iterations = 0;
    std::string failure;
    Eigen::VectorXd increment; ///< dq of the equations (translations and spins)
  };
  enum class Algorithm { newton, modified_newton, broyden };

  /// A dynamic step from time `from` to `to`, or a static load step between load fractions,
  /// from the committed state.
  Increment make_increment(bool dynamic, double from, double to) const;
  bool try_increment(bool dynamic, double from, double to, int depth, TransientStepReport& report);
  Attempt solve(const Increment& increment, Algorithm algorithm, int max_iterations);
  /// Out-of-balance force of the last assembled trial state for the trial increment dq.
  Eigen::VectorXd residual(const Increment& increment, const Eigen::VectorXd& dq) const;
  /// Effective tangent of the last assembly (with a tangent): K, or
  /// M / (beta dt^2) + (1 + alpha) (K + gamma / (beta dt) C).
  Eigen::SparseMatrix<double> effective_tangent(const Increment& increment) const;
  bool factorize(const Eigen::SparseMatrix<double>& matrix);
  bool converged(const Increment& increment, const Eigen::VectorXd& dq,
                 const Eigen::VectorXd& residual) const;
  void commit(const Increment& increment, const Eigen::VectorXd& dq);
  void revert();
  /// -sum_c M r_c a_g,c(t) (equations).
  Eigen::VectorXd ground_force(double time) const;
  /// Relative acceleration in equilibrium with the committed state (massive equations).
  void make_acceleration_consistent();
  double newmark_gamma() const;
  double newmark_beta() const;
  // The implementation owns the rest (see transient_analysis.cpp).
  model::Model& model_;
  model::DofMap map_;
  TransientSettings settings_;
  model::Assembler assembler_;
  Eigen::SparseMatrix<double> mass_;
  Eigen::SparseMatrix<double> damping_;
  std::vector<GroundAcceleration> ground_;
  std::vector<Eigen::VectorXd> influence_;
  std::vector<element::NodeConfiguration> committed_nodes_;
  Eigen::VectorXd committed_full_force_;
  Eigen::VectorXd static_load_;  // held static load (full)
  Eigen::VectorXd static_base_;  // during apply_static_load: the load held before it (full)
  Eigen::VectorXd static_delta_; // and the load it adds (full)
  double static_fraction_ = 0.0; // of static_delta_ committed so far
  Eigen::VectorXd velocity_;     // equations
  Eigen::VectorXd acceleration_; // equations
  Eigen::VectorXd committed_reduced_force_; // T^T f_int of the committed state
  std::vector<element::NodeConfiguration> trial_nodes_;
  element::ElementEnergy initial_element_energy_;
  std::string initial_failure_; // the start could not be evaluated
  bool acceleration_consistent_ = true;
  double model_extent_ = 1.0; // mm, for the round-off floor
  // Per equation: the length whose relative round-off its unknown carries (the model's size
  // for translations, 1 rad for rotations), and the residual's round-off floor from the last
  // tangent, position_round_off x sum_j |K_ij| length_j.
  Eigen::VectorXd equation_length_;
  Eigen::VectorXd round_off_floor_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver_;
  std::vector<int> solver_pattern_; // outer and inner indices the solver was analysed for
  double time_ = 0.0;
  TransientEnergy energy_;
  std::vector<FallbackRecord> fallbacks_;
};

} // namespace brb::analysis
