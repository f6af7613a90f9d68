#include "brb/solid/solid_static.hpp"

#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"

#include <Eigen/SparseLU>

#include <algorithm>
#include <stdexcept>

namespace brb::solid {

template <class Law>
SolidNewtonReport solve_static(SolidModel<Law>& model, Eigen::VectorXd& displacement,
                               const PrescribedDisplacements& prescribed,
                               const Eigen::VectorXd& external_force,
                               const SolidNewtonSettings& settings, Eigen::VectorXd* reactions) {
  const int n = model.dof_count();
  if (displacement.size() != n || external_force.size() != n ||
      prescribed.dofs.size() != prescribed.values.size())
    throw std::invalid_argument("solve_static: vector sizes do not match the model's DOFs");
  // free DOF numbering; the jump of the prescribed values from the starting state
  std::vector<int> equation(n, 0);
  Eigen::VectorXd jump = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < prescribed.dofs.size(); ++i) {
    const int dof = prescribed.dofs[i];
    if (dof < 0 || dof >= n)
      throw std::invalid_argument("solve_static: prescribed DOF " + std::to_string(dof) +
                                  " is not a DOF of the model");
    equation[dof] = -1;
    jump[dof] = prescribed.values[i] - displacement[dof];
  }
  int free_count = 0;
  for (int& e : equation)
    e = e < 0 ? -1 : free_count++;

  SolidNewtonReport report;
  Eigen::VectorXd force;
  Eigen::SparseMatrix<double> tangent;
  Eigen::VectorXd residual(free_count);
  const double external_scale =
      external_force.size() > 0 ? external_force.cwiseAbs().maxCoeff() : 0;
  // K_ff x = rhs on the free DOFs; false when K_ff is singular
  const auto solve_free = [&](const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(tangent.nonZeros());
    for (int column = 0; column < tangent.outerSize(); ++column) {
      if (equation[column] < 0)
        continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(tangent, column); it; ++it) {
        if (equation[it.row()] >= 0)
          triplets.emplace_back(equation[it.row()], equation[column], it.value());
      }
    }
    Eigen::SparseMatrix<double> free_tangent(free_count, free_count);
    free_tangent.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    solver.compute(free_tangent);
    if (solver.info() != Eigen::Success)
      return false;
    x = solver.solve(rhs);
    return true;
  };

  // Tangent predictor: the free DOFs follow the jump of the prescribed ones through the
  // tangent of the starting state, K_ff du_f = (f_ext - f_int)_f - K_fp du_p. Moving the
  // prescribed DOFs alone would strain only the elements next to them (a softening law would
  // then damage them in the first iteration, and Newton would leave the path).
  if (jump.cwiseAbs().maxCoeff() > 0.0 && free_count > 0 &&
      model.evaluate(displacement, force, &tangent, report.failure)) {
    const Eigen::VectorXd coupling = tangent * jump;
    for (int dof = 0; dof < n; ++dof) {
      if (equation[dof] >= 0)
        residual[equation[dof]] = external_force[dof] - force[dof] - coupling[dof];
    }
    Eigen::VectorXd predictor;
    if (solve_free(residual, predictor)) {
      for (int dof = 0; dof < n; ++dof) {
        if (equation[dof] >= 0)
          displacement[dof] += predictor[equation[dof]];
      }
    }
  }
  report.failure.clear();
  for (std::size_t i = 0; i < prescribed.dofs.size(); ++i)
    displacement[prescribed.dofs[i]] = prescribed.values[i];

  for (int iteration = 0;; ++iteration) {
    if (!model.evaluate(displacement, force, &tangent, report.failure))
      return report;
    for (int dof = 0; dof < n; ++dof) {
      if (equation[dof] >= 0)
        residual[equation[dof]] = external_force[dof] - force[dof];
    }
    report.iterations = iteration;
    report.residual = free_count > 0 ? residual.cwiseAbs().maxCoeff() : 0.0;
    const double scale = force.cwiseAbs().maxCoeff() + external_scale + 1.0;
    if (report.residual <= settings.tolerance * scale)
      break;
    if (iteration == settings.max_iterations) {
      report.failure = "no convergence in " + std::to_string(iteration) +
                       " Newton iterations (residual " + std::to_string(report.residual) + " N)";
      return report;
    }
    Eigen::VectorXd correction;
    if (!solve_free(residual, correction)) {
      report.failure = "the tangent is singular (a mechanism: check the supports)";
      return report;
    }
    for (int dof = 0; dof < n; ++dof) {
      if (equation[dof] >= 0)
        displacement[dof] += correction[equation[dof]];
    }
  }
  model.commit();
  report.converged = true;
  if (reactions != nullptr)
    *reactions = force - external_force;
  return report;
}

template SolidNewtonReport solve_static(SolidModel<material::IsotropicElastic3D>&, Eigen::VectorXd&,
                                        const PrescribedDisplacements&, const Eigen::VectorXd&,
                                        const SolidNewtonSettings&, Eigen::VectorXd*);
template SolidNewtonReport solve_static(SolidModel<material::SteelDamagePlasticity3D>&,
                                        Eigen::VectorXd&, const PrescribedDisplacements&,
                                        const Eigen::VectorXd&, const SolidNewtonSettings&,
                                        Eigen::VectorXd*);

template SolidNewtonReport solve_static(SolidModel<material::MortarDamage3D>&, Eigen::VectorXd&,
                                        const PrescribedDisplacements&, const Eigen::VectorXd&,
                                        const SolidNewtonSettings&, Eigen::VectorXd*);

} // namespace brb::solid
