#include "brb/analysis/static_analysis.hpp"

#include "brb/analysis/line_search.hpp"
#include "brb/element/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace brb::analysis {

using element::Matrix3;
using element::NodeConfiguration;
using element::Vector3;
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
  return std::abs(external_work - stored - dissipated - integration_misfit - released_in_jumps) /
         std::max(gross_work, 1e-30);
}

double EnergyBalance::law_relative_error() const {
  return std::abs(external_work - stored - dissipated - released_by_laws) /
         std::max(gross_work, 1e-30);
}

double EnergyBalance::relative_misfit() const {
  return std::abs(integration_misfit) / std::max(gross_work, 1e-30);
}

StaticAnalysis::StaticAnalysis(model::Model& model, NewtonSettings settings)
    : model_(model), settings_(settings), evaluations_(settings.element_threads) {
  committed_.resize(model_.node_count());
  for (int node = 0; node < model_.node_count(); ++node) {
    committed_[node].position = model_.coordinates(node);
  }
  trial_ = committed_;
  internal_force_ = Eigen::VectorXd::Zero(model_.dof_count());
  committed_internal_force_ = internal_force_;
  reference_load_ = Eigen::VectorXd::Zero(model_.dof_count());
  constant_load_ = Eigen::VectorXd::Zero(model_.dof_count());
  control_rate_ = Eigen::VectorXd::Zero(model_.dof_count());
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
  motion_nodes_.clear();
  control_value_ = committed_[node].position[dof] - model_.coordinates(node)[dof];
  control_rate_.setZero();
  control_rate_[model::Model::global_dof(node, dof)] = 1.0;
  number_equations();
}

void StaticAnalysis::use_prescribed_motion(std::vector<int> nodes) {
  for (const int node : nodes) {
    if (node < 0 || node >= model_.node_count())
      throw std::invalid_argument("prescribed motion of a node the model does not have");
  }
  displacement_control_.reset();
  motion_nodes_ = std::move(nodes);
  motion_start_.clear();
  for (const int node : motion_nodes_)
    motion_start_.push_back(committed_[node]);
  motion_target_ = motion_start_;
  motion_rotation_.assign(motion_nodes_.size(), element::Vector3::Zero());
  control_rate_.setZero();
  control_value_ = 0.0;
  number_equations();
}

void StaticAnalysis::set_motion_target(std::span<const NodeConfiguration> targets) {
  if (targets.size() != motion_nodes_.size())
    throw std::invalid_argument("set_motion_target: one target per prescribed node");
  control_rate_.setZero();
  for (std::size_t k = 0; k < motion_nodes_.size(); ++k) {
    const int node = motion_nodes_[k];
    motion_start_[k] = committed_[node];
    motion_target_[k] = targets[k];
    motion_rotation_[k] =
        element::vector_from_rotation(targets[k].rotation * committed_[node].rotation.transpose());
    // d x / ds = x_target - x_0; the spin rate of exp(s theta) R_0 is theta (global)
    const element::Vector3 travel = targets[k].position - committed_[node].position;
    for (int i = 0; i < 3; ++i) {
      control_rate_[kDofPerNode * node + i] = travel[i];
      control_rate_[kDofPerNode * node + 3 + i] = motion_rotation_[k][i];
    }
  }
  control_value_ = 0.0;
  control_force_ = committed_internal_force_.dot(control_rate_);
}

Eigen::MatrixXd StaticAnalysis::condensed_tangent() {
  if (motion_nodes_.empty())
    throw std::logic_error("condensed_tangent needs prescribed motion");
  if (tangent_.rows() == 0)
    return tangent_prescribed_prescribed_;
  // K_ff was assembled at the converged state (the last assembly); factorize it afresh
  // (the solver holds the factor of an earlier iterate).
  Eigen::SparseLU<Eigen::SparseMatrix<double>> factor;
  factor.compute(tangent_);
  if (factor.info() != Eigen::Success)
    throw std::runtime_error("condensed tangent: singular internal tangent");
  const Eigen::MatrixXd internal = factor.solve(tangent_free_prescribed_);
  return tangent_prescribed_prescribed_ - tangent_prescribed_free_ * internal;
}

AnalysisPathState StaticAnalysis::path_state() const {
  AnalysisPathState state;
  state.nodes = committed_;
  state.internal_force = committed_internal_force_;
  state.control_value = control_value_;
  state.control_force = control_force_;
  state.stable = committed_stable_;
  state.energy = energy_;
  state.energy_error_sum = energy_error_sum_;
  return state;
}

void StaticAnalysis::restore_path_state(const AnalysisPathState& state) {
  if (state.nodes.size() != committed_.size())
    throw std::invalid_argument("restore_path_state: the state is of another model");
  committed_ = state.nodes;
  trial_ = committed_;
  committed_internal_force_ = state.internal_force;
  internal_force_ = committed_internal_force_;
  control_value_ = state.control_value;
  control_force_ = state.control_force;
  committed_stable_ = state.stable;
  energy_ = state.energy;
  energy_error_sum_ = state.energy_error_sum;
  released_at_commit_ = energy_.released_by_laws;
}

template <class Archive, class Self>
void StaticAnalysis::archive_committed(Archive& archive, Self& self) {
  archive(self.committed_, self.committed_internal_force_, self.control_value_, self.control_force_,
          self.committed_stable_, self.energy_, self.energy_error_sum_, self.released_at_commit_,
          self.force_scale_, self.total_iterations_, self.total_substeps_, self.regularised_steps_,
          self.unstable_accepted_, self.energy_cuts_, self.energy_tolerance_missed_,
          self.far_branch_cuts_, self.retraced_steps_, self.work_.assemblies,
          self.work_.line_search_assemblies, self.work_.converged_newton_iterations,
          self.work_.failed_newton_iterations, self.work_.failed_newton_calls,
          self.work_.pseudo_time_steps, self.work_.pseudo_time_iterations);
}

void StaticAnalysis::save_state(io::StateWriter& out) const {
  out(static_cast<std::uint64_t>(model_.elements().size()),
      static_cast<std::uint64_t>(free_dofs_.size()));
  archive_committed(out, *this);
  for (const auto& element : model_.elements())
    element->save_state(out);
}

void StaticAnalysis::load_state(io::StateReader& in) {
  std::uint64_t elements = 0, equations = 0;
  in(elements, equations);
  if (elements != model_.elements().size() || equations != free_dofs_.size())
    in.mismatch("a model of " + std::to_string(elements) + " elements and " +
                std::to_string(equations) + " free DOFs where this one has " +
                std::to_string(model_.elements().size()) + " and " +
                std::to_string(free_dofs_.size()) +
                ": a checkpoint of another brace, refinement or program version");
  archive_committed(in, *this);
  for (const auto& element : model_.elements())
    element->load_state(in);
  trial_ = committed_;
  internal_force_ = committed_internal_force_;
}

void StaticAnalysis::use_load_control(const Eigen::VectorXd& reference_load) {
  if (reference_load.size() != model_.dof_count())
    throw std::invalid_argument("load vector size");
  displacement_control_.reset();
  motion_nodes_.clear();
  control_rate_.setZero();
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
  prescribed_index_.assign(model_.dof_count(), -1);
  for (std::size_t k = 0; k < motion_nodes_.size(); ++k) {
    for (int dof = 0; dof < kDofPerNode; ++dof)
      prescribed_index_[kDofPerNode * motion_nodes_[k] + dof] =
          kDofPerNode * static_cast<int>(k) + dof;
  }
  free_dofs_.clear();
  for (int node = 0; node < model_.node_count(); ++node) {
    for (int dof = 0; dof < kDofPerNode; ++dof) {
      const auto d = static_cast<model::Dof>(dof);
      const bool controlled = displacement_control_ && displacement_control_->first == node &&
                              displacement_control_->second == d;
      if (model_.is_fixed(node, d) || controlled ||
          prescribed_index_[model::Model::global_dof(node, d)] >= 0)
        continue;
      equation_[model::Model::global_dof(node, d)] = static_cast<int>(free_dofs_.size());
      free_dofs_.push_back(model::Model::global_dof(node, d));
    }
  }
  pattern_analysed_ = false;
  tangent_slots_valid_ = false;
}

bool StaticAnalysis::tangent_slots_match() const {
  std::size_t next = 0;
  for (const auto& element : model_.elements()) {
    const auto nodes = element->nodes();
    if (next + nodes.size() > slot_element_nodes_.size() ||
        !std::equal(nodes.begin(), nodes.end(), slot_element_nodes_.begin() + next))
      return false;
    next += nodes.size();
  }
  return next == slot_element_nodes_.size();
}

void StaticAnalysis::build_tangent_slots() {
  tangent_slots_.resize(triplets_.size());
  const int* starts = tangent_.outerIndexPtr();
  const int* rows = tangent_.innerIndexPtr();
  for (std::size_t k = 0; k < triplets_.size(); ++k) {
    const int column = triplets_[k].col();
    // compressed column-major, rows sorted within a column
    const int* found =
        std::lower_bound(rows + starts[column], rows + starts[column + 1], triplets_[k].row());
    tangent_slots_[k] = static_cast<int>(found - rows);
  }
  slot_element_nodes_.clear();
  for (const auto& element : model_.elements()) {
    const auto nodes = element->nodes();
    slot_element_nodes_.insert(slot_element_nodes_.end(), nodes.begin(), nodes.end());
  }
  tangent_slots_valid_ = true;
}

bool StaticAnalysis::assemble(bool with_tangent, std::string& failure) {
  if (!assemble_forces(with_tangent, failure))
    return false;
  if (with_tangent)
    gather_tangent();
  return true;
}

bool StaticAnalysis::assemble_forces(bool check_tangent, std::string& failure) {
  ++work_.assemblies;
  internal_force_.setZero();
  force_scale_ = 0.0;
  if (!evaluations_.evaluate(model_, trial_, check_tangent, failure))
    return false;
  const auto elements = model_.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto nodes = elements[e]->nodes();
    const Eigen::VectorXd& element_force = evaluations_.force(e);
    force_scale_ = std::max(force_scale_, element_force.lpNorm<Eigen::Infinity>());
    const int element_dofs = static_cast<int>(nodes.size()) * kDofPerNode;
    for (int a = 0; a < element_dofs; ++a)
      internal_force_[kDofPerNode * nodes[a / kDofPerNode] + a % kDofPerNode] += element_force[a];
  }
  return true;
}

void StaticAnalysis::gather_tangent() {
  const auto free_count = static_cast<Eigen::Index>(free_dofs_.size());
  const auto prescribed_count = static_cast<Eigen::Index>(kDofPerNode * motion_nodes_.size());
  // Add into the tangent's value slots where its pattern is known, else collect triplets.
  const bool into_slots = tangent_slots_valid_ && tangent_slots_match();
  std::size_t slot = 0;
  triplets_.clear();
  if (into_slots)
    std::fill_n(tangent_.valuePtr(), tangent_.nonZeros(), 0.0);
  control_column_ = Eigen::VectorXd::Zero(free_count);
  if (prescribed_count > 0) {
    tangent_free_prescribed_ = Eigen::MatrixXd::Zero(free_count, prescribed_count);
    tangent_prescribed_free_ = Eigen::MatrixXd::Zero(prescribed_count, free_count);
    tangent_prescribed_prescribed_ = Eigen::MatrixXd::Zero(prescribed_count, prescribed_count);
  }
  const auto elements = model_.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto nodes = elements[e]->nodes();
    const Eigen::MatrixXd& element_tangent = evaluations_.tangent(e);
    const int element_dofs = static_cast<int>(nodes.size()) * kDofPerNode;
    for (int a = 0; a < element_dofs; ++a) {
      const int row = kDofPerNode * nodes[a / kDofPerNode] + a % kDofPerNode;
      const int free_row = equation_[row];
      const int prescribed_row = prescribed_index_[row];
      if (free_row < 0 && prescribed_row < 0)
        continue;
      for (int b = 0; b < element_dofs; ++b) {
        const int column = kDofPerNode * nodes[b / kDofPerNode] + b % kDofPerNode;
        const double value = element_tangent(a, b);
        const int free_column = equation_[column];
        const int prescribed_column = prescribed_index_[column];
        if (free_row >= 0) {
          if (free_column >= 0) {
            if (into_slots)
              tangent_.valuePtr()[tangent_slots_[slot++]] += value;
            else
              triplets_.emplace_back(free_row, free_column, value);
          } else {
            control_column_[free_row] += value * control_rate_[column];
            if (prescribed_column >= 0)
              tangent_free_prescribed_(free_row, prescribed_column) += value;
          }
        } else if (free_column >= 0) {
          tangent_prescribed_free_(prescribed_row, free_column) += value;
        } else if (prescribed_column >= 0) {
          tangent_prescribed_prescribed_(prescribed_row, prescribed_column) += value;
        }
      }
    }
  }
  if (!into_slots) {
    tangent_.resize(free_count, free_count);
    tangent_.setFromTriplets(triplets_.begin(), triplets_.end());
    build_tangent_slots();
  }
}

Eigen::VectorXd StaticAnalysis::free_residual(double control) const {
  Eigen::VectorXd residual(static_cast<Eigen::Index>(free_dofs_.size()));
  const bool load_control = !kinematic_control();
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
  for (std::size_t k = 0; k < motion_nodes_.size(); ++k) {
    NodeConfiguration& node = trial_[motion_nodes_[k]];
    node.position = motion_start_[k].position +
                    value * (motion_target_[k].position - motion_start_[k].position);
    node.rotation =
        element::rotation_from_vector(value * motion_rotation_[k]) * motion_start_[k].rotation;
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
      (kinematic_control() ? 0.0 : std::abs(control) * reference_load_.lpNorm<Eigen::Infinity>());
  const double stiffest = tangent_.rows() > 0 ? tangent_.diagonal().cwiseAbs().maxCoeff() : 0.0;
  const double round_off_floor =
      settings_.position_round_off * model_extent_ * stiffest / settings_.relative_force_tolerance;
  const double scale = force_scale_ + load + round_off_floor + 1e-6;
  return residual.lpNorm<Eigen::Infinity>() <= settings_.relative_force_tolerance * scale;
}

StaticAnalysis::Attempt StaticAnalysis::newton(double control,
                                               const Eigen::SparseMatrix<double>* viscosity,
                                               int max_iterations, bool assembled) {
  const Attempt attempt = newton_iterations(control, viscosity, max_iterations, assembled);
  if (viscosity != nullptr) {
    ++work_.pseudo_time_steps;
    work_.pseudo_time_iterations += attempt.iterations;
  } else if (attempt.converged) {
    work_.converged_newton_iterations += attempt.iterations;
  } else {
    ++work_.failed_newton_calls;
    work_.failed_newton_iterations += attempt.iterations;
  }
  return attempt;
}

StaticAnalysis::Attempt
StaticAnalysis::newton_iterations(double control, const Eigen::SparseMatrix<double>* viscosity,
                                  int max_iterations, bool assembled) {
  Attempt attempt;
  Eigen::VectorXd residual;
  // With a viscosity C (free x free, symmetric positive definite) this is one backward-Euler step
  // of the gradient flow C du/dtau = F_ext - F_int(u) (pseudo-time step 1): the residual
  // gains -C (u - u_start), the tangent C. `moved_` holds u - u_start of the free DOF
  // (spins for rotations).
  moved_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  const auto pseudo_residual = [&] {
    Eigen::VectorXd r = free_residual(control);
    if (viscosity != nullptr)
      r -= (*viscosity) * moved_;
    return r;
  };
  int polished = 0;
  double start_residual = 0.0;
  double smallest_residual = 0.0;
  for (int iteration = 0; iteration <= max_iterations; ++iteration) {
    // (a failure counts the iterations it did: iteration corrections taken, plus the one
    // that failed when it failed within an iteration)
    attempt.iterations = iteration;
    if (!assembled && !assemble(true, attempt.failure))
      return attempt;
    assembled = false;
    residual = pseudo_residual();
    if (!residual.allFinite()) {
      attempt.failure = "non-finite residual";
      return attempt;
    }
    // Within tolerance: converged, unless polishing corrections are asked
    // (NewtonSettings::polish_corrections). A polishing correction is taken whole: the line
    // search guards against divergence from far away, and at round-off it cannot decrease
    // the norm.
    bool polishing = false;
    if (residual_converged(residual, control)) {
      if (viscosity != nullptr || polished >= settings_.polish_corrections ||
          iteration == max_iterations) {
        attempt.converged = true;
        attempt.iterations = iteration;
        return attempt;
      }
      polishing = true;
      ++polished;
      if (iteration == 0)
        attempt.started_within_tolerance = true;
    }
    if (iteration == max_iterations)
      break;

    // Stagnation cut-off (NewtonSettings::stagnation_iterations): a plain call whose residual
    // has not fallen to a fraction of its start in that many iterations is on a plateau
    // (a snap-through ahead) and gives the step to the fallbacks.
    const double residual_norm = residual.norm();
    if (iteration == 0)
      start_residual = smallest_residual = residual_norm;
    smallest_residual = std::min(smallest_residual, residual_norm);
    if (viscosity == nullptr && !polishing && settings_.stagnation_iterations > 0 &&
        iteration >= settings_.stagnation_iterations &&
        smallest_residual > settings_.stagnation_ratio * start_residual) {
      attempt.failure = "Newton-Raphson stagnated: residual norm " + readable(residual_norm) +
                        " after " + std::to_string(iteration) + " iterations, from " +
                        readable(start_residual);
      attempt.iterations = iteration;
      return attempt;
    }

    const Eigen::SparseMatrix<double>* matrix = &tangent_;
    if (viscosity != nullptr) {
      regularised_tangent_ = tangent_ + *viscosity;
      matrix = &regularised_tangent_;
      // The viscosity's blocks may widen the pattern (the sum's pattern is the union, so the
      // same count of entries is the same pattern): then analyse it for this matrix, and
      // again for the next plain tangent.
      if (regularised_tangent_.nonZeros() != tangent_.nonZeros()) {
        solver_.analyzePattern(*matrix);
        pattern_analysed_ = false;
      }
    }
    if (!pattern_analysed_ && matrix->nonZeros() == tangent_.nonZeros()) {
      solver_.analyzePattern(*matrix);
      pattern_analysed_ = true;
    }
    attempt.iterations = iteration + 1;
    solver_.factorize(*matrix);
    if (solver_.info() != Eigen::Success) {
      attempt.failure = "singular tangent stiffness";
      return attempt;
    }
    const Eigen::VectorXd increment = solver_.solve(residual);
    if (!increment.allFinite()) {
      attempt.failure = "non-finite Newton increment";
      return attempt;
    }

    // Line search: backtracking on the residual norm; when no step down to 1/64 lowers it
    // and the projected residual s(eta) = du . r(u + eta du) changes sign over the step,
    // the root of s (projected_line_search); failing that, the step of 1/64 (as before it).
    // Measured on brbf9 with the brace files' 16 core elements under El Centro: at t = 1.70 s
    // the story-9 brace (a 70 x 12 mm plate, eight half-waves bearing 1.5 to 1.9 kN each, a
    // penetration of about 3e-4 mm) stalled Newton at residuals of 200 to 600 N in every
    // substep of 1/16, backtracking failing to 1/64 at each iteration; each substep went to
    // pseudo-transient continuation (100 to 1,600 iterations) and the run stalled there. Only
    // when backtracking fails: tried first, the projected search changed paths it did not
    // need to (the `passes` check's brace jumped to another mode, a 1.5 % force drop).
    const std::vector<NodeConfiguration> start = trial_;
    const Eigen::VectorXd start_moved = moved_;
    const double start_norm = residual_norm;
    // A trial point's forces decide it; its tangent is gathered only if it is accepted (about
    // two trials in three are not), from the same evaluation (its finiteness is checked at
    // the trial, as before, so the same trials are accepted).
    const auto take_step = [&](double step, std::string& failure) {
      trial_ = start;
      apply_free_increment(increment, step);
      moved_ = start_moved + step * increment;
      ++work_.line_search_assemblies;
      return assemble_forces(true, failure);
    };
    double full_slope = std::numeric_limits<double>::quiet_NaN();
    double step = 1.0;
    for (int search = 0;; ++search) {
      std::string failure;
      const bool ok = take_step(step, failure);
      bool accept = ok && (!settings_.line_search || polishing);
      if (ok && !accept) {
        const Eigen::VectorXd trial_residual = pseudo_residual();
        if (search == 0)
          full_slope = increment.dot(trial_residual);
        accept = trial_residual.norm() < start_norm;
      }
      if (!accept && search == 6 && ok && settings_.line_search && !polishing) {
        const auto projected = [&](double eta, double& slope) {
          std::string unused;
          if (!take_step(eta, unused))
            return false;
          slope = increment.dot(pseudo_residual());
          return true;
        };
        accept = projected_line_search(residual.dot(increment), full_slope, projected) ||
                 take_step(step, failure);
      }
      if (accept) {
        gather_tangent();
        assembled = true;
        break;
      }
      if (search == 6) {
        attempt.failure = failure.empty() ? "line search failed" : failure;
        return attempt;
      }
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

bool StaticAnalysis::within_budget(double committed_error, double change, double tolerance,
                                   const StepEnergy& step) const {
  // Round-off floor: the energies are sums of many terms of their own size.
  const double round_off =
      1e-13 * (std::abs(step.end.stored) + std::abs(step.end.dissipated) + std::abs(step.work));
  const double step_error = step.work - change;
  const double budget = tolerance * energy_.gross_work;
  if (std::abs(committed_error + step_error) <=
      budget + tolerance * std::abs(step.work) + round_off)
    return true;
  // The committed error may already exceed the budget: a jump passed by pseudo-transient
  // continuation commits its booking error unchecked, and so does a step accepted after its
  // cuts ran out. Cutting later steps cannot repay it (their own errors shrink with the
  // step, the debt does not), so it is carried as it stands and a step passes if its own
  // error is within its share of the budget. Without this every step after such a jump was
  // cut to the energy_halvings floor (measured: PC160 with the sub-element waves, a
  // 6,000-step piece ran 161 s without the balance control and was not done after 30 min
  // with it).
  return std::abs(committed_error) > budget &&
         std::abs(step_error) <= tolerance * std::abs(step.work) + round_off;
}

bool StaticAnalysis::within_energy_tolerance(const StepEnergy& step) const {
  if (!(settings_.energy_tolerance > 0.0))
    return true;
  const double change = step.end.stored + step.end.dissipated - energy_.stored - energy_.dissipated;
  return within_budget(energy_error_sum_, change, settings_.energy_tolerance, step);
}

bool StaticAnalysis::within_balance_tolerance(const StepEnergy& step) const {
  if (!(settings_.balance_tolerance > 0.0))
    return true;
  const double change = step.end.stored + step.end.dissipated + step.end.integration_misfit -
                        energy_.stored - energy_.dissipated - energy_.integration_misfit;
  // the committed balance's signed error (the sum of the committed steps' errors)
  const double committed_error = energy_.external_work - energy_.stored - energy_.dissipated -
                                 energy_.integration_misfit - energy_.released_in_jumps;
  return within_budget(committed_error, change, settings_.balance_tolerance, step);
}

void StaticAnalysis::commit(double control, const StepEnergy& step) {
  const double energy_before = energy_.stored + energy_.dissipated + released_at_commit_;
  energy_.external_work += step.work;
  energy_.gross_work += std::abs(step.work);
  for (const auto& element : model_.elements())
    element->commit();
  committed_ = trial_;
  committed_internal_force_ = internal_force_;
  control_value_ = control;
  if (kinematic_control()) {
    control_force_ = internal_force_.dot(control_rate_);
  } else {
    control_force_ = reference_load_.dot(internal_force_);
  }
  energy_.stored = step.end.stored;
  energy_.dissipated = step.end.dissipated;
  energy_.integration_misfit = step.end.integration_misfit;
  released_at_commit_ = energy_.released_by_laws;
  energy_error_sum_ +=
      step.work - (energy_.stored + energy_.dissipated + energy_.released_by_laws - energy_before);
  if (model_.apply_commit_couplings())
    refresh_committed_forces();
  if (recording_path_)
    path_.push_back({control, false, committed_stable_, committed_});
}

void StaticAnalysis::refresh_committed_forces() {
  // A coupling changed committed states without moving a node (Model::add_commit_coupling):
  // the internal forces drop (or rise) at a fixed configuration, which does no work, so only
  // the forces from which the next step's trapezoidal work starts change. The laws' energies
  // are continuous across such a change (FiberSection::split_halves).
  revert();
  std::string failure;
  if (!assemble(false, failure))
    return; // keep the former forces; the next step evaluates the new state anyway
  committed_internal_force_ = internal_force_;
  control_force_ = kinematic_control() ? internal_force_.dot(control_rate_)
                                       : reference_load_.dot(internal_force_);
}

void StaticAnalysis::revert() {
  trial_ = committed_;
  for (const auto& element : model_.elements())
    element->revert_to_committed();
}

bool StaticAnalysis::halve(double from, double to, int depth, StepReport& report,
                           FarCuts far_cuts) {
  revert();
  const double middle = 0.5 * (from + to);
  return try_increment(from, middle, depth + 1, report, far_cuts) &&
         try_increment(middle, to, depth + 1, report, far_cuts);
}

bool StaticAnalysis::try_increment(double from, double to, int depth, StepReport& report,
                                   FarCuts far_cuts) {
  report.deepest_halving = std::max(report.deepest_halving, depth);
  // Tangent predictor from the converged state.
  revert();
  mark_path_point();
  Attempt attempt;
  bool landed_far = false;
  FarCuts halves_far_cuts; // what the halves keep if the step is cut for its correction
  if (assemble(true, attempt.failure)) {
    Eigen::VectorXd load;
    if (kinematic_control()) {
      load = -(to - from) * control_column_;
    } else {
      load = Eigen::VectorXd(static_cast<Eigen::Index>(free_dofs_.size()));
      for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
        load[static_cast<Eigen::Index>(e)] = (to - from) * reference_load_[free_dofs_[e]];
      }
    }
    set_control_value(to);
    if (!free_dofs_.empty()) { // (nothing to predict when every DOF is prescribed)
      if (!pattern_analysed_) {
        solver_.analyzePattern(tangent_);
        pattern_analysed_ = true;
      }
      solver_.factorize(tangent_);
    }
    if (!free_dofs_.empty() && solver_.info() == Eigen::Success) {
      const Eigen::VectorXd predictor = solver_.solve(load);
      if (predictor.allFinite())
        apply_free_increment(predictor, 1.0);
    }
    const std::vector<NodeConfiguration> predicted = trial_;
    attempt = newton(to, nullptr, settings_.max_iterations);
    double correction_ratio = 0.0;
    landed_far = attempt.converged && !lands_near_predictor(attempt, predicted, &correction_ratio);
    // Far at three depths by a steady ratio as the predictor halved: a steep path, not a jump
    // (NewtonSettings::far_ratio_growth).
    const double growth = settings_.far_ratio_growth;
    const auto steady = [growth](double ratio, double previous) {
      return ratio <= growth * previous && previous <= growth * ratio;
    };
    if (landed_far && far_cuts.before > 0.0 && steady(correction_ratio, far_cuts.last) &&
        steady(far_cuts.last, far_cuts.before))
      landed_far = false;
    // (a crush below is another reason to cut, with no ratio for the halves to keep)
    if (landed_far)
      halves_far_cuts = {correction_ratio, far_cuts.last};
    if (attempt.converged && jumped_past_peak()) {
      // Crushed from intact within the substep: another branch (jumped_past_peak). Cut;
      // at the floor the state is not the path either, so the step is treated as failed
      // and passed by the continuation, which follows the crush if the flow pushes it.
      landed_far = true;
      if (depth >= settings_.max_halvings) {
        attempt.converged = false;
        attempt.failure = "a contact link crushed from intact within the smallest substep";
      }
    }
  }
  report.iterations += attempt.iterations;
  const bool at_floor = depth >= settings_.max_halvings;
  if (landed_far && !at_floor) {
    // Newton converged far from where the tangent predicted: onto another branch (see
    // NewtonSettings::max_correction_ratio). Cut the step so the path is followed.
    ++report.far_branch_cuts;
    ++far_branch_cuts_;
    return halve(from, to, depth, report, halves_far_cuts);
  }
  bool stable = true;
  if (attempt.converged && settings_.require_stable_equilibrium) {
    stable = tangent_is_positive_definite();
    if (!stable && committed_stable_ && depth < settings_.stability_halvings) {
      attempt.converged = false;
      attempt.failure = "converged to an unstable equilibrium";
    }
  }
  const StepEnergy step = attempt.converged ? trial_step_energy() : StepEnergy{};
  if (attempt.converged && !at_floor && !dissipation_supplied_by_work(step)) {
    // The step dissipated stored energy the loading did not supply: it landed on another
    // branch (NewtonSettings::max_correction_ratio). Cut it so the path is followed.
    ++report.far_branch_cuts;
    ++far_branch_cuts_;
    return halve(from, to, depth, report, {});
  }
  if (attempt.converged && !(within_energy_tolerance(step) && within_balance_tolerance(step))) {
    if (depth < std::min(settings_.energy_halvings, settings_.max_halvings)) {
      // A kink inside the step (yield, contact), or kinematics the trapezoidal rule does not
      // follow: halve it until the trapezoidal work and the energies agree
      // (NewtonSettings::energy_tolerance, balance_tolerance).
      ++report.energy_cuts;
      ++energy_cuts_;
      return halve(from, to, depth, report, {});
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
    commit(to, step);
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
  if (!at_floor)
    return halve(from, to, depth, report, {});
  if (pass_limit_point(to, report))
    return true;
  revert();
  report.failure =
      "step from " + readable(from) + " to " + readable(to) + ": " + last_pseudo_failure_;
  return false;
}

bool StaticAnalysis::lands_near_predictor(const Attempt& attempt,
                                          const std::vector<NodeConfiguration>& predicted,
                                          double* correction_ratio) const {
  // A Newton that started within tolerance only polished an equilibrium
  // (NewtonSettings::polish_corrections): not a landing on another branch, however small the
  // step's own motion against which the corrections are measured.
  if (!(settings_.max_correction_ratio > 0.0) || attempt.started_within_tolerance)
    return true;
  double prediction = 0.0, correction = 0.0;
  for (std::size_t node = 0; node < trial_.size(); ++node) {
    prediction =
        std::max(prediction, (predicted[node].position - committed_[node].position).norm());
    correction = std::max(correction, (trial_[node].position - predicted[node].position).norm());
  }
  if (correction_ratio != nullptr)
    *correction_ratio = correction / std::max(prediction, std::numeric_limits<double>::min());
  // Round-off floor: positions carry ~1e-14 of the model's size.
  return correction <= settings_.max_correction_ratio * prediction +
                           1e3 * settings_.position_round_off * model_extent_;
}

void StaticAnalysis::mark_path_point() {
  for (const auto& element : model_.elements())
    element->mark_path_point();
}

bool StaticAnalysis::jumped_past_peak() const {
  if (!(settings_.max_correction_ratio > 0.0))
    return false;
  // Measured on the brbf9 story-8 brace (16 core elements in a 200 mm tube, fixed ends,
  // second cycle at 1 dy): Newton reached states in which one to five stations had the core
  // 20 to 40 mm deep in crushed mortar, an equilibrium because crushed mortar bears nothing,
  // and the brace dropped from -413 to -150 kN; crushing a station takes its bearing peak,
  // fc over 244 x 105 mm, about 1.3 MN, while no converged state of the same run with mortar ten
  // times stronger (no crushing possible) bore more than 2.3 kN at any station.
  for (const auto& element : model_.elements()) {
    if (element->jumped_past_peak())
      return true;
  }
  return false;
}

bool StaticAnalysis::dissipation_supplied_by_work(const StepEnergy& step) const {
  if (!(settings_.max_correction_ratio > 0.0))
    return true;
  // Along a followed path a step dissipates what its work supplies, plus a little stored
  // energy (friction slipping as a brace unloads); a step that dissipates more than its
  // positive work plus half its magnitude has released stored energy into dissipation: a
  // snap the step size hid (measured: the Girona D3 step of dy / 10 that crushed the bearing
  // mortar while unloading dissipated 15,000 N mm against a work of -7,200 N mm).
  const double dissipated = step.end.dissipated - energy_.dissipated;
  // Floor: 1e-3 of the gross work. Backstress recovery (Chaboche's dynamic recovery) turns
  // stored energy into dissipation in small steps (measured: 100 N mm against a work of 60 N
  // mm in the `passes` check, 3e-5 of its gross work); a crush releases far more.
  const double floor = 1e-3 * (energy_.gross_work + std::abs(step.work)) + 1e-9;
  return dissipated <= std::max(step.work, 0.0) + 0.5 * std::abs(step.work) + floor;
}

bool StaticAnalysis::energy_change_supplied_by_work(const StepEnergy& step) const {
  if (!(settings_.max_correction_ratio > 0.0))
    return true;
  // A step along the path changes the elements' energy by its work, to the trapezoidal
  // rule's error where a law kinks inside it (a few per cent of the step's work at most,
  // NewtonSettings::energy_tolerance); a step across a jump releases stored energy its work
  // did not supply (measured on the shallow truss of the tests: 80,000 N mm against a work
  // of 300 N mm). Same floor as dissipation_supplied_by_work.
  const double change = step.end.stored + step.end.dissipated - energy_.stored - energy_.dissipated;
  const double floor = 1e-3 * (energy_.gross_work + std::abs(step.work)) + 1e-9;
  return std::abs(step.work - change) <= 0.5 * std::abs(step.work) + floor;
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
  // A step that passed a limit point brings its own work (see pseudo_transient).
  commit(to, {attempt.jump_work, element_energy()});
  if (recording_path_)
    path_.back().passed_limit_point = true;
  ++report.substeps;
  return true;
}

StepReport StaticAnalysis::step_to(double target) {
  StepReport report;
  report.substeps = 0;
  path_.clear();
  recording_path_ = !motion_nodes_.empty();
  if (recording_path_) {
    path_start_ = committed_;
    path_start_control_ = control_value_;
    path_target_ = motion_target_;
  }
  report.converged = try_increment(control_value_, target, 0, report, {});
  recording_path_ = false;
  if (!report.converged)
    path_.clear();
  total_iterations_ += report.iterations;
  total_substeps_ += report.substeps;
  return report;
}

double StaticAnalysis::motion_distance(std::span<const NodeConfiguration> from,
                                       std::span<const NodeConfiguration> to) const {
  double distance = 0.0;
  for (std::size_t k = 0; k < from.size(); ++k) {
    const double turn =
        element::vector_from_rotation(to[k].rotation * from[k].rotation.transpose()).norm();
    distance =
        std::max({distance, (to[k].position - from[k].position).norm(), turn * model_extent_});
  }
  return distance;
}

std::string StaticAnalysis::retrace_refusal() const {
  if (motion_nodes_.empty())
    return "a retrace needs prescribed motion";
  if (!(settings_.retrace_target_ratio > 0.0))
    return "path retrace is off";
  if (path_.empty())
    return "no converged step to retrace";
  if (control_value_ != path_start_control_)
    return "the control is not where the last step started";
  for (std::size_t node = 0; node < committed_.size(); ++node) {
    if (committed_[node].position != path_start_[node].position ||
        committed_[node].rotation != path_start_[node].rotation)
      return "the committed state is not the one the last step started from";
  }
  std::vector<NodeConfiguration> start;
  for (const int node : motion_nodes_)
    start.push_back(path_start_[node]);
  const double travel = motion_distance(start, path_target_);
  const double change = motion_distance(path_target_, motion_target_);
  if (!(change < settings_.retrace_target_ratio * travel))
    return "the target moved " + readable(change) + " mm from the last step's, which travelled " +
           readable(travel) + " mm";
  return {};
}

StepReport StaticAnalysis::retrace_last_path() {
  StepReport report;
  report.substeps = 0;
  report.failure = retrace_refusal();
  if (!report.failure.empty())
    return report;
  for (std::size_t k = 0; k < path_.size(); ++k) {
    PathSubstep& substep = path_[k];
    revert();
    mark_path_point();
    if (substep.passed_limit_point) {
      // Onto the branch the jump reached last time; failing that, the continuation again.
      if (!retrace_jump(substep, report)) {
        revert();
        if (!pass_limit_point(substep.control, report)) {
          report.failure = "retrace: " + last_pseudo_failure_;
          break;
        }
      }
      substep.nodes = committed_;
      continue;
    }
    // Warm start: the free nodes where this substep converged last time, the prescribed
    // nodes at the substep's control for the new target.
    trial_ = substep.nodes;
    set_control_value(substep.control);
    const std::vector<NodeConfiguration> guess = trial_;
    const Attempt attempt = newton(substep.control, nullptr, settings_.max_iterations);
    report.iterations += attempt.iterations;
    // The guess is where this substep ended last time; if an earlier substep ended on
    // another branch this time (a jump not taken), Newton can converge from it across the
    // jump. The far-branch tests of try_increment tell: a correction far beyond the guess's
    // motion, a link crushed from intact, or stored energy released that the step's work did
    // not supply.
    std::string substep_failure;
    StepEnergy step;
    if (!attempt.converged) {
      substep_failure = attempt.failure;
    } else {
      step = trial_step_energy();
      if (!lands_near_predictor(attempt, guess) || jumped_past_peak() ||
          !dissipation_supplied_by_work(step) || !energy_change_supplied_by_work(step))
        substep_failure = "a substep landed on another branch";
    }
    if (!substep_failure.empty()) {
      // A limit point that a later substep passed last time may come at or before this
      // substep's control for the new target. (Not passed by continuation here: over a whole
      // step, pseudo_transient's booking of the control's work, with the free nodes held
      // where the step started, errs by a large part of the step's work; the adaptive solve
      // passes limit points in short substeps.)
      revert();
      if (retrace_early_jump(k, report))
        continue;
      report.failure = "retrace: " + substep_failure;
      break;
    }
    // The energy-error budget holds for the retrace too: a retrace that spent it would leave
    // every later adaptive step cut to the floor (measured: 1,024 substeps per solve).
    if (!(within_energy_tolerance(step) && within_balance_tolerance(step))) {
      report.failure = "retrace: a substep would exceed the energy-error budget";
      break;
    }
    if (unstable_end_of_path(substep)) {
      report.failure = "retrace: converged to an unstable equilibrium";
      break;
    }
    committed_stable_ = substep.stable;
    commit(substep.control, step);
    substep.nodes = committed_;
    ++report.substeps;
  }
  total_iterations_ += report.iterations;
  total_substeps_ += report.substeps;
  if (!report.failure.empty()) {
    revert();
    path_.clear();
    return report;
  }
  path_target_ = motion_target_;
  report.converged = true;
  ++retraced_steps_;
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

Eigen::SparseMatrix<double> StaticAnalysis::nodal_stiffness_metric() const {
  const auto size = static_cast<Eigen::Index>(free_dofs_.size());
  // Free equations of each node's translations (kind 0) and rotations (kind 1).
  std::vector<std::vector<int>> blocks(2 * static_cast<std::size_t>(model_.node_count()));
  for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
    const int dof = free_dofs_[e];
    blocks[static_cast<std::size_t>(2 * (dof / kDofPerNode) + (dof % kDofPerNode < 3 ? 0 : 1))]
        .push_back(static_cast<int>(e));
  }
  const double mean_stiffness = size > 0 ? tangent_.diagonal().cwiseAbs().mean() : 0.0;
  const double floor = 1e-9 * mean_stiffness; // a DOF without stiffness still damps
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const std::vector<int>& block = blocks[k];
    if (block.size() < 3) {
      // Some of the node's DOF of this kind are restrained: their diagonal entries.
      for (const int e : block)
        entries.emplace_back(e, e, std::max(std::abs(tangent_.coeff(e, e)), floor));
      continue;
    }
    // The diagonal of the block in the node's own axes R (Model::node_axes), turned back:
    // R diag(|r_i^T K r_i|) R^T.
    const Matrix3& axes = model_.node_axes(static_cast<int>(k / 2));
    Matrix3 stiffness;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        stiffness(i, j) = tangent_.coeff(block[i], block[j]);
    }
    Vector3 local;
    for (int i = 0; i < 3; ++i)
      local[i] = std::max(std::abs(axes.col(i).dot(stiffness * axes.col(i))), floor);
    const Matrix3 metric = axes * local.asDiagonal() * axes.transpose();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(block[i], block[j], metric(i, j));
    }
  }
  Eigen::SparseMatrix<double> metric(size, size);
  metric.setFromTriplets(entries.begin(), entries.end());
  return metric;
}

StaticAnalysis::Attempt StaticAnalysis::pseudo_transient(double control) {
  Attempt total;
  if (!assemble(true, total.failure))
    return total;
  // The energy released is what the jump takes out of the system: the drop of the elements'
  // stress work (stored plus material-dissipated energy plus the integration misfit; by the
  // laws alone in EnergyBalance::released_by_laws), plus the work the (constant) loads do
  // during it.
  const element::ElementEnergy before = element_energy();
  const double control_force_before = internal_force_.dot(control_rate_);
  Eigen::VectorXd travelled = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  // Backward-Euler steps of the gradient flow C du/dtau = F_ext - F_int(u), with the
  // viscosity C = c D: D is the diagonal of K_0 (the tangent at the start of the jump), taken
  // in each node's own axes (Model::node_axes: a brace's axis and section axes) and turned
  // back, per node for its translations and for its rotations. Each DOF gets the same
  // relative viscosity whatever its units and stiffness, and D turns with the model, so a
  // turned brace takes the same path. (The absolute value of the whole 3 x 3 block mixes the
  // axial stiffness into the lateral DOF of a bowed core: measured, it made the brbf3 path
  // hang on the step again.)
  // The first rule, C = c times the mean diagonal entry, is for the translations of a brace
  // thousands of times stiffer than for its rotations (whose entries are EI/L, in N mm):
  // the flow was resolved for some DOF and not for others, and the branch it came to rest on
  // hung on round-off. Measured on the brbf3 story-2 brace (16 core elements, one cycle at
  // Delta_by): moving the step points by 1e-9 mm, or the step from 0.3 to 0.41 mm, changed
  // the compression peak from -455 kN (a bow of 4 mm) to -415 kN after a jump that released
  // 1.2e6 N mm. With this D (and the far-branch control), steps of 0.15, 0.3, 0.41 and
  // 0.6155 mm to 6.2 mm, and of Delta_by / 10 to Delta_by, give -423.6 kN (-419.6 kN at the
  // smaller amplitude) and a 24.4 mm bow, the path the first rule also takes at the finest
  // steps; the same cycle with its points moved by 1e-9 mm still buckles globally (open).
  // c starts at 1e-3 and halves after each converged step (the flow speeds up as it
  // settles), down to 1e-12.
  const Eigen::SparseMatrix<double> metric = nodal_stiffness_metric();
  double relative_viscosity = 1e-3;
  // The flow must pass a softening law's peak, not jump over it (StaticAnalysis::
  // jumped_past_peak): the pseudo-time step that crushes a link from intact is retried
  // shorter, so a crush happens only where the flow pushes a link through its peak force.
  mark_path_point();
  for (int pseudo_step = 0; pseudo_step < settings_.fallback_iterations; ++pseudo_step) {
    const std::vector<NodeConfiguration> start = trial_;
    const Eigen::SparseMatrix<double> viscosity = relative_viscosity * metric;
    const Attempt attempt = newton(control, &viscosity, settings_.max_iterations);
    total.iterations += attempt.iterations;
    if (!attempt.converged || jumped_past_peak()) {
      // a more viscous (shorter) pseudo-time step from the same state
      trial_ = start;
      relative_viscosity *= 10.0;
      continue;
    }
    mark_path_point();
    travelled += moved_;
    // at rest when the plain residual is below tolerance (the state is assembled)
    const Eigen::VectorXd rest_residual = free_residual(control);
    if (residual_converged(rest_residual, control)) {
      total.converged = true;
      total.jump_work = book_jump({before, control_force_before}, travelled, control);
      return total;
    }
    relative_viscosity = std::max(0.5 * relative_viscosity, 1e-12);
  }
  total.failure = "pseudo-transient continuation did not come to rest in " +
                  std::to_string(settings_.fallback_iterations) + " pseudo-time steps";
  return total;
}

double StaticAnalysis::book_jump(const JumpStart& start, const Eigen::VectorXd& travelled,
                                 double control) {
  // The trial state is the assembled rest point of the jump.
  const element::ElementEnergy after = element_energy();
  double load_work = 0.0;
  for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
    const int dof = free_dofs_[e];
    const double load =
        constant_load_[dof] + (kinematic_control() ? 0.0 : control * reference_load_[dof]);
    load_work += load * travelled[static_cast<Eigen::Index>(e)];
  }
  const element::ElementEnergy& before = start.energy;
  energy_.released_by_laws +=
      before.stored + before.dissipated + load_work - after.stored - after.dissipated;
  energy_.released_in_jumps += before.stored + before.dissipated + before.integration_misfit +
                               load_work - after.stored - after.dissipated -
                               after.integration_misfit;
  // External work of this step: the control moved first (on the old branch, ending at
  // the control force of the jump's start), then the jump at fixed control, under constant
  // loads.
  const double control_work = 0.5 *
                              (committed_internal_force_.dot(control_rate_) + start.control_force) *
                              (control - control_value_);
  return control_work + load_work;
}

Eigen::VectorXd StaticAnalysis::free_motion_since_commit() const {
  Eigen::VectorXd motion = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  for (std::size_t e = 0; e < free_dofs_.size(); ++e) {
    const int node = free_dofs_[e] / kDofPerNode, component = free_dofs_[e] % kDofPerNode;
    motion[static_cast<Eigen::Index>(e)] =
        component < 3
            ? trial_[node].position[component] - committed_[node].position[component]
            : element::vector_from_rotation(trial_[node].rotation *
                                            committed_[node].rotation.transpose())[component - 3];
  }
  return motion;
}

bool StaticAnalysis::unstable_end_of_path(const PathSubstep& substep) const {
  return &substep == &path_.back() && settings_.require_stable_equilibrium && substep.stable &&
         !tangent_is_positive_definite();
}

bool StaticAnalysis::retrace_early_jump(std::size_t failed, StepReport& report) {
  // The limit point came earlier for the new target: no equilibrium near the old one is left
  // at substep `failed`. Jump at its control to the branch the next recorded jump reached
  // (Newton from that jump's rest point), then go on along that branch, warm-started from
  // that rest point. Without it such a retrace fell back to an adaptive solve at every outer
  // iteration (tests/analysis/path_retrace_test.cpp: the shallow truss retraced 20 and 30 %
  // of its step beyond a recorded jump); measured on brbf3 with 16-element braces at dt
  // 0.005 s: 353 s against 562 s without it.
  std::size_t jump = failed + 1;
  while (jump < path_.size() && !path_[jump].passed_limit_point)
    ++jump;
  if (jump == path_.size())
    return false;
  const PathSubstep early{path_[failed].control, true, path_[jump].stable, path_[jump].nodes};
  if (!retrace_jump(early, report)) {
    revert();
    return false;
  }
  // The path as solved this time: the jump here, the recorded substeps up to the old jump
  // now steps along the branch reached.
  path_[failed].passed_limit_point = true;
  path_[failed].stable = early.stable;
  path_[failed].nodes = committed_;
  for (std::size_t k = failed + 1; k <= jump; ++k) {
    path_[k].passed_limit_point = false;
    path_[k].nodes = path_[jump].nodes;
  }
  return true;
}

bool StaticAnalysis::retrace_jump(const PathSubstep& substep, StepReport& report) {
  // The jump's start, as pseudo_transient books it: the control moved, the free nodes at
  // the committed state.
  set_control_value(substep.control);
  std::string failure;
  if (!assemble(false, failure)) // its forces and energies; no tangent needed
    return false;
  const JumpStart start{element_energy(), internal_force_.dot(control_rate_)};
  // Newton from where the jump came to rest last time: the branch it jumped to.
  trial_ = substep.nodes;
  set_control_value(substep.control);
  if (!assemble(true, failure))
    return false;
  mark_path_point();
  const std::vector<NodeConfiguration> guess = trial_;
  const Attempt attempt =
      newton(substep.control, nullptr, settings_.max_iterations, /*assembled=*/true);
  report.iterations += attempt.iterations;
  if (!attempt.converged || !lands_near_predictor(attempt, guess) || jumped_past_peak() ||
      unstable_end_of_path(substep))
    return false;
  committed_stable_ = substep.stable;
  const double work = book_jump(start, free_motion_since_commit(), substep.control);
  ++regularised_steps_;
  report.used_regularised_newton = true;
  commit(substep.control, {work, element_energy()});
  ++report.substeps;
  return true;
}

element::ElementEnergy StaticAnalysis::element_energy() const {
  element::ElementEnergy total;
  for (const auto& element : model_.elements()) {
    const auto energy = element->energy();
    total.stored += energy.stored;
    total.dissipated += energy.dissipated;
    total.integration_misfit += energy.integration_misfit;
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
