// Modal analysis: K phi = w^2 M phi on the equations of a DofMap. DOF without mass are
// condensed statically first (exact for the eigenproblem: their rows are static,
// K_oo phi_o + K_om phi_m = 0), then the dense symmetric-definite problem is solved
// (Eigen GeneralizedSelfAdjointEigenSolver). Shapes are mass-normalised.
#pragma once

#include "brb/model/dof_map.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <vector>

namespace brb::analysis {

struct Mode {
  double circular_frequency = 0.0; ///< rad/s
  double period = 0.0;             ///< s
  Eigen::VectorXd shape;           ///< equations, phi^T M phi = 1
  /// Gamma_d = phi^T M r_d and effective-mass ratio Gamma_d^2 / (r_d^T M r_d) for ground
  /// directions X, Y, Z (0 where the model has no mass along d).
  Eigen::Vector3d participation = Eigen::Vector3d::Zero();
  Eigen::Vector3d effective_mass_ratio = Eigen::Vector3d::Zero();
};

/// The `count` lowest modes (fewer if the model has fewer DOF with mass). Throws
/// std::runtime_error when the (condensed) stiffness is not positive definite (a
/// mechanism) or the model has no mass.
std::vector<Mode> modal_analysis(const Eigen::SparseMatrix<double>& tangent,
                                 const Eigen::SparseMatrix<double>& mass, const model::DofMap& map,
                                 int count);

} // namespace brb::analysis
