// Static equilibrium of a SolidModel by Newton-Raphson on the free DOFs with the
// consistent tangent (sparse LU: the steel law's tangent is not symmetric), for the
// elastic acceptance checks (patch test, bar, cantilever) and small static steps.
#pragma once

#include "brb/solid/solid_model.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace brb::solid {

/// Prescribed displacements: DOF (3 node + direction) and value (mm).
struct PrescribedDisplacements {
  std::vector<int> dofs;
  std::vector<double> values;

  void add(int node, int direction, double value) {
    dofs.push_back(3 * node + direction);
    values.push_back(value);
  }
};

struct SolidNewtonSettings {
  int max_iterations = 30;
  /// Converged when |f_ext - f_int|_inf over the free DOFs <= tolerance x (largest internal
  /// force component + largest external force + 1 N).
  double tolerance = 1e-10;
};

struct SolidNewtonReport {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0; ///< |f_ext - f_int|_inf over the free DOFs at the end (N)
  std::string failure;
};

/// Solves f_int(u) = f_ext on the free DOFs with u = prescribed on the others, starting from
/// `displacement` (its prescribed entries are overwritten first). On convergence the state
/// is committed and `displacement` holds the solution; otherwise the model's committed state
/// is untouched. `reactions`, when given, receives f_int - f_ext on every DOF (the support
/// reactions on the prescribed ones).
template <class Law>
SolidNewtonReport
solve_static(SolidModel<Law>& model, Eigen::VectorXd& displacement,
             const PrescribedDisplacements& prescribed, const Eigen::VectorXd& external_force,
             const SolidNewtonSettings& settings = {}, Eigen::VectorXd* reactions = nullptr);

} // namespace brb::solid
