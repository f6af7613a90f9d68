#include "brb/analysis/static_analysis.hpp"

#include "brb/element/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace brb::analysis {

using element::NodeConfiguration;
using model::kDofPerNode;

namespace {

/// A number for messages: 6 significant digits.
std::string readable(double value) {
  std::ostringstream text;
  text << std::setprecision(6) << value;
  return text.str();
}

} // namespace

double EnergyBalance::relative_error() const {
  return std::abs(external_work - stored - dissipated - released_in_jumps) /
         std::max(gross_work, 1e-30);
}

StaticAnalysis::StaticAnalysis(model::Model& model, NewtonSettings settings)
    : model_(model), settings_(settings) {
  committed_.resize(model_.node_count());
  for (int node = 0; node < model_.node_count(); ++node) {
    committed_[node].position = model_.coordinates(node);
  }
  trial_ = committed_;
  internal_force_ = Eigen::VectorXd::Zero(model_.dof_count());
  committed_internal_force_ = internal_force_;
  reference_load_ = Eigen::VectorXd::Zero(model_.dof_count());
  constant_load_ = Eigen::VectorXd::Zero(model_.dof_count());
  number_equations();
  for (int node = 0; node < model_.node_count(); ++node) {
    model_extent_ = std::max(model_extent_, model_.coordinates(node).cwiseAbs().maxCoeff());
  }
  model_extent_ = std::max(model_extent_, 1.0);
}

void StaticAnalysis::use_displacement_control(int node, model::Dof dof) {
  if (dof >= model::rx)
    throw std::invalid_argument("displacement control needs a translation DOF");
  if (model_.is_fixed(node, dof))
    throw std::invalid_argument("the controlled DOF is restrained");
  displacement_control_ = {node, dof};
  control_value_ = committed_[node].position[dof] - model_.coordinates(node)[dof];
  number_equations();
}

void StaticAnalysis::use_load_control(const Eigen::VectorXd& reference_load) {
  if (reference_load.size() != model_.dof_count())
    throw std::invalid_argument("load vector size");
  displacement_control_.reset();
  reference_load_ = reference_load;
  control_value_ = 0.0;
  number_equations();
}

void StaticAnalysis::set_constant_load(const Eigen::VectorXd& load) {
  if (load.size() != model_.dof_count())
    throw std::invalid_argument("load vector size");
  constant_load_ = load;
}

void StaticAnalysis::number_equations() {
  equation_.assign(model_.dof_count(), -1);
  free_dofs_.clear();
  for (int node = 0; node < model_.node_count(); ++node) {
    for (int dof = 0; dof < kDofPerNode; ++dof) {
      const auto d = static_cast<model::Dof>(dof);
      const bool controlled = displacement_control_ && displacement_control_->first == node &&
                              displacement_control_->second == d;
      if (model_.is_fixed(node, d) || controlled)
        continue;
      equation_[model::Model::global_dof(node, d)] = static_cast<int>(free_dofs_.size());
      free_dofs_.push_back(model::Model::global_dof(node, d));
    }
  }
  pattern_analysed_ = false;
}

bool StaticAnalysis::assemble(bool with_tangent, std::string& failure) {
  internal_force_.setZero();
  force_scale_ = 0.0;
  const int control_dof =
      displacement_control_
          ? model::Model::global_dof(displacement_control_->first, displacement_control_->second)
          : -1;
  if (with_tangent) {
    triplets_.clear();
    control_column_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  }
  for (const auto& element : model_.elements()) {
    const auto nodes = element->nodes();
    element_nodes_.resize(nodes.size());
    for (std::size_t a = 0; a < nodes.size(); ++a)
      element_nodes_[a] = trial_[nodes[a]];
    if (!element->evaluate(element_nodes_, element_force_, element_tangent_, failure)) {
      return false;
    }
    if (!element_force_.allFinite() || (with_tangent && !element_tangent_.allFinite())) {
      failure = "an element returned a non-finite force or tangent";
      return false;
    }
    force_scale_ = std::max(force_scale_, element_force_.lpNorm<Eigen::Infinity>());
    const int element_dofs = static_cast<int>(nodes.size()) * kDofPerNode;
    for (int a = 0; a < element_dofs; ++a) {
      const int row = kDofPerNode * nodes[a / kDofPerNode] + a % kDofPerNode;
      internal_force_[row] += element_force_[a];
      if (!with_tangent || equation_[row] < 0)
        continue;
      for (int b = 0; b < element_dofs; ++b) {
        const int column = kDofPerNode * nodes[b / kDofPerNode] + b % kDofPerNode;
        const double value = element_tangent_(a, b);
        if (equation_[column] >= 0) {
          triplets_.emplace_back(equation_[row], equation_[column], value);
        } else if (column == control_dof) {
          control_column_[equation_[row]] += value;
        }
      }
    }
  }
  if (with_tangent) {
    const auto size = static_cast<Eigen::Index>(free_dofs_.size());
    tangent_.resize(size, size);
    tangent_.setFromTriplets(triplets_.begin(), triplets_.end());
  }
  return true;
}

Eigen::VectorXd StaticAnalysis::free_residual(double control) const {
  Eigen::VectorXd residual(static_cast<Eigen::Index>(free_dofs_.size()));
  const bool load_control = !displacement_control_;
  for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
    const int dof = free_dofs_[e];
    double external = constant_load_[dof];
    if (load_control)
      external += control * reference_load_[dof];
    residual[static_cast<Eigen::Index>(e)] = external - internal_force_[dof];
  }
  return residual;
}

void StaticAnalysis::apply_free_increment(const Eigen::VectorXd& increment, double scale) {
  for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
    const int dof = free_dofs_[e];
    const int node = dof / kDofPerNode, component = dof % kDofPerNode;
    const double value = scale * increment[static_cast<Eigen::Index>(e)];
    if (component < 3) {
      trial_[node].position[component] += value;
    }
  }
  // spins: R <- exp([dw]x) R, one rotation per node
  for (int node = 0; node < model_.node_count(); ++node) {
    element::Vector3 spin = element::Vector3::Zero();
    bool any = false;
    for (int k = 0; k < 3; ++k) {
      const int e = equation_[kDofPerNode * node + 3 + k];
      if (e >= 0) {
        spin[k] = scale * increment[e];
        any = true;
      }
    }
    if (any)
      trial_[node].rotation = element::rotation_from_vector(spin) * trial_[node].rotation;
  }
}

void StaticAnalysis::set_control_value(double value) {
  if (displacement_control_) {
    const auto [node, dof] = *displacement_control_;
    trial_[node].position[dof] = model_.coordinates(node)[dof] + value;
  }
}

bool StaticAnalysis::residual_converged(const Eigen::VectorXd& residual, double control) const {
  // Round-off in the residual is relative to the largest element force, not to the
  // assembled sum (large axial forces cancel at the nodes of a chain), and it has a floor:
  // positions carry a relative error of ~1e-16 of the model's size, which the stiffest
  // element turns into force. The tolerance must stay above both.
  if (residual.size() == 0)
    return true; // every DOF is restrained or prescribed: nothing to balance
  const double load =
      constant_load_.lpNorm<Eigen::Infinity>() +
      (displacement_control_ ? 0.0 : std::abs(control) * reference_load_.lpNorm<Eigen::Infinity>());
  const double round_off_floor = 1e-14 * model_extent_ * tangent_.diagonal().cwiseAbs().maxCoeff() /
                                 settings_.relative_force_tolerance;
  const double scale = force_scale_ + load + round_off_floor + 1e-6;
  return residual.lpNorm<Eigen::Infinity>() <= settings_.relative_force_tolerance * scale;
}

StaticAnalysis::Attempt StaticAnalysis::newton(double control, double viscosity,
                                               int max_iterations) {
  Attempt attempt;
  bool assembled = false;
  Eigen::VectorXd residual;
  // With viscosity c > 0 this is one backward-Euler step of the gradient flow
  // c du/dtau = F_ext - F_int(u) (pseudo-time step 1): the residual gains -c (u - u_start),
  // the tangent c I. `moved_` holds u - u_start of the free DOF (spins for rotations).
  moved_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  const auto pseudo_residual = [&] {
    Eigen::VectorXd r = free_residual(control);
    if (viscosity > 0.0)
      r -= viscosity * moved_;
    return r;
  };
  for (int iteration = 0; iteration <= max_iterations; ++iteration) {
    if (!assembled && !assemble(true, attempt.failure))
      return attempt;
    assembled = false;
    residual = pseudo_residual();
    if (!residual.allFinite()) {
      attempt.failure = "non-finite residual";
      return attempt;
    }
    if (residual_converged(residual, control)) {
      attempt.converged = true;
      attempt.iterations = iteration;
      return attempt;
    }
    if (iteration == max_iterations)
      break;

    Eigen::SparseMatrix<double> matrix = tangent_;
    if (viscosity > 0.0) {
      for (Eigen::Index k = 0; k < matrix.rows(); ++k)
        matrix.coeffRef(k, k) += viscosity;
    }
    if (!pattern_analysed_) {
      solver_.analyzePattern(matrix);
      pattern_analysed_ = true;
    }
    solver_.factorize(matrix);
    if (solver_.info() != Eigen::Success) {
      attempt.failure = "singular tangent stiffness";
      return attempt;
    }
    const Eigen::VectorXd increment = solver_.solve(residual);
    if (!increment.allFinite()) {
      attempt.failure = "non-finite Newton increment";
      return attempt;
    }

    // Backtracking line search on the residual norm.
    const std::vector<NodeConfiguration> start = trial_;
    const Eigen::VectorXd start_moved = moved_;
    const double start_norm = residual.norm();
    double step = 1.0;
    for (int search = 0;; ++search) {
      apply_free_increment(increment, step);
      moved_ = start_moved + step * increment;
      std::string failure;
      const bool ok = assemble(true, failure);
      const bool accept =
          ok && (!settings_.line_search || search == 6 || pseudo_residual().norm() < start_norm);
      if (accept) {
        assembled = true;
        break;
      }
      if (search == 6) {
        attempt.failure = failure.empty() ? "line search failed" : failure;
        return attempt;
      }
      trial_ = start;
      step *= 0.5;
    }
  }
  attempt.failure =
      "Newton-Raphson did not converge in " + std::to_string(max_iterations) + " iterations";
  attempt.iterations = max_iterations;
  return attempt;
}

double StaticAnalysis::increment_work() const {
  // Work of the converged forces over the increment (trapezoidal); translations are
  // additive, rotations enter through the incremental rotation vector.
  double work = 0.0;
  for (int node = 0; node < model_.node_count(); ++node) {
    const element::Vector3 translation = trial_[node].position - committed_[node].position;
    const element::Vector3 rotation = element::vector_from_rotation(
        trial_[node].rotation * committed_[node].rotation.transpose());
    for (int k = 0; k < 3; ++k) {
      const int t = kDofPerNode * node + k, r = t + 3;
      work += 0.5 * (committed_internal_force_[t] + internal_force_[t]) * translation[k];
      work += 0.5 * (committed_internal_force_[r] + internal_force_[r]) * rotation[k];
    }
  }
  return work;
}

bool StaticAnalysis::within_energy_tolerance() const {
  if (!(settings_.energy_tolerance > 0.0))
    return true;
  const double work = increment_work();
  const element::ElementEnergy energy = element_energy();
  const double change = energy.stored + energy.dissipated - energy_.stored - energy_.dissipated;
  const double step_error = work - change;
  // Round-off floor: the energies are sums of many terms of their own size.
  const double round_off =
      1e-13 * (std::abs(energy.stored) + std::abs(energy.dissipated) + std::abs(work));
  return std::abs(energy_error_sum_ + step_error) <=
         settings_.energy_tolerance * (energy_.gross_work + std::abs(work)) + round_off;
}

void StaticAnalysis::commit(double control) {
  // A step that passed a limit point brings its own work (see pseudo_transient).
  const double work = jump_work_ ? *jump_work_ : increment_work();
  const double energy_before = energy_.stored + energy_.dissipated + released_at_commit_;
  energy_.external_work += work;
  energy_.gross_work += std::abs(work);
  jump_work_.reset();
  for (const auto& element : model_.elements())
    element->commit();
  committed_ = trial_;
  committed_internal_force_ = internal_force_;
  control_value_ = control;
  if (displacement_control_) {
    control_force_ = internal_force_[model::Model::global_dof(displacement_control_->first,
                                                              displacement_control_->second)];
  } else {
    control_force_ = reference_load_.dot(internal_force_);
  }
  const element::ElementEnergy energy = element_energy();
  energy_.stored = energy.stored;
  energy_.dissipated = energy.dissipated;
  released_at_commit_ = energy_.released_in_jumps;
  energy_error_sum_ +=
      work - (energy_.stored + energy_.dissipated + energy_.released_in_jumps - energy_before);
}

void StaticAnalysis::revert() {
  trial_ = committed_;
  for (const auto& element : model_.elements())
    element->revert_to_committed();
}

bool StaticAnalysis::try_increment(double from, double to, int depth, StepReport& report) {
  report.deepest_halving = std::max(report.deepest_halving, depth);
  // Tangent predictor from the converged state.
  revert();
  Attempt attempt;
  if (assemble(true, attempt.failure)) {
    Eigen::VectorXd load;
    if (displacement_control_) {
      load = -(to - from) * control_column_;
    } else {
      load = Eigen::VectorXd(static_cast<Eigen::Index>(free_dofs_.size()));
      for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
        load[static_cast<Eigen::Index>(e)] = (to - from) * reference_load_[free_dofs_[e]];
      }
    }
    set_control_value(to);
    // (SparseLU does not return on an empty matrix: with no free DOF there is nothing to
    // predict.)
    if (tangent_.rows() > 0 && !pattern_analysed_) {
      solver_.analyzePattern(tangent_);
      pattern_analysed_ = true;
    }
    if (tangent_.rows() > 0)
      solver_.factorize(tangent_);
    if (tangent_.rows() > 0 && solver_.info() == Eigen::Success) {
      const Eigen::VectorXd predictor = solver_.solve(load);
      if (predictor.allFinite())
        apply_free_increment(predictor, 1.0);
    }
    attempt = newton(to, 0.0, settings_.max_iterations);
  }
  report.iterations += attempt.iterations;
  const bool at_floor = depth >= settings_.max_halvings;
  bool stable = true;
  if (attempt.converged && settings_.require_stable_equilibrium) {
    stable = tangent_is_positive_definite();
    if (!stable && committed_stable_ && depth < settings_.stability_halvings) {
      attempt.converged = false;
      attempt.failure = "converged to an unstable equilibrium";
    }
  }
  if (attempt.converged && !within_energy_tolerance()) {
    if (depth < std::min(settings_.energy_halvings, settings_.max_halvings)) {
      // A kink inside the step (yield, contact): halve it until the trapezoidal work and
      // the energies agree (NewtonSettings::energy_tolerance).
      ++report.energy_cuts;
      ++energy_cuts_;
      revert();
      const double middle = 0.5 * (from + to);
      return try_increment(from, middle, depth + 1, report) &&
             try_increment(middle, to, depth + 1, report);
    }
    ++report.energy_tolerance_missed;
    ++energy_tolerance_missed_;
  }
  if (attempt.converged) {
    if (settings_.require_stable_equilibrium) {
      if (!stable && committed_stable_) {
        ++report.unstable_accepted;
        ++unstable_accepted_;
      }
      committed_stable_ = stable;
    }
    commit(to);
    ++report.substeps;
    return true;
  }
  revert();
  // Deep in the cuts, a failing step is most likely a limit point (the restrained core
  // jumping to a higher mode), not a step too long for Newton: try to pass it by
  // pseudo-transient continuation before cutting further (cutting cannot pass a limit point).
  if (!at_floor && depth >= settings_.pseudo_transient_depth && pass_limit_point(to, report)) {
    return true;
  }
  if (!at_floor) {
    const double middle = 0.5 * (from + to);
    return try_increment(from, middle, depth + 1, report) &&
           try_increment(middle, to, depth + 1, report);
  }
  if (pass_limit_point(to, report))
    return true;
  revert();
  report.failure =
      "step from " + readable(from) + " to " + readable(to) + ": " + last_pseudo_failure_;
  return false;
}

bool StaticAnalysis::pass_limit_point(double to, StepReport& report) {
  // Pseudo-transient continuation. The static path has no neighbour here (a limit point:
  // the restrained core jumping to a higher buckling mode, a snap-through); follow the
  // gradient flow c du/dtau = F_ext - F_int(u) in pseudo-time until it comes to rest on the
  // next stable branch. The energy the viscosity absorbs on the way is the energy the jump
  // releases; it is booked separately (EnergyBalance::released_in_jumps).
  revert();
  set_control_value(to);
  const Attempt attempt = pseudo_transient(to);
  report.iterations += attempt.iterations;
  if (!attempt.converged) {
    last_pseudo_failure_ = attempt.failure;
    revert();
    return false;
  }
  report.used_regularised_newton = true;
  ++regularised_steps_;
  committed_stable_ = !settings_.require_stable_equilibrium || tangent_is_positive_definite();
  commit(to);
  ++report.substeps;
  return true;
}

StepReport StaticAnalysis::step_to(double target) {
  StepReport report;
  report.substeps = 0;
  report.converged = try_increment(control_value_, target, 0, report);
  total_iterations_ += report.iterations;
  total_substeps_ += report.substeps;
  return report;
}

StepReport StaticAnalysis::initialise() {
  return step_to(control_value_);
}

double StaticAnalysis::displacement(int node, model::Dof dof) const {
  if (dof < model::rx)
    return committed_[node].position[dof] - model_.coordinates(node)[dof];
  return element::vector_from_rotation(committed_[node].rotation)[dof - model::rx];
}

StaticAnalysis::Attempt StaticAnalysis::pseudo_transient(double control) {
  Attempt total;
  if (!assemble(true, total.failure))
    return total;
  // The energy released is what the jump takes out of the system: the drop of stored plus
  // material-dissipated energy, plus the work the (constant) loads do during it.
  const element::ElementEnergy before = element_energy();
  const double control_force_before =
      displacement_control_ ? internal_force_[model::Model::global_dof(
                                  displacement_control_->first, displacement_control_->second)]
                            : 0.0;
  Eigen::VectorXd travelled = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  const double stiffness = tangent_.diagonal().cwiseAbs().mean();
  double viscosity = 1e-3 * stiffness;
  for (int pseudo_step = 0; pseudo_step < settings_.fallback_iterations; ++pseudo_step) {
    const std::vector<NodeConfiguration> start = trial_;
    const Attempt attempt = newton(control, viscosity, settings_.max_iterations);
    total.iterations += attempt.iterations;
    if (!attempt.converged) {
      trial_ = start; // a more viscous (shorter) pseudo-time step from the same state
      viscosity *= 10.0;
      continue;
    }
    travelled += moved_;
    // at rest when the plain residual is below tolerance (the state is assembled)
    if (residual_converged(free_residual(control), control)) {
      total.converged = true;
      const element::ElementEnergy after = element_energy();
      double load_work = 0.0;
      for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
        const int dof = free_dofs_[e];
        const double load =
            constant_load_[dof] + (displacement_control_ ? 0.0 : control * reference_load_[dof]);
        load_work += load * travelled[static_cast<Eigen::Index>(e)];
      }
      energy_.released_in_jumps +=
          before.stored + before.dissipated + load_work - after.stored - after.dissipated;
      // External work of this step: the control moved first (on the old branch, ending at
      // control_force_before), then the jump at fixed control, under constant loads.
      double control_work = 0.0;
      if (displacement_control_) {
        const int dof =
            model::Model::global_dof(displacement_control_->first, displacement_control_->second);
        control_work = 0.5 * (committed_internal_force_[dof] + control_force_before) *
                       (control - control_value_);
      }
      jump_work_ = control_work + load_work;
      return total;
    }
    viscosity = std::max(0.5 * viscosity, 1e-12 * stiffness);
  }
  total.failure = "pseudo-transient continuation did not come to rest in " +
                  std::to_string(settings_.fallback_iterations) + " pseudo-time steps";
  return total;
}

element::ElementEnergy StaticAnalysis::element_energy() const {
  element::ElementEnergy total;
  for (const auto& element : model_.elements()) {
    const auto energy = element->energy();
    total.stored += energy.stored;
    total.dissipated += energy.dissipated;
  }
  return total;
}

bool StaticAnalysis::tangent_is_positive_definite() const {
  if (tangent_.rows() == 0)
    return true;
  // Definiteness of the symmetric part (the tangent is non-symmetric away from equilibrium
  // and with non-associated terms, but stability is a property of the quadratic form).
  const Eigen::SparseMatrix<double> symmetric =
      0.5 * (tangent_ + Eigen::SparseMatrix<double>(tangent_.transpose()));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(symmetric);
  if (factor.info() != Eigen::Success)
    return false;
  return factor.vectorD().minCoeff() > 0.0;
}

Eigen::SparseMatrix<double> StaticAnalysis::free_tangent() {
  revert();
  std::string failure;
  if (!assemble(true, failure))
    throw std::runtime_error("free_tangent: " + failure);
  return tangent_;
}

} // namespace brb::analysis
