// StaticAnalysis: path-following static solution of a Model under displacement control of
// one DOF (the cyclic test of a brace), load control (a reference load times a factor), or
// prescribed motion of a set of nodes (all six DOF each, a parameter 0..1 moving them from
// their committed to a target configuration: the nested solve of a condensed BRBElement).
//
// Algorithm per step: tangent predictor, Newton-Raphson with a backtracking line search on
// the residual; on failure the step is retried in halves down to a floor (1 / 2^max_halvings
// of the step), and at the floor by pseudo-transient continuation (backward-Euler steps of
// the gradient flow c du/dtau = F_ext - F_int, which passes limit points and comes to rest
// on the next stable branch). Every such fallback is reported.
// Nothing is committed until a (sub)step converges, so a failure leaves the last
// converged state intact.
//
// Energy: external work is integrated with the trapezoidal rule over converged steps;
// elements report stored and dissipated energy (their laws' exact bookkeeping of each
// update) and the integration misfit (the trapezoidal work of the stresses at the
// integration points minus those: the laws' time discretisation, O(step^2) where a step
// has a kink of the stress-strain path inside it), and the pseudo-viscosity's absorbed
// energy is the energy released in jumps, so W = stored + dissipated + misfit + released is
// a check of the solution itself (equilibrium, kinematics, the jumps' accounting), and
// W = stored + dissipated + released (the laws' balance) a check that also holds in the
// limit of small steps.
#pragma once

#include "brb/element/element.hpp"
#include "brb/model/element_evaluations.hpp"
#include "brb/model/model.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace brb::analysis {

struct NewtonSettings {
  int max_iterations = 30;
  /// Converged when |residual|_inf <= tolerance * (largest element force component +
  /// largest external load + 1 N).
  double relative_force_tolerance = 1e-9;
  /// Relative precision assumed for node positions (of the model's size): the stiffest
  /// element turns it into the residual's round-off floor, 1e-14 x size x largest diagonal
  /// stiffness, below which no tolerance is asked. Lower it only to compare solutions more
  /// closely than that (e.g. a condensed against an expanded model).
  double position_round_off = 1e-14;
  bool line_search = true;
  /// Newton corrections taken after the residual first falls within tolerance (pseudo-transient
  /// steps excepted; not past max_iterations). 0: converged as soon as within tolerance. A
  /// condensed element asks 1: its outer forces sum the inner residuals of every internal
  /// node, so a state within tolerance node by node can be off by a hundred times that in its
  /// outer forces (measured: 0.006 N of 52 kN against a 5e-5 N tolerance), and an outer Newton
  /// cannot converge on forces that carry such noise. One correction from within tolerance
  /// takes the inner residual to round-off (Newton's quadratic convergence).
  int polish_corrections = 0;
  /// Stagnation cut-off of plain Newton (0: off; pseudo-time steps are never cut by it). A
  /// plain Newton call gives up at iteration `stagnation_iterations` when the smallest
  /// residual norm it has reached is still above `stagnation_ratio` times its start, and the
  /// step goes to the fallbacks (halving, pseudo-time) that many iterations sooner. Why: a
  /// restrained core's mode jump is a snap-through that plain Newton cannot pass, and it
  /// tried for all max_iterations first, backtracking some five times per iteration on a
  /// residual that plateaued at 1e5 to 1e6 N. Measured on CB225's record at x4 (48 core
  /// elements), first 200 steps, one run after the other beside another run: 176 s without
  /// the cut-off (such failing calls were 43 % of all assemblies), 155 s at 15 iterations,
  /// 105 s at 12 and 133 s at 10 (0.1 each; the force path within 0.23 % RMS at 10). Not
  /// sooner: at 10 and 12 the restrained Girona D3 core at steps of dy / 7 took another
  /// branch through a mode jump (compression peak -114,172 N against -114,245 N at dy / 7, 10
  /// and 13 without it; RestrainedCore.PathThroughTheModeJumpsDoesNotHangOnTheStepSize): a
  /// call that plateaus and then converges, cut, lets the pseudo-time solver pass the jump
  /// elsewhere. At 15 all three step sizes give -114,245 N. Extending the cut-off to the
  /// pseudo-time steps (at 10) saved 4 % more and was left out.
  int stagnation_iterations = 15;
  double stagnation_ratio = 0.1;
  int max_halvings = 12;         ///< substep floor: step / 2^max_halvings
  int fallback_iterations = 500; ///< pseudo-time steps allowed per limit point
  /// From this many cuts on, a failing step first tries pseudo-transient continuation.
  int pseudo_transient_depth = 4;
  /// Accept a converged (sub)step only if its tangent is positive definite (a stable
  /// equilibrium under the control); otherwise cut the step. Newton started far from the
  /// path can converge onto an unstable branch (e.g. a bowed column carried straight past
  /// its Euler load, bowed against its imperfection); cutting the step keeps it on the
  /// stable one. The check applies when the step starts from a stable state; after
  /// `stability_halvings` cuts an unstable state is accepted and reported (the path itself
  /// has lost stability: a limit point, or a plastic mechanism).
  bool require_stable_equilibrium = true;
  int stability_halvings = 6;
  /// Energy-error control (0: off). The trapezoidal work of a step and the change of the
  /// elements' stored + dissipated energy differ where the path has a kink inside the step
  /// (a fiber yielding, a contact link closing): the rule integrates a kinked force
  /// exactly only at the kink. A converged substep is cut when the running sum of these
  /// per-step differences would exceed `energy_tolerance` times the gross work so far
  /// (sum of |work| per step), so that at every instant
  ///   sum |W_step - dE_step| <= energy_tolerance * sum |W_step|.
  /// Cutting stops after `energy_halvings` cuts (the step is then accepted and counted
  /// in StepReport::energy_tolerance_missed). Steps that pass a limit point by
  /// pseudo-transient continuation book their jump separately and are not cut. An error
  /// such steps commit beyond the budget is carried, not repaid: while it stands, a later
  /// step passes if its own error is within its share, tolerance * |W_step|.
  /// The default, 1e-2, is a guard, not an accuracy target: a well-resolved run misfits by
  /// 1e-5 to 1e-3 and is never cut, but a converged step that lands on a far branch whose
  /// energy the loading could not have supplied (measured: Girona D1, where Newton steps
  /// crushed the bearing mortar through and created 0.35 of the gross work) is cut until
  /// the path is followed (D1: misfit 0.005). Tighter values buy accuracy at a high cost
  /// (README, "Energy balance").
  double energy_tolerance = kEnergyGuard;
  /// Far-branch control (0: off). A converged (sub)step whose Newton correction moved some
  /// node further than `max_correction_ratio` times the largest motion of the tangent
  /// predictor has converged onto another equilibrium branch, not followed the path; it is
  /// cut (down to the substep floor). Measured on the restrained Girona D3 core (steps of
  /// dy / 10, unloading from 2 dy in compression): Newton corrections of 4.3 and 20 mm
  /// against a predictor of 0.29 mm, after which the next step crushed the bearing mortar
  /// through; steps of dy / 13 and dy / 20 follow the path and crush nothing. Smooth steps
  /// corrected by up to 4.6 times their prediction there; with 5 the run crushes nothing at
  /// steps of dy / 5, 7, 10, 13 and 20 (with 10 it still did at dy / 7, with 3 it took four
  /// times the substeps). The same control cuts a substep, and retries shorter a pseudo-time
  /// step of a jump, in which an element went past a softening peak with no path point near
  /// it (Element::jumped_past_peak: a bearing link crushed from intact).
  double max_correction_ratio = 5.0;
  /// Far-branch control on steep paths (0: off, every far landing is cut down to the floor).
  /// A substep that lands far is accepted when the steps it was cut from, its parent and its
  /// parent's parent, were both cut for landing far and the three correction-to-prediction
  /// ratios are steady: each within a factor `far_ratio_growth` of the next, either way.
  /// Halving a step halves its predictor: across a jump to another branch the correction
  /// stays what it was, so the ratio doubles; on a path that is steep or kinked where the
  /// tangent mispredicts it (a contact or friction state changing at every substep) the
  /// correction halves with the step, so the ratio stays. Measured on Girona D3 (the
  /// compression reload from +7.8 mm): a core node corrected by ten times its predicted motion
  /// (ratios within 1 % of each other) at every depth from 5 to 11, so every substep of two
  /// steps was cut to the floor (769 cuts, 55 s for the run; with this test 20 cuts, the total
  /// energy within 2e-5). Not looser: accepting after one level, or ratios that fall, let the
  /// `passes` check's brace take a mode jump in coarser substeps (ratios 330, 400, 197 at
  /// depths 6 to 8), a force drop of 1.3 to 2.1 % of Pysc against its K3.8a limit of 1 %
  /// (0.17 % when the jump is cut to the floor).
  double far_ratio_growth = 1.25;
  static constexpr double kEnergyGuard = 1e-2;
  int energy_halvings = 10;
  /// Balance control (0: off). Like energy_tolerance, but on the balance of the solution,
  /// EnergyBalance::relative_error (the laws' integration misfit set apart): a converged
  /// substep is cut (up to `energy_halvings` cuts) when the running signed sum of
  /// W_step - (change of stored + dissipated + misfit) would exceed `balance_tolerance`
  /// times the gross work. What it cuts is the part of the trapezoidal rule the fibers do
  /// not see: the co-rotational kinematics within a step (a restrained core swinging
  /// across its gap as the force reverses); cutting where the laws kink (every step that
  /// yields a fiber) is energy_tolerance's. Off by default: the cuts move the substep
  /// points, and a restrained core's path can follow them onto another branch (measured
  /// on Girona D3 at 5e-7: a bearing face crushed, which no step size of the plain run
  /// does; README, "Energy balance"). Validation specimens ask for it in metrics.json
  /// (`solver.balance_tolerance`, 5e-7 for those that use it) where it was measured to
  /// leave the path as it is.
  double balance_tolerance = 0.0;
  /// Path retrace (retrace_last_path; 0: off): a new motion target may retrace the last
  /// step's substeps when it lies closer than this fraction of that step's travel to the
  /// target it was solved for (both measured as the largest motion of a prescribed node,
  /// rotations times the model's size). Below 0.5, so that a halved global step (a target
  /// half the travel back) is solved afresh: a retrace would carry a jump of the full step
  /// (a core snapped to a higher mode) to a target that need not reach it. Not much below:
  /// near a brace's compression limit a frame's Newton corrects its targets by a quarter of
  /// the step (measured on brbf3: 0.092 mm after 0.355 mm) and a fresh solve there jumps at
  /// some targets and not at others.
  double retrace_target_ratio = 0.4;
  /// Threads that evaluate the elements of each assembly (model/element_evaluations.hpp;
  /// >= 1). The results are bitwise the same for every count: each element is evaluated
  /// into its own buffers and the sums are taken in element order. Worth more than one on a
  /// model with many costly elements (a fiber core at 2x or 4x its default elements) when
  /// the cores are free; nested analyses (a BRBElement's inner model) keep 1.
  int element_threads = 1;
};

/// What one call of step_to() did.
struct StepReport {
  bool converged = false;
  int iterations = 0;      ///< Newton iterations over all attempts
  int substeps = 1;        ///< converged substeps taken
  int deepest_halving = 0; ///< 0: the step went through whole
  bool used_regularised_newton = false;
  int unstable_accepted = 0;       ///< substeps accepted at the floor with an unstable tangent
  int energy_cuts = 0;             ///< substeps cut by the energy-error control
  int energy_tolerance_missed = 0; ///< substeps accepted at the energy-control floor
  int far_branch_cuts = 0;         ///< substeps cut by the far-branch control
  std::string failure;             ///< why it stopped, when it did not converge
};

/// Where a solver's effort went, since construction: what a run's time is made of (the
/// elements' evaluations are most of it), for choosing what to speed up. Every Newton
/// iteration falls in one of the three iteration counts, so their sum is the analysis's
/// total_iterations(). Measured on PC250 at x4 (48 core elements), its first 1,499 steps:
/// 428,967 assemblies for 99,410 iterations, 95 % of them at line-search trial points (two in
/// three rejected); the plain Newton calls that failed (3,030, most stagnating at 15
/// iterations before the step was cut) took 68 % of the assemblies, the converged ones 9 %,
/// the pseudo-time steps 22 % (validation/README, the x4 paragraph).
struct SolverWork {
  std::int64_t assemblies = 0;             ///< evaluations of every element's force and tangent
  std::int64_t line_search_assemblies = 0; ///< of them, at a line search's trial points
  std::int64_t converged_newton_iterations = 0; ///< in plain Newton calls that converged
  /// In plain Newton calls that did not converge (stagnated, diverged, an element failed):
  /// the step was then cut or passed in pseudo-time.
  std::int64_t failed_newton_iterations = 0;
  std::int64_t failed_newton_calls = 0;
  std::int64_t pseudo_time_steps = 0;      ///< backward-Euler steps of the gradient flow, tried
  std::int64_t pseudo_time_iterations = 0; ///< Newton iterations in them
};

/// Totals over the analysis (N mm).
struct EnergyBalance {
  double external_work = 0.0;
  double stored = 0.0;
  double dissipated = 0.0;
  /// Energy absorbed by the pseudo-viscosity while the solver passed limit points (the
  /// energy those jumps release, e.g. a restrained core snapping to a higher mode): the drop
  /// of the elements' stress work (stored + dissipated + integration misfit) during the
  /// jumps plus the loads' work on them.
  double released_in_jumps = 0.0;
  /// The same energy measured by the laws' stored + dissipated energy alone (it differs by
  /// the trapezoidal rule's misfit over the jumps' paths, which the stress work sums in one
  /// step); the energy-error control of the steps uses it.
  double released_by_laws = 0.0;
  /// Sum over the elements of ElementEnergy::integration_misfit, committed state (N mm).
  double integration_misfit = 0.0;
  /// Gross work: the sum over steps of |work of the step| (N mm). The scale of the balance:
  /// the net work of a cyclic test after nearly elastic full cycles is close to zero.
  double gross_work = 0.0;
  /// The balance of the solution:
  /// |W - stored - dissipated - integration_misfit - released_in_jumps| / max(gross_work, tiny)
  double relative_error() const;
  /// The laws' balance, |W - stored - dissipated - released_by_laws| / max(gross_work, tiny):
  /// includes the laws' time discretisation (it falls with the step size).
  double law_relative_error() const;
  /// |integration_misfit| / max(gross_work, tiny)
  double relative_misfit() const;
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, EnergyBalance>
void state_fields(Archive& archive, Self& energy) {
  static_assert(sizeof(EnergyBalance) == 7 * sizeof(double),
                "a new field of EnergyBalance must be listed here");
  archive(energy.external_work, energy.stored, energy.dissipated, energy.released_in_jumps,
          energy.released_by_laws, energy.integration_misfit, energy.gross_work);
}

/// The committed path of an analysis: what a caller that rolls the analysis back (a
/// condensed macro element between global commits) must keep besides its elements' states.
struct AnalysisPathState {
  std::vector<element::NodeConfiguration> nodes;
  Eigen::VectorXd internal_force;
  double control_value = 0.0;
  double control_force = 0.0;
  bool stable = true;
  EnergyBalance energy;
  double energy_error_sum = 0.0; ///< signed sum of the steps' energy misfits
};

class StaticAnalysis {
public:
  explicit StaticAnalysis(model::Model& model, NewtonSettings settings = {});

  /// Checkpoints of a long run (io/state_archive.hpp): between steps, the committed state of
  /// the analysis (nodes, forces, control, energy balance, statistics) and of every element
  /// of its model. load_state reads it into an analysis of a model built from the same input
  /// with the same control, as its committed and trial state; a checkpoint of another model
  /// throws io::CheckpointMismatch. The next step then runs as it would have in the run that
  /// wrote the checkpoint, to the bit (test CyclicCheckpoint).
  void save_state(io::StateWriter& out) const;
  void load_state(io::StateReader& in);

  /// Control by the displacement of one DOF (it becomes prescribed).
  void use_displacement_control(int node, model::Dof dof);
  /// Control by a load factor times a reference load (N or N mm per DOF).
  void use_load_control(const Eigen::VectorXd& reference_load);
  /// Control by the motion of `nodes` (all six DOF of each become prescribed). The control
  /// parameter runs from 0 to 1 between their committed configuration and the target of
  /// set_motion_target(): translations linearly, rotations along the rotation vector of
  /// the relative rotation, R(s) = exp(s theta) R_0 with theta = log(R_target R_0^T).
  void use_prescribed_motion(std::vector<int> nodes);
  /// Targets of the prescribed nodes (in the order given to use_prescribed_motion), from
  /// their committed configuration; the control restarts at 0 (step_to(1.0) gets there).
  void set_motion_target(std::span<const element::NodeConfiguration> targets);
  /// Under prescribed motion, the tangent of the last converged state statically condensed
  /// to the prescribed DOF (6 per node, in their order): K_pp - K_pf K_ff^-1 K_fp, with
  /// respect to translations and spins. Valid right after a converged step_to().
  Eigen::MatrixXd condensed_tangent();

  /// The committed path (node configurations, forces, control, energies) and its restoration;
  /// the elements' states are the caller's (Model::copy_element_states_from).
  AnalysisPathState path_state() const;
  void restore_path_state(const AnalysisPathState& state);

  /// A dead load applied in every state (e.g. gravity), in addition to the control.
  void set_constant_load(const Eigen::VectorXd& load);

  /// Moves the control (displacement or load factor) to `target` from its current value.
  StepReport step_to(double target);
  /// Under prescribed motion, solves the last converged step_to() again for the current
  /// motion target, from the committed state that step started from (the caller restores
  /// it: a condensed element between the iterations of its global step): the same
  /// substeps (control values), each Newton solve started from the configuration the
  /// substep reached last time; a substep that passed a limit point is solved by Newton
  /// from the branch that jump reached (failing that, by pseudo-transient continuation
  /// again), its released energy booked as pseudo_transient books it; none of step_to's
  /// step-size cuts (the substeps were chosen for a target closer than
  /// NewtonSettings::retrace_target_ratio of its travel to this one).
  /// Why: the global Newton of a frame asks a brace for its forces at targets that differ
  /// by ever smaller corrections; an adaptive solve from scratch for each may cut its step
  /// differently or come to rest elsewhere after a jump, so the forces it returns jump by
  /// more than the global tolerance (measured: brbf3's global Newton stalled at residuals of
  /// 4 to 130 N). A retrace is a smooth function of the target and is cheaper.
  /// Refused (converged false, nothing moved, the failure says why) without such a step,
  /// from another state, or for a target too far. Stopped, with the reason and the
  /// substeps before it committed (like step_to), by a substep that does not converge,
  /// lands on another branch (NewtonSettings::max_correction_ratio's tests and
  /// energy_change_supplied_by_work), would exceed the energy-error budget
  /// (NewtonSettings::energy_tolerance, balance_tolerance), or, as the last one, ends on an
  /// unstable equilibrium where step_to's ended on a stable one. Either way the caller then
  /// solves with step_to().
  StepReport retrace_last_path();

  /// Current value of the control and the force conjugate to it (the reaction at the
  /// controlled DOF in displacement control; the load factor's work-conjugate in load control).
  double control_value() const { return control_value_; }
  double control_force() const { return control_force_; }

  const element::NodeConfiguration& node(int index) const { return committed_[index]; }
  /// Displacement of a translational DOF, or the rotation-vector component of R for a rotation.
  double displacement(int node, model::Dof dof) const;
  /// Internal force at each DOF of the converged state (reactions at restrained DOF).
  const Eigen::VectorXd& internal_force() const { return committed_internal_force_; }

  const EnergyBalance& energy() const { return energy_; }
  /// Statistics since construction.
  int total_iterations() const { return total_iterations_; }
  int total_substeps() const { return total_substeps_; }
  int regularised_steps() const { return regularised_steps_; }
  int unstable_accepted() const { return unstable_accepted_; }
  int energy_cuts() const { return energy_cuts_; }
  int energy_tolerance_missed() const { return energy_tolerance_missed_; }
  int far_branch_cuts() const { return far_branch_cuts_; }
  int retraced_steps() const { return retraced_steps_; }
  const SolverWork& work() const { return work_; }

  /// Solves the initial state (control at zero) so that reactions and energies exist.
  StepReport initialise();

  /// The tangent stiffness of the last converged state restricted to the free DOF, and
  /// the DOF numbering (global DOF per free equation). For eigen-buckling analyses.
  Eigen::SparseMatrix<double> free_tangent();
  const std::vector<int>& free_dofs() const { return free_dofs_; }

private:
  struct Attempt {
    bool converged = false;
    int iterations = 0;
    std::string failure;
    double jump_work = 0.0; ///< pseudo_transient: external work of the step it passed
    /// The start was within tolerance, so what Newton did was the corrections asked by
    /// NewtonSettings::polish_corrections (lands_near_predictor accepts it).
    bool started_within_tolerance = false;
  };

  void number_equations();
  /// Displacement control or prescribed motion (the control moves DOF, not a load).
  bool kinematic_control() const { return displacement_control_ || !motion_nodes_.empty(); }
  /// Assembles internal forces (all DOF) and the free-free tangent at the trial state.
  bool assemble(bool with_tangent, std::string& failure);
  /// The first half of assemble(): evaluates the elements at the trial state and sums their
  /// forces (internal_force_, force_scale_). With `check_tangent` an element whose tangent
  /// is not finite fails the evaluation, as in assemble(true), so gather_tangent() can
  /// follow later without evaluating again.
  bool assemble_forces(bool check_tangent, std::string& failure);
  /// The second half: the tangent blocks (free x free, control column, prescribed blocks)
  /// from the elements' tangents of the last evaluation.
  void gather_tangent();
  /// Whether the elements still have the nodes the tangent's value slots were built for.
  bool tangent_slots_match() const;
  /// The value slot of every triplets_ entry in the compressed tangent_.
  void build_tangent_slots();
  Eigen::VectorXd free_residual(double control) const;
  void apply_free_increment(const Eigen::VectorXd& increment, double scale);
  void set_control_value(double value);
  /// Whether a residual of the last assembled state is below tolerance (with its round-off
  /// floor).
  bool residual_converged(const Eigen::VectorXd& residual, double control) const;
  /// Newton-Raphson at `control`; with `viscosity` (free x free), one backward-Euler step
  /// of the gradient flow from the trial state (see pseudo_transient). `assembled`: the trial
  /// state is already assembled (with its tangent), so the first iteration does not assemble.
  Attempt newton(double control, const Eigen::SparseMatrix<double>* viscosity, int max_iterations,
                 bool assembled = false);
  /// newton() without the booking of its iterations in work_.
  Attempt newton_iterations(double control, const Eigen::SparseMatrix<double>* viscosity,
                            int max_iterations, bool assembled);
  /// The metric of the pseudo-transient viscosity from the last assembled tangent (see
  /// pseudo_transient): per node, |sym K| of its translation block and of its rotation block.
  Eigen::SparseMatrix<double> nodal_stiffness_metric() const;
  Attempt pseudo_transient(double control);
  /// Where a jump started: the elements' energies and the control force with the control
  /// moved and the free nodes still at the committed state.
  struct JumpStart {
    element::ElementEnergy energy;
    double control_force = 0.0;
  };
  /// Books the energy a jump released, from its start to the assembled trial state (its rest
  /// point) over the free-DOF motion `travelled`; returns the external work of the step.
  double book_jump(const JumpStart& start, const Eigen::VectorXd& travelled, double control);
  /// Free-DOF motion of the trial state from the committed one (spins as rotation vectors).
  Eigen::VectorXd free_motion_since_commit() const;
  /// Whether the trial state that `attempt` converged to is within
  /// NewtonSettings::max_correction_ratio of the tangent predictor `predicted` (always, when
  /// the attempt started within tolerance and only polished).
  /// `correction_ratio`, if given, receives the largest correction over the largest predicted
  /// motion.
  bool lands_near_predictor(const Attempt& attempt,
                            const std::vector<element::NodeConfiguration>& predicted,
                            double* correction_ratio = nullptr) const;
  /// Commits the state reached by pseudo-transient continuation at control `to`, if any.
  bool pass_limit_point(double to, StepReport& report);
  /// Sum of the elements' energies at their last evaluated (trial) state.
  element::ElementEnergy element_energy() const;
  /// The correction ratios (largest correction over largest predicted motion) of the far
  /// landings the steps enclosing a substep were cut for (NewtonSettings::far_ratio_growth):
  /// `last` of the step it halves, `before` of that step's own parent; 0 where a step was not
  /// cut for a far landing.
  struct FarCuts {
    double last = 0.0;
    double before = 0.0;
  };
  /// Solves the (sub)step from control `from` to `to`, `depth` cuts deep, cutting it on
  /// failure; `far_cuts` as FarCuts says.
  bool try_increment(double from, double to, int depth, StepReport& report, FarCuts far_cuts);
  /// Reverts the trial state and tries the step as two halves, one cut deeper (`far_cuts` of
  /// both halves).
  bool halve(double from, double to, int depth, StepReport& report, FarCuts far_cuts);
  /// Trapezoidal work of the converged forces over the trial increment (N mm).
  double increment_work() const;
  /// A converged trial step's work and the elements' energies at its end: computed once,
  /// for the energy check and the commit.
  struct StepEnergy {
    double work = 0.0;
    element::ElementEnergy end;
  };
  StepEnergy trial_step_energy() const { return {increment_work(), element_energy()}; }
  /// Whether the step keeps the running energy error within
  /// NewtonSettings::energy_tolerance (always true when the control is off).
  bool within_energy_tolerance(const StepEnergy& step) const;
  /// Whether the step keeps the running balance error within
  /// NewtonSettings::balance_tolerance (always true when the control is off).
  bool within_balance_tolerance(const StepEnergy& step) const;
  /// The test both controls share: the committed running error plus the step's error
  /// (step.work - change) stays within `tolerance` times the gross work with the step; or,
  /// where the committed error already exceeds tolerance times the gross work (a jump, a
  /// step whose cuts ran out), the step's own error is within tolerance times its |work|.
  bool within_budget(double committed_error, double change, double tolerance,
                     const StepEnergy& step) const;
  /// Path control of softening laws (the third test of the far-branch control): marks every
  /// element's last evaluated state as the last path point; whether some element has since
  /// gone past a softening peak without a path point near it (Element::jumped_past_peak).
  void mark_path_point();
  bool jumped_past_peak() const;
  /// Whether a converged step dissipates no more than its work supplies (the second test of
  /// the far-branch control).
  bool dissipation_supplied_by_work(const StepEnergy& step) const;
  /// Whether a converged step changes the elements' energy (stored + dissipated) by its work,
  /// within half its magnitude: not a jump to another branch (retrace_last_path's test of a
  /// warm-started substep; a step-size control would flip with the target).
  bool energy_change_supplied_by_work(const StepEnergy& step) const;
  void commit(double control, const StepEnergy& step);
  /// The committed internal forces again, after a commit coupling changed committed states.
  void refresh_committed_forces();
  /// Whether the tangent of the last assembly (a converged state) is positive definite.
  bool tangent_is_positive_definite() const;
  void revert();

  /// One committed substep of the last step_to(), for retrace_last_path().
  struct PathSubstep {
    double control = 0.0;
    bool passed_limit_point = false;
    bool stable = true; ///< whether its equilibrium was stable (or accepted unstable)
    std::vector<element::NodeConfiguration> nodes; ///< the configuration it converged to
  };
  /// Largest motion between two configurations of the prescribed nodes (rotation angle
  /// times the model's size).
  double motion_distance(std::span<const element::NodeConfiguration> from,
                         std::span<const element::NodeConfiguration> to) const;
  /// Why the last path cannot be retraced to the current target; empty when it can.
  std::string retrace_refusal() const;
  /// Substep `failed` of the path found no equilibrium near its recorded one (or landed on
  /// another branch): jumps there, at its control, to the branch the next recorded jump reached,
  /// and rewrites the path (that substep a jump, the ones up to the old jump steps along the
  /// branch reached). False, the trial state reverted, without a later jump or when the jump's
  /// Newton fails.
  bool retrace_early_jump(std::size_t failed, StepReport& report);
  /// Retraces a substep that passed a limit point: Newton from the configuration the jump
  /// came to rest at last time, its energy booked as pseudo_transient books it. False (the
  /// caller reverts) when Newton does not converge there, lands far from it, or ends the
  /// path unstable (unstable_end_of_path).
  bool retrace_jump(const PathSubstep& substep, StepReport& report);
  /// Whether the retraced (assembled) state of `substep` ends the path on an unstable
  /// equilibrium where step_to's ended on a stable one: the committed end of a global step
  /// must be as stable as the adaptive solve found it (an unstable equilibrium accepted
  /// would be left by the next step's adaptive solve through a jump); the tangent is checked
  /// like try_increment's, for the last substep only.
  bool unstable_end_of_path(const PathSubstep& substep) const;
  /// The fields save_state and load_state archive, in one list.
  template <class Archive, class Self> static void archive_committed(Archive& archive, Self& self);

  model::Model& model_;

  NewtonSettings settings_;
  std::optional<std::pair<int, model::Dof>> displacement_control_;
  Eigen::VectorXd reference_load_;
  Eigen::VectorXd constant_load_;

  std::vector<int> equation_;  // global DOF -> free equation or -1
  std::vector<int> free_dofs_; // free equation -> global DOF

  std::vector<element::NodeConfiguration> committed_;
  std::vector<element::NodeConfiguration> trial_;
  Eigen::VectorXd internal_force_;
  Eigen::VectorXd committed_internal_force_;
  double force_scale_ = 0.0;  // largest element force component of the last assembly
  double model_extent_ = 1.0; // largest coordinate magnitude (mm), for the round-off floor
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> tangent_; // free x free
  Eigen::VectorXd control_column_;      // d F_free / d control
  // The tangent's pattern is fixed by the elements' nodes: the first assembly builds it from
  // triplets, and later ones add each free x free entry straight into its value slot (in
  // the same order, so the sums are the same). The slot of every entry in element order,
  // and the elements' nodes it was built for (a change rebuilds it).
  std::vector<int> tangent_slots_;
  std::vector<int> slot_element_nodes_;
  bool tangent_slots_valid_ = false;
  Eigen::SparseMatrix<double> regularised_tangent_; // tangent + viscosity (pseudo-time steps)
  // d (prescribed DOF) / d control, all DOF (zero but at the controlled ones)
  Eigen::VectorXd control_rate_;
  // prescribed motion: nodes, their configuration at control 0, targets, rotation vectors
  std::vector<int> motion_nodes_;
  std::vector<element::NodeConfiguration> motion_start_;
  std::vector<element::NodeConfiguration> motion_target_;
  std::vector<element::Vector3> motion_rotation_;
  std::vector<int> prescribed_index_;             // global DOF -> prescribed DOF index or -1
  Eigen::MatrixXd tangent_free_prescribed_;       // K_fp
  Eigen::MatrixXd tangent_prescribed_free_;       // K_pf
  Eigen::MatrixXd tangent_prescribed_prescribed_; // K_pp
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver_;
  bool pattern_analysed_ = false;

  double control_value_ = 0.0;
  double control_force_ = 0.0;
  EnergyBalance energy_;
  int total_iterations_ = 0;
  int total_substeps_ = 0;
  int regularised_steps_ = 0;
  int unstable_accepted_ = 0;
  int energy_cuts_ = 0;
  int energy_tolerance_missed_ = 0;
  int far_branch_cuts_ = 0;
  int retraced_steps_ = 0;
  SolverWork work_;
  // the last step_to() under prescribed motion: where it started, its target, its substeps
  bool recording_path_ = false;
  std::vector<element::NodeConfiguration> path_start_;
  double path_start_control_ = 0.0;
  std::vector<element::NodeConfiguration> path_target_;
  std::vector<PathSubstep> path_;
  double energy_error_sum_ = 0.0;   // sum over committed steps of |work - change of energy|
  double released_at_commit_ = 0.0; // released_by_laws at the last commit
  bool committed_stable_ = true;
  Eigen::VectorXd moved_; // free-DOF motion since the start of a pseudo-time step
  std::string last_pseudo_failure_;

  model::ElementEvaluations evaluations_; // the elements' forces and tangents per assembly
};

} // namespace brb::analysis
