// BRBElement: the `full` BRB macro element in `condensed` mode (DESIGN.md section 4). Two
// outer nodes (12 DOF) face the model; inside, the whole brace model of build_brace_model
// (core chain, casing chain, contact links, stopper) is solved by a nested StaticAnalysis
// under the prescribed motion of its two end nodes, from the element's committed state to
// the trial configuration of the outer nodes, with every fallback of StaticAnalysis
// (substepping of the end-motion increment, pseudo-transient continuation through the mode
// jumps of the restrained core, the stability check). It returns the outer-node forces and
// the statically condensed tangent K_oo - K_oi K_ii^-1 K_io.
//
// Layer: it owns a Model and a StaticAnalysis, so it lives in the analysis layer (an element
// made of a solved sub-model); the global model holds it through element::Element like any
// other element.
//
// Orientation: the internal model lies along local x from the origin (the brace's own
// axes: axis from the start to the end node, section y, section z; BracePlacement). Outer
// configurations are rotated into those axes (x_l = Q^T (x - X_start), R_l = Q^T R Q),
// forces and tangent back (f = Q f_l, K = T K_l T^T, T = diag(Q, Q, Q, Q)): the response is
// objective by construction.
//
// Path dependence: every evaluation restarts from the committed internal state (a twin
// model holds the committed element states, AnalysisPathState the committed path), because
// the nested solver commits its substeps; commit() takes the trial internal state over,
// revert_to_committed() drops it. The first evaluation of a global step solves adaptively
// (StaticAnalysis::step_to); the next ones, at targets near it, retrace that solve's
// substeps with warm starts (StaticAnalysis::retrace_last_path), so that the forces are a
// smooth function of the outer configuration within a global step. A failed internal solve returns
// false with the reason and leaves the committed state untouched; the global solver then cuts its
// step.
//
// Energy: stored = stored energy of the internal elements; dissipated = their dissipation
// plus the energy the internal solver booked as released in jumps (pseudo-transient
// continuation through a snap-through: that energy leaves the static system, like heat, by
// the laws' measure), and the integration misfit their stress work adds, so that a global
// balance external work = stored + dissipated + misfit holds for the element.
//
// Reused tangent (WorkSkips::reuse_tangents, DESIGN.md section 10): asked again at the outer
// configuration of its last evaluation (bit for bit), while its committed history is the one
// that evaluation started from or differs from it by a step that dissipated nothing (no
// plastic flow, damage, slip or jump: the internal brace is then elastic and path
// independent), the element returns that evaluation's forces and tangent instead of solving
// its internal brace again. The implicit frame solver's predictor is the committed
// configuration, so every step of an elastic brace saves one internal solve. Not bit-exact:
// a re-solve would restart from the converged internal state and land within the internal
// solver's tolerance of the same equilibrium, or, for a core in contact with its casing (many
// near-equal equilibria), of a neighbouring one (`brb bench skips` measures the difference).
#pragma once

#include "brb/analysis/brace_indicators.hpp"
#include "brb/analysis/static_analysis.hpp"
#include "brb/model/brace_model.hpp"

#include <array>
#include <optional>

namespace brb::analysis {

class BRBElement final : public element::Element {
public:
  /// nodes: {start, end} outer nodes of the global model at `start` and `end` (reference
  /// positions, the brace's length apart); `section_z`: direction of the section's z axis
  /// (and of a "z" imperfection), default as BracePlacement::between. Throws
  /// ParameterError on an inconsistent spec or placement.
  BRBElement(std::array<int, 2> nodes, const element::Vector3& start, const element::Vector3& end,
             const model::BraceSpec& spec, std::optional<element::Vector3> section_z = std::nullopt,
             NewtonSettings settings = {}, const model::WorkSkips& skips = {});
  BRBElement(const BRBElement&) = delete;
  BRBElement& operator=(const BRBElement&) = delete;

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const element::NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override;
  void revert_to_committed() override;
  void copy_state_from(const Element& other) override;
  element::ElementEnergy energy() const override { return trial_.energy; }

  /// Outputs of the committed state.
  double axial_force() const { return committed_.axial_force; } ///< N, tension positive
  double deformation() const { return committed_.deformation; } ///< mm, change of outer distance
  /// Mean axial strain of the yielding zone: change of its elements' chord lengths over
  /// their initial lengths.
  double core_strain() const { return committed_.core_strain; }
  const BraceIndicators& indicators() const { return tracker_.indicators(); }

  /// The internal brace (local axes) and its nominal properties (yield force, dy).
  const model::BraceHandles& internal_brace() const { return work_; }
  const model::BracePlacement& placement() const { return placement_; }
  /// Internal solver statistics since construction (all evaluations).
  int internal_iterations() const { return analysis_.total_iterations(); }
  int internal_regularised_steps() const { return analysis_.regularised_steps(); }
  /// Evaluations solved by retracing the last internal path (StaticAnalysis::retrace_last_path).
  int internal_retraced_steps() const { return analysis_.retraced_steps(); }
  /// Evaluations answered from the last one (WorkSkips::reuse_tangents).
  long reused_evaluations() const { return reused_evaluations_; }

private:
  struct Outputs {
    double axial_force = 0.0;
    double deformation = 0.0;
    double core_strain = 0.0;
    element::ElementEnergy energy;
  };

  /// Rolls the internal model back to the committed state if an evaluation moved it.
  void restore_committed_internal_state();
  Outputs outputs_of_internal_state() const;

  std::array<int, 2> nodes_;
  model::BracePlacement placement_;
  double length_ = 0.0;
  model::BraceModel work_;            ///< internal model the nested solver moves (local axes)
  model::BraceModel committed_model_; ///< its twin: the committed element states
  StaticAnalysis analysis_;           ///< nested solver on work_.model
  AnalysisPathState committed_path_;
  bool work_is_committed_ = true;
  BraceIndicatorTracker tracker_;
  Outputs trial_;
  Outputs committed_;

  /// The last successful evaluation, for WorkSkips::reuse_tangents.
  struct LastEvaluation {
    bool valid = false;
    std::array<element::NodeConfiguration, 2> configuration;
    Eigen::VectorXd force;
    Eigen::MatrixXd tangent;
    Outputs outputs;
  };
  bool reuse_tangents_ = true;
  LastEvaluation last_;
  long reused_evaluations_ = 0;
};

} // namespace brb::analysis
