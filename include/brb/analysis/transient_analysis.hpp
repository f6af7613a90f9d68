// TransientAnalysis: nonlinear time-history analysis of a Model on the equations of a
// DofMap, in relative coordinates under uniform ground acceleration:
//   M a + C v + f_int(u) = f_static - M sum_c r_c a_g,c(t)
// (r_c: influence vector of component c). Implicit Newmark (average acceleration,
// gamma = 1/2, beta = 1/4) or HHT-alpha (Hilber, Hughes, Taylor 1977; alpha in [-1/3, 0],
// gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4), Newton-Raphson with a backtracking line
// search. A failed step is retried: halved substeps down to a floor, then the other
// algorithms (modified Newton on the initial stiffness, then Broyden-type secant updates);
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
  /// inertia/damping/external force + 1 N) and the energy norm |du^T r| is small (stated
  /// in the implementation).
  double relative_force_tolerance = 1e-8;
  bool line_search = true;
  int max_halvings = 8; ///< substep floor: dt / 2^max_halvings
};

/// A uniform ground acceleration component along a global direction.
struct GroundAcceleration {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX(); ///< unit vector
  double dt = 0.01;                                      ///< s
  std::vector<double> acceleration;                      ///< mm/s^2
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
/// a0 = 2 w_i w_j (xi_i w_j - xi_j w_i) / (w_j^2 - w_i^2), a1 = 2 (xi_j w_j - xi_i w_i) / (w_j^2 - w_i^2).
std::pair<double, double> rayleigh_coefficients(double w_i, double xi_i, double w_j, double xi_j);

struct FallbackRecord {
  double time = 0.0;         ///< s, start of the step that needed it
  std::string what;          ///< e.g. "substep 1/4", "initial-stiffness Newton", "Broyden"
  std::string reason;        ///< why the previous attempt failed
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
  /// |E_I + W_static - kinetic - damping - stored - dissipated| / max(|E_I|, gross) ...
  double absolute_error() const { return input + static_work - kinetic - damping - stored - dissipated; }
};

class TransientAnalysis {
public:
  TransientAnalysis(model::Model& model, model::DofMap map, TransientSettings settings = {});

  /// Static load control from the current held load to held + `load` (full DOF vector,
  /// N and N mm) in `steps` equal increments (each with the same substepping); the total
  /// is then held during the dynamic run. Throws nothing; reports failure.
  TransientStepReport apply_static_load(const Eigen::VectorXd& load, int steps);

  void set_damping(const DampingSpec& damping);
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

private:
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
  Eigen::VectorXd static_load_; // held static load (full)
  Eigen::VectorXd velocity_;     // equations
  Eigen::VectorXd acceleration_; // equations
  double time_ = 0.0;
  TransientEnergy energy_;
  std::vector<FallbackRecord> fallbacks_;
};

} // namespace brb::analysis
