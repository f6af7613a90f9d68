// DofMap: from the model's full DOF (6 per node) to the equations a solver works with.
// Every full DOF is either restrained (zero), an equation of its own, or a linear
// combination of equations (a constrained DOF: equal DOF, rigid diaphragm). With T the
// (full x equations) transformation, u_full = T q, and the solver's system is the
// congruent one: residual T^T (f_ext - f_int), tangent T^T K T, mass T^T M T
// (master-slave elimination, e.g. Cook et al., Concepts and Applications of FEA, sec. 9.2).
//
// A planar frame (dimension 2) lives in the X-Z plane: uy, rx and rz of every node are
// removed, which leaves ux, uz, ry (one code path with 3D models).
#pragma once

#include "brb/model/model.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <span>
#include <vector>

namespace brb::model {

/// One term of a full DOF's expression in the equations: u_full += factor * q[equation].
struct DofTerm {
  int equation = -1;
  double factor = 0.0;
};

class DofMap {
public:
  /// Numbers the equations of `model` (dimension 2: planar in X-Z; 3: full 3D).
  /// Throws std::invalid_argument for a DOF slaved twice, a cycle of constraints, a
  /// restrained slave DOF, a diaphragm on a planar model, or a dimension other than 2 or 3.
  static DofMap build(const Model& model, int dimension);

  int equation_count() const { return equation_count_; }
  int full_dof_count() const { return static_cast<int>(offsets_.size()) - 1; }
  int dimension() const { return dimension_; }

  /// The terms of a full DOF (empty: restrained or removed).
  std::span<const DofTerm> terms(int full_dof) const {
    return {terms_.data() + offsets_[full_dof],
            static_cast<std::size_t>(offsets_[full_dof + 1] - offsets_[full_dof])};
  }
  /// The equation of a full DOF that is an independent unknown, else -1.
  int independent_equation(int full_dof) const { return independent_[full_dof]; }

  /// u_full = T q (translations and spin components of every node).
  Eigen::VectorXd expand(const Eigen::VectorXd& equations) const;
  /// T^T f: a full force vector reduced to the equations.
  Eigen::VectorXd reduce(const Eigen::VectorXd& full) const;
  /// T as a sparse matrix (full x equations).
  const Eigen::SparseMatrix<double>& transformation() const { return transformation_; }
  /// T^T diag(m) T: the model's lumped masses on the equations (sparse; diagonal unless a
  /// constraint couples a slave's mass to its master's rotation).
  Eigen::SparseMatrix<double> reduced_mass(const Model& model) const;
  /// The influence vector of a uniform ground translation along `direction` (global unit
  /// vector): the equations' displacements when every node translates rigidly by direction,
  /// r with T r = translation of every free node (least squares not needed: a rigid
  /// translation is representable whenever no translation is restrained, and restrained
  /// DOF move with the ground).
  Eigen::VectorXd ground_influence(const Eigen::Vector3d& direction) const;

private:
  int dimension_ = 3;
  int equation_count_ = 0;
  std::vector<int> offsets_; // full DOF -> first term (size full + 1)
  std::vector<DofTerm> terms_;
  std::vector<int> independent_;
  Eigen::SparseMatrix<double> transformation_;
};

} // namespace brb::model
