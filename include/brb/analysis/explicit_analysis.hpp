// ExplicitAnalysis: explicit central-difference time-history analysis of a Model on the
// equations of a DofMap, with a lumped (diagonal) mass, in relative coordinates under
// uniform ground acceleration (the same equations as TransientAnalysis):
//   M a + C v + f_int(u) = f_static - M_phys sum_c r_c a_g,c(t).
//
// Integrator. boost::numeric::odeint::velocity_verlet on the second-order system
// (displacements and velocities of the equations), which is the central-difference method
// in its velocity form (Hughes, The Finite Element Method, ch. 9; Belytschko, Liu,
// Moran, Nonlinear Finite Elements, Box 6.1):
//   q_{n+1} = q_n + dt v_n + dt^2/2 a_n,   a_{n+1} = M^-1 f(q_{n+1}, v_{n+1/2}, t_{n+1}),
//   v_{n+1} = v_n + dt/2 (a_n + a_{n+1}).
// Damping C = a0 M_phys + a1 K0 (Rayleigh). The stiffness part, a full matrix, is evaluated
// at the half-step velocity v_{n+1/2} = v_n + dt/2 a_n (Belytschko et al., Box 6.1), not at
// the v_n odeint hands to the system (with v_n the stable step of a damped oscillator
// shrinks: xi = 0.2 gives 1.23/w instead of 1.64/w). It is first-order accurate in the
// damping force and stable for dt <= (2/w)(sqrt(1 + xi_k^2) - xi_k), xi_k = a1 w / 2
// (Belytschko et al., ch. 6). The mass part is diagonal, so it is taken at
// v_{n+1} = v_{n+1/2} + dt/2 a_{n+1} and solved per equation,
//   (m_i + a0 m_phys,i dt/2) a_i = f_i - (C_k v_{n+1/2})_i - a0 m_phys,i v_{n+1/2,i}:
// second-order and without effect on the limit 2/w (both limits are checked by the tests).
//
// Mass. The diagonal of DofMap::reduced_mass (T^T M T). An off-diagonal term (a rigid
// diaphragm whose slaves carry mass couples the master's translations to its rotation) is
// refused: lump the floor's mass and rotational inertia at the diaphragm master placed at
// the centre of mass, where T^T M T is diagonal. Equations without mass (rotations of frame
// nodes, typically) get a selectively scaled mass m_i = R_i (dt_target^2 + a1 dt_target),
// R_i = sum_j |K0_ij| (K0: initial tangent, a1: the stiffness part of Rayleigh damping): the
// Gershgorin bound of that equation's row of M^-1 K0 is then w^2 <= 1 / (dt^2 + a1 dt), for
// which the damped central-difference limit (2 / w)(sqrt(1 + xi^2) - xi), xi = a1 w / 2, is
// 2 dt_target: twice the step, coupling included. (With stiffness damping, a mass of
// R_i dt^2 alone would make the limit shrink like dt^2 / a1 as the step is refined.) The added mass
// is reported (mass_scaling()). dt_target is the user's time step, or when automatic safety * 2 /
// max_i sqrt(|K0_ii| / m_i) over the equations with mass.
//
// Stable step. w_max^2 is the largest eigenvalue of M^-1/2 K0 M^-1/2 (K0 symmetrised, scaled
// masses included), by power iteration: rho + |A x - rho x| (the Rayleigh quotient plus its
// residual, an eigenvalue lies within the residual of rho), capped by the Gershgorin bound
// max_i sum_j |A_ij| and by that of M^-1 K0, max_i R_i / m_i (both rigorous; the second is
// tight for scaled equations, where the power iteration converges slowly). With the damping ratio
// of that frequency, xi_k = a1 w_max / 2 (the stiffness part of Rayleigh damping), dt_stable =
// safety * (2 / w_max) * (sqrt(1 + xi_k^2) - xi_k). The step is taken from the initial state and
// estimated again every stability_check_interval steps from the tangent of the step's end
// state: an automatic step is reduced to the new estimate and the step retaken
// (fallbacks()), a given one stops the run. Between checks a stiffening that outgrows the
// step diverges; a non-finite state stops the run with a reason.
//
// Ground input uses the physical masses: a scaled (massless) equation carries no ground
// inertia force, its added mass only slows it down.
//
// Energy (relative formulation, Uang & Bertero 1990), trapezoidal over each step with the
// forces of the equations as they were evaluated: input E_I = -sum int (M_phys r_c a_g,c)^T dq,
// damping int f_damping^T dq (the damping forces above), static work int f_static^T dq, kinetic 1/2
// v^T M v (scaled mass included), element stored + dissipated energies. static_work starts at the
// energy of the initial state (its kinetic, stored and dissipated energy: the work that brought the
// structure there), so absolute_error() measures the run alone. The central-difference
// balance of kinetic energy is exact up to the non-accumulating term dt^2/8 a^T M a, i.e. a
// relative error of about (w dt)^2 / 4 of the current energy.
#pragma once

#include "brb/analysis/transient_analysis.hpp"
#include "brb/model/assembler.hpp"
#include "brb/model/dof_map.hpp"
#include "brb/model/model.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace brb::analysis {

struct ExplicitSettings {
  /// Time step (s). 0: automatic, the stable step. Otherwise typically a ground record's dt
  /// divided by an integer (see record_substep).
  double time_step = 0.0;
  /// Factor on the stability limit 2 / w_max (and on the automatic mass-scaling target).
  double stable_step_safety = 0.9;
  /// Refuse (std::invalid_argument) a time_step above the stable step. false lets such a run
  /// go, to demonstrate the instability; it stops when the state becomes non-finite.
  bool refuse_unstable_step = true;
  /// Selective mass scaling of the equations without mass; false: such an equation is an
  /// input error.
  bool mass_scaling = true;
  /// initialise_static: the state must be in equilibrium,
  /// |T^T (f_static - f_int)|_inf <= tolerance * (largest element force + largest load + 1 N).
  double static_tolerance = 1e-6;
  int max_power_iterations = 5000;
  /// Every this many steps the stable step is estimated again from the tangent of the step's
  /// end state, before it is committed (a stiffening structure: contact closing, tension
  /// stiffening); 0: never. When the step exceeds the estimate by half the safety margin
  /// (dt > stable * (1 + (1/safety - 1)/2)), an automatic step is reduced to the estimate and
  /// the step retaken (recorded in fallbacks()); a given step stops the run with the reason.
  /// Costs a tangent assembly and a power iteration per check; 1 for contact problems, whose
  /// stiffness can jump within a step.
  int stability_check_interval = 10;
};

/// The largest record substep not above `stable_step`: record_dt / ceil(record_dt / stable).
double record_substep(double record_dt, double stable_step);

/// What the selective mass scaling added (sums over the equations, each direction counted).
struct MassScalingReport {
  int scaled_equations = 0;
  double added_translational_mass = 0.0; ///< tonne
  double translational_mass = 0.0;       ///< tonne, physical + added
  double added_rotational_inertia = 0.0; ///< tonne mm^2
  double rotational_inertia = 0.0;       ///< tonne mm^2, physical + added
  double translational_fraction() const {
    return translational_mass > 0.0 ? added_translational_mass / translational_mass : 0.0;
  }
  double rotational_fraction() const {
    return rotational_inertia > 0.0 ? added_rotational_inertia / rotational_inertia : 0.0;
  }
};

/// The stable step and how it was found.
struct StableStepEstimate {
  double max_frequency = 0.0;    ///< w_max (rad/s)
  double gershgorin_bound = 0.0; ///< the cap on w_max (rad/s)
  int power_iterations = 0;
  double damping_ratio = 0.0; ///< xi_k = a1 w_max / 2, the part that lowers the limit
  double stable_step = 0.0;   ///< s, safety included
};

struct ExplicitStepReport {
  bool completed = false;
  int steps = 0;       ///< steps taken by this call
  std::string failure; ///< when not completed: why the run stopped
};

class ExplicitAnalysis {
public:
  ExplicitAnalysis(model::Model& model, model::DofMap map, ExplicitSettings settings = {});

  // Set-up: before prepare(), i.e. the first step or query (std::logic_error after it).

  /// Rayleigh damping (modal_ratios: std::invalid_argument, not available explicitly).
  void set_damping(const DampingSpec& damping);
  void add_ground_acceleration(GroundAcceleration component);
  /// A load (full DOF vector, N and N mm) held constant during the run.
  void set_static_load(const Eigen::VectorXd& load);
  /// Starts from `nodes` (one configuration per model node) with full-DOF `velocity`
  /// (translations and spins; the value of each equation's own DOF is taken). The elements'
  /// committed states are the model's as they are.
  void set_initial_state(std::span<const element::NodeConfiguration> nodes,
                         const Eigen::VectorXd& velocity);
  /// Starts at rest from a converged static state found elsewhere (e.g. the gravity steps of
  /// TransientAnalysis or StaticAnalysis on this model, whose elements hold its committed
  /// states): its node configurations and its load, which is then held. Throws
  /// std::invalid_argument when the state is not in equilibrium under the load (see
  /// ExplicitSettings::static_tolerance) and std::runtime_error when an element refuses it.
  void initialise_static(std::span<const element::NodeConfiguration> nodes,
                         const Eigen::VectorXd& static_load);
  /// The same from a twin model (same elements in the same order) whose elements hold the
  /// converged state; their states are copied into this model's elements.
  void initialise_static(const model::Model& converged,
                         std::span<const element::NodeConfiguration> nodes,
                         const Eigen::VectorXd& static_load);

  /// Masses, initial tangent, stable step (done by the first step() or query). Throws
  /// std::invalid_argument for an equation with neither mass nor stiffness, an off-diagonal
  /// mass, a refused time step; std::runtime_error when an element refuses the initial state.
  void prepare();

  /// One step of time_step(). After a failure every call returns the same failure.
  ExplicitStepReport step();
  /// Steps up to `time` (s), the last one shortened to land on it.
  ExplicitStepReport run_to(double time);

  double stable_time_step() { return stable_step_estimate().stable_step; }
  const StableStepEstimate& stable_step_estimate();
  /// The step in use (s).
  double time_step();
  const MassScalingReport& mass_scaling();
  /// The lumped masses of the equations (scaled ones included).
  const Eigen::VectorXd& lumped_mass();

  double time() const { return time_; }
  const model::DofMap& dof_map() const { return map_; }
  /// Full-DOF vectors of the committed state: displacement (translation, rotation vector of
  /// the triad), relative velocity and acceleration (T times the equations' values).
  Eigen::VectorXd displacement() const;
  Eigen::VectorXd velocity() const;
  Eigen::VectorXd acceleration() const;
  /// Ground acceleration vector (global, mm/s^2) at the committed time.
  Eigen::Vector3d ground_acceleration() const;
  /// Internal forces of the committed state on every full DOF (reactions at supports).
  const Eigen::VectorXd& internal_force() const { return committed_full_force_; }
  const std::vector<element::NodeConfiguration>& nodes() const { return committed_nodes_; }
  /// Energies of the committed state (zero until prepare()).
  const TransientEnergy& energy() const { return energy_; }
  /// Why the run stopped (time: start of the step that failed), if it did.
  const std::optional<FallbackRecord>& failure() const { return failure_; }
  /// The automatic step's reductions after a stability check (time, new step, why).
  const std::vector<FallbackRecord>& fallbacks() const { return fallbacks_; }

private:
  /// The forces of one evaluation of the equations of motion (equations).
  struct EquationForces {
    Eigen::VectorXd internal; ///< T^T f_int
    Eigen::VectorXd damping;  ///< C v
    Eigen::VectorXd ground;   ///< M_phys sum_c r_c a_g,c
  };

  void require_not_started(const char* what) const;
  Eigen::VectorXd reduced_load() const;
  void build_masses_and_step();
  /// Forces and acceleration at displacement q of the equations (applied from the committed
  /// nodes into trial_nodes_) at time t, with the half-step velocity v_{n+1/2} and half the
  /// step (0 at the initial state). False with a reason on failure.
  bool evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& half_step_velocity, double half_dt,
                double t, EquationForces& forces, Eigen::VectorXd& acceleration,
                std::string& reason);
  ExplicitStepReport advance(double dt);
  ExplicitStepReport stop(double dt, std::string reason);
  /// w_max and the stable step for `tangent` with the lumped masses and the damping.
  StableStepEstimate estimate_stable_step(const Eigen::SparseMatrix<double>& tangent) const;
  enum class StabilityCheck { fine, reduced, stop };
  /// The stability check of a step's trial end state (ExplicitSettings::
  /// stability_check_interval): fine, the automatic step reduced (retake the step), or stop.
  StabilityCheck check_stable_step(std::string& reason);

  model::Model& model_;
  model::DofMap map_;
  ExplicitSettings settings_;
  model::Assembler assembler_;
  std::vector<int> equation_dof_; // equation -> its full DOF

  // set-up
  DampingSpec damping_spec_;
  std::vector<GroundAcceleration> ground_;
  std::vector<Eigen::VectorXd> influence_;
  Eigen::VectorXd static_load_; // full
  bool prepared_ = false;

  // from prepare()
  Eigen::VectorXd physical_mass_;                 // equations
  Eigen::VectorXd mass_;                          // equations, scaled included
  Eigen::VectorXd mass_damping_;                  // a0 M_phys (diagonal)
  Eigen::SparseMatrix<double> stiffness_damping_; // a1 K0
  Eigen::VectorXd static_reduced_;
  MassScalingReport mass_scaling_;
  StableStepEstimate stable_;
  double time_step_ = 0.0;

  // committed state
  std::vector<element::NodeConfiguration> committed_nodes_;
  std::vector<element::NodeConfiguration> trial_nodes_;
  Eigen::VectorXd committed_full_force_;
  Eigen::VectorXd displacement_; // equations (accumulated increments)
  Eigen::VectorXd velocity_;
  Eigen::VectorXd acceleration_;
  EquationForces forces_;
  double time_ = 0.0;
  TransientEnergy energy_;
  std::optional<FallbackRecord> failure_;
  std::vector<FallbackRecord> fallbacks_;
  int steps_since_check_ = 0;
};

} // namespace brb::analysis
