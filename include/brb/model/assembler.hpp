// Assembler: evaluates the model's elements at a configuration of the nodes and gathers
// their forces and tangents onto the equations of a DofMap (T^T f, T^T K T). Shared by the
// dynamic and modal analyses. One virtual call per element; the scatter loops are plain.
#pragma once

#include "brb/element/element.hpp"
#include "brb/model/dof_map.hpp"
#include "brb/model/element_evaluations.hpp"
#include "brb/model/model.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <span>
#include <string>
#include <vector>

namespace brb::model {

class Assembler {
public:
  /// `threads`: of the element loop (ElementEvaluations; results the same for any count).
  Assembler(const Model& model, const DofMap& map, int threads = 1);

  /// Evaluates the elements (all, or those with include[e] true) at `nodes` (one
  /// configuration per model node). Returns false with the element's reason when one cannot
  /// evaluate, or when one returns a non-finite force or tangent.
  bool assemble(std::span<const element::NodeConfiguration> nodes, bool with_tangent,
                std::string& failure, const std::vector<bool>* include = nullptr);

  /// Internal forces on every full DOF (reactions at restrained DOF), N and N mm.
  const Eigen::VectorXd& full_force() const { return full_force_; }
  /// T^T f_int.
  const Eigen::VectorXd& reduced_force() const { return reduced_force_; }
  /// T^T K T of the last assembly with a tangent.
  const Eigen::SparseMatrix<double>& reduced_tangent() const { return tangent_; }
  /// Largest element force component of the last assembly (a scale for tolerances).
  double force_scale() const { return force_scale_; }
  /// Sum of the evaluated elements' energies (trial states of the last assembly).
  element::ElementEnergy energy() const;

private:
  const Model& model_;
  const DofMap& map_;
  Eigen::VectorXd full_force_;
  Eigen::VectorXd reduced_force_;
  Eigen::SparseMatrix<double> tangent_;
  std::vector<Eigen::Triplet<double>> triplets_;
  ElementEvaluations evaluations_;
  std::vector<bool> evaluated_;
  double force_scale_ = 0.0;
};

/// Moves node configurations by an increment of the equations times `scale`:
/// translations add (u += T dq), spins rotate the triads (R <- exp([T dq]x) R).
void apply_increment(const DofMap& map, std::span<element::NodeConfiguration> nodes,
                     const Eigen::VectorXd& increment, double scale = 1.0);

/// The nodal displacement of a configuration: translation x - X and the rotation vector of
/// the triad (6 per node), as a full vector.
Eigen::VectorXd full_displacement(const Model& model,
                                  std::span<const element::NodeConfiguration> nodes);

/// Node configurations of the undeformed model.
std::vector<element::NodeConfiguration> initial_configuration(const Model& model);

} // namespace brb::model
