// Modal analysis (modal_analysis.hpp). Equations split into those with mass (m) and without
// (o). The massless rows are static, K_oo phi_o + K_om phi_m = 0, so the eigenproblem reduces
// exactly to (K_mm - K_mo K_oo^-1 K_om) phi_m = w^2 M_mm phi_m (static condensation; e.g.
// Chopra, Dynamics of Structures, sec. 9.3), solved densely; phi_o = -K_oo^-1 K_om phi_m.
// The tangent's symmetric part is used (a tangent is non-symmetric only through geometric or
// non-associated terms, and vibration is a property of the quadratic form).
#include "brb/analysis/modal_analysis.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace brb::analysis {

std::vector<Mode> modal_analysis(const Eigen::SparseMatrix<double>& tangent,
                                 const Eigen::SparseMatrix<double>& mass, const model::DofMap& map,
                                 int count) {
  const Eigen::Index equations = map.equation_count();
  if (tangent.rows() != equations || tangent.cols() != equations || mass.rows() != equations ||
      mass.cols() != equations)
    throw std::invalid_argument("modal analysis: the tangent and mass must be " +
                                std::to_string(equations) + " x " + std::to_string(equations) +
                                " (the DOF map's equations)");
  // Split: an equation has mass when its diagonal mass is positive (a positive semi-definite
  // lumped mass T^T M T has zero rows wherever its diagonal is zero).
  std::vector<Eigen::Index> massive, massless;
  const Eigen::VectorXd mass_diagonal = Eigen::MatrixXd(mass).diagonal();
  for (Eigen::Index i = 0; i < equations; ++i)
    (mass_diagonal[i] > 0.0 ? massive : massless).push_back(i);
  if (massive.empty())
    throw std::runtime_error("modal analysis: the model has no mass on its equations");

  const Eigen::MatrixXd dense_tangent = Eigen::MatrixXd(tangent);
  const Eigen::MatrixXd stiffness = 0.5 * (dense_tangent + dense_tangent.transpose());
  const Eigen::MatrixXd dense_mass = Eigen::MatrixXd(mass);
  const auto m = static_cast<Eigen::Index>(massive.size());
  const auto o = static_cast<Eigen::Index>(massless.size());
  const Eigen::MatrixXd k_mm = stiffness(massive, massive);
  const Eigen::MatrixXd m_mm = dense_mass(massive, massive);

  Eigen::MatrixXd condensed = k_mm;
  Eigen::MatrixXd recovery(o, m); // phi_o = recovery phi_m
  if (o > 0) {
    const Eigen::MatrixXd k_oo = stiffness(massless, massless);
    const Eigen::MatrixXd k_om = stiffness(massless, massive);
    const Eigen::LLT<Eigen::MatrixXd> factor(k_oo);
    if (factor.info() != Eigen::Success)
      throw std::runtime_error("modal analysis: the stiffness of the massless equations is not "
                               "positive definite (a mechanism)");
    recovery = -factor.solve(k_om);
    condensed += k_om.transpose() * recovery;
  }
  if (Eigen::LLT<Eigen::MatrixXd>(condensed).info() != Eigen::Success)
    throw std::runtime_error("modal analysis: the condensed stiffness is not positive definite "
                             "(a mechanism, or an unstable state)");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(condensed, m_mm);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("modal analysis: the eigensolver failed (is the mass matrix of the "
                             "equations with mass singular?)");

  std::array<Eigen::VectorXd, 3> influence;
  Eigen::Vector3d direction_mass;
  for (int d = 0; d < 3; ++d) {
    influence[d] = map.ground_influence(Eigen::Vector3d::Unit(d));
    direction_mass[d] = influence[d].dot(mass * influence[d]);
  }

  const int modes = std::min<int>(std::max(count, 0), static_cast<int>(m));
  std::vector<Mode> result;
  result.reserve(static_cast<std::size_t>(modes));
  for (int j = 0; j < modes; ++j) {
    Mode mode;
    const double eigenvalue = solver.eigenvalues()[j];
    mode.circular_frequency = std::sqrt(eigenvalue);
    mode.period = 2.0 * std::numbers::pi / mode.circular_frequency;
    // Eigen normalises phi_m^T M_mm phi_m = 1; the massless part adds no mass.
    const Eigen::VectorXd shape_massive = solver.eigenvectors().col(j);
    mode.shape = Eigen::VectorXd::Zero(equations);
    mode.shape(massive) = shape_massive;
    if (o > 0)
      mode.shape(massless) = recovery * shape_massive;
    // A deterministic sign: the largest component positive.
    Eigen::Index largest = 0;
    mode.shape.cwiseAbs().maxCoeff(&largest);
    if (mode.shape[largest] < 0.0)
      mode.shape = -mode.shape;
    const Eigen::VectorXd mass_shape = mass * mode.shape;
    for (int d = 0; d < 3; ++d) {
      if (!(direction_mass[d] > 0.0))
        continue;
      mode.participation[d] = mass_shape.dot(influence[d]);
      mode.effective_mass_ratio[d] =
          mode.participation[d] * mode.participation[d] / direction_mass[d];
    }
    result.push_back(std::move(mode));
  }
  return result;
}

} // namespace brb::analysis
