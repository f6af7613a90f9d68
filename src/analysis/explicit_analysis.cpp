// Explicit central difference through Boost.Odeint's velocity Verlet (see
// explicit_analysis.hpp for the method, the mass scaling rule and the stable step).
#include "brb/analysis/explicit_analysis.hpp"
#include "brb/analysis/eigen_velocity_verlet.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace brb::analysis {

namespace {

using Stepper = EigenVelocityVerlet;

const char* dof_name(int dof) {
  static constexpr const char* names[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  return names[dof];
}

std::string describe_equation(int full_dof) {
  return "node " + std::to_string(full_dof / model::kDofPerNode) + " " +
         dof_name(full_dof % model::kDofPerNode);
}

bool is_translation(int full_dof) {
  return full_dof % model::kDofPerNode < 3;
}

/// Largest eigenvalue of the symmetric matrix `a` by power iteration: the Rayleigh quotient
/// plus its residual norm (for a unit x some eigenvalue lies within |a x - rho x| of rho:
/// Weinstein's bound, Parlett, The Symmetric Eigenvalue Problem, ch. 4), capped by the
/// Gershgorin bound. The quotient alone approaches the largest eigenvalue from below.
struct PowerIterationResult {
  double eigenvalue = 0.0;
  double gershgorin = 0.0;
  int iterations = 0;
};

PowerIterationResult largest_eigenvalue(const Eigen::SparseMatrix<double>& a, int max_iterations) {
  PowerIterationResult result;
  const Eigen::Index n = a.rows();
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(n);
  for (int column = 0; column < a.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, column); it; ++it)
      row_sum[it.row()] += std::abs(it.value());
  }
  result.gershgorin = n > 0 ? row_sum.maxCoeff() : 0.0;
  if (result.gershgorin == 0.0)
    return result;
  // a fixed seed: the estimate is reproducible; random signs excite the highest modes
  std::mt19937 generator(20021);
  std::uniform_real_distribution<double> distribution(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i)
    x[i] = distribution(generator);
  x.normalize();
  double bound = result.gershgorin;
  double previous = 0.0;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    const Eigen::VectorXd y = a * x;
    const double rho = x.dot(y);
    const double residual = (y - rho * x).norm();
    bound = std::abs(rho) + residual;
    result.iterations = iteration;
    if (residual <= 1e-10 * std::abs(rho) ||
        (iteration > 1 && std::abs(rho - previous) <= 1e-13 * std::abs(rho)))
      break;
    previous = rho;
    const double norm = y.norm();
    if (norm == 0.0)
      break;
    x = y / norm;
  }
  result.eigenvalue = std::min(bound, result.gershgorin);
  return result;
}

} // namespace

double record_substep(double record_dt, double stable_step) {
  if (!(record_dt > 0.0) || !(stable_step > 0.0))
    throw std::invalid_argument("record_substep: the record dt and the stable step must be > 0");
  return record_dt / std::ceil(record_dt / stable_step * (1.0 - 1e-12));
}

ExplicitAnalysis::ExplicitAnalysis(model::Model& model, model::DofMap map,
                                   ExplicitSettings settings)
    : model_(model), map_(std::move(map)), settings_(settings), assembler_(model_, map_) {
  if (!(settings_.time_step >= 0.0) || !std::isfinite(settings_.time_step))
    throw std::invalid_argument("explicit analysis: time_step must be >= 0 (0: automatic)");
  if (!(settings_.stable_step_safety > 0.0 && settings_.stable_step_safety <= 1.0))
    throw std::invalid_argument("explicit analysis: stable_step_safety must be in (0, 1]");
  equation_dof_.assign(map_.equation_count(), -1);
  for (int dof = 0; dof < map_.full_dof_count(); ++dof) {
    if (const int equation = map_.independent_equation(dof); equation >= 0)
      equation_dof_[equation] = dof;
  }
  static_load_ = Eigen::VectorXd::Zero(model_.dof_count());
  committed_nodes_ = model::initial_configuration(model_);
  trial_nodes_ = committed_nodes_;
  committed_full_force_ = Eigen::VectorXd::Zero(model_.dof_count());
  const Eigen::Index n = map_.equation_count();
  displacement_ = Eigen::VectorXd::Zero(n);
  velocity_ = Eigen::VectorXd::Zero(n);
  acceleration_ = Eigen::VectorXd::Zero(n);
}

void ExplicitAnalysis::require_not_started(const char* what) const {
  if (prepared_)
    throw std::logic_error(std::string("explicit analysis: ") + what +
                           " must come before prepare() (the first step or query)");
}

void ExplicitAnalysis::set_damping(const DampingSpec& damping) {
  require_not_started("set_damping");
  if (!damping.modal_ratios.empty())
    throw std::invalid_argument("explicit analysis: modal damping is not available (a full C "
                                "matrix); use Rayleigh mass_factor and stiffness_factor");
  if (!(damping.mass_factor >= 0.0) || !(damping.stiffness_factor >= 0.0))
    throw std::invalid_argument("explicit analysis: Rayleigh factors must be >= 0");
  if (!damping.include_in_stiffness_damping.empty() &&
      damping.include_in_stiffness_damping.size() != model_.elements().size())
    throw std::invalid_argument("explicit analysis: include_in_stiffness_damping needs one entry "
                                "per model element (" +
                                std::to_string(model_.elements().size()) + ")");
  damping_spec_ = damping;
}

void ExplicitAnalysis::add_ground_acceleration(GroundAcceleration component) {
  require_not_started("add_ground_acceleration");
  if (!(component.dt > 0.0))
    throw std::invalid_argument("explicit analysis: ground acceleration dt must be > 0");
  if (std::abs(component.direction.norm() - 1.0) > 1e-9)
    throw std::invalid_argument("explicit analysis: ground acceleration direction must be a unit "
                                "vector");
  influence_.push_back(map_.ground_influence(component.direction));
  ground_.push_back(std::move(component));
}

void ExplicitAnalysis::set_static_load(const Eigen::VectorXd& load) {
  require_not_started("set_static_load");
  if (load.size() != model_.dof_count())
    throw std::invalid_argument("explicit analysis: the static load needs " +
                                std::to_string(model_.dof_count()) + " full DOF values, got " +
                                std::to_string(load.size()));
  if (!load.allFinite())
    throw std::invalid_argument("explicit analysis: the static load is not finite");
  static_load_ = load;
}

void ExplicitAnalysis::set_initial_state(std::span<const element::NodeConfiguration> nodes,
                                         const Eigen::VectorXd& velocity) {
  require_not_started("set_initial_state");
  if (static_cast<int>(nodes.size()) != model_.node_count())
    throw std::invalid_argument("explicit analysis: the initial state needs " +
                                std::to_string(model_.node_count()) + " node configurations");
  if (velocity.size() != model_.dof_count() || !velocity.allFinite())
    throw std::invalid_argument("explicit analysis: the initial velocity needs " +
                                std::to_string(model_.dof_count()) + " finite full DOF values");
  committed_nodes_.assign(nodes.begin(), nodes.end());
  trial_nodes_ = committed_nodes_;
  // Each equation's value is that of its own full DOF (a rotation: the triad's rotation
  // vector, the spins' sum for a rotation about a fixed axis).
  const Eigen::VectorXd full = model::full_displacement(model_, committed_nodes_);
  for (std::size_t equation = 0; equation < equation_dof_.size(); ++equation) {
    displacement_[static_cast<Eigen::Index>(equation)] = full[equation_dof_[equation]];
    velocity_[static_cast<Eigen::Index>(equation)] = velocity[equation_dof_[equation]];
  }
}

void ExplicitAnalysis::initialise_static(std::span<const element::NodeConfiguration> nodes,
                                         const Eigen::VectorXd& static_load) {
  set_static_load(static_load);
  set_initial_state(nodes, Eigen::VectorXd::Zero(model_.dof_count()));
  std::string reason;
  if (!assembler_.assemble(committed_nodes_, false, reason))
    throw std::runtime_error("explicit analysis: an element refuses the static state: " + reason);
  const Eigen::VectorXd residual = map_.reduce(static_load_) - assembler_.reduced_force();
  const double scale = assembler_.force_scale() + static_load_.lpNorm<Eigen::Infinity>() + 1.0;
  const double imbalance = residual.size() > 0 ? residual.lpNorm<Eigen::Infinity>() : 0.0;
  for (const auto& element : model_.elements())
    element->revert_to_committed();
  if (imbalance > settings_.static_tolerance * scale) {
    Eigen::Index worst = 0;
    residual.cwiseAbs().maxCoeff(&worst);
    throw std::invalid_argument(
        "explicit analysis: the static state is not in equilibrium under its load: residual " +
        std::to_string(imbalance) + " at " + describe_equation(equation_dof_[worst]) +
        " exceeds static_tolerance * force scale = " +
        std::to_string(settings_.static_tolerance * scale));
  }
}

void ExplicitAnalysis::initialise_static(const model::Model& converged,
                                         std::span<const element::NodeConfiguration> nodes,
                                         const Eigen::VectorXd& static_load) {
  require_not_started("initialise_static");
  if (&converged != &model_)
    model_.copy_element_states_from(converged);
  initialise_static(nodes, static_load);
}

Eigen::VectorXd ExplicitAnalysis::reduced_load() const {
  return map_.reduce(static_load_);
}

StableStepEstimate
ExplicitAnalysis::estimate_stable_step(const Eigen::SparseMatrix<double>& tangent) const {
  // w_max^2: largest eigenvalue of M^-1/2 Ks M^-1/2, Ks the symmetric part of the tangent
  const Eigen::VectorXd inverse_root = mass_.cwiseSqrt().cwiseInverse();
  const Eigen::SparseMatrix<double> transposed = tangent.transpose();
  const Eigen::SparseMatrix<double> symmetric = 0.5 * (tangent + transposed);
  const Eigen::SparseMatrix<double> scaled =
      inverse_root.asDiagonal() * symmetric * inverse_root.asDiagonal();
  const PowerIterationResult power = largest_eigenvalue(scaled, settings_.max_power_iterations);
  // Gershgorin on M^-1 Ks (the same eigenvalues): max_i sum_j |Ks_ij| / m_i. Rigorous, and
  // tight where scaled masses make the power iteration slow (its residual then dominates).
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(symmetric.rows());
  for (int column = 0; column < symmetric.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(symmetric, column); it; ++it)
      row_sum[it.row()] += std::abs(it.value());
  }
  const double row_bound = row_sum.size() > 0 ? row_sum.cwiseQuotient(mass_).maxCoeff() : 0.0;
  StableStepEstimate estimate;
  estimate.max_frequency = std::sqrt(std::min(power.eigenvalue, row_bound));
  estimate.gershgorin_bound = std::sqrt(std::min(power.gershgorin, row_bound));
  estimate.power_iterations = power.iterations;
  const double w = estimate.max_frequency;
  if (w > 0.0) {
    // only the stiffness part, at v_{n+1/2}, lowers the limit (see the header)
    estimate.damping_ratio = damping_spec_.stiffness_factor * w / 2.0;
    const double xi = estimate.damping_ratio;
    estimate.stable_step =
        settings_.stable_step_safety * (2.0 / w) * (std::sqrt(1.0 + xi * xi) - xi);
  }
  return estimate;
}

ExplicitAnalysis::StabilityCheck ExplicitAnalysis::check_stable_step(std::string& reason) {
  steps_since_check_ = 0;
  // the tangent of the trial end state (re-evaluating the same trial state: its forces and
  // energies stay those of the step)
  if (!assembler_.assemble(trial_nodes_, true, reason)) {
    reason = "the tangent for the stability check: " + reason;
    return StabilityCheck::stop;
  }
  const StableStepEstimate current = estimate_stable_step(assembler_.reduced_tangent());
  // act once the stiffening has used half of the safety margin
  const double allowance = 1.0 + 0.5 * (1.0 / settings_.stable_step_safety - 1.0);
  if (!(current.max_frequency > 0.0) || time_step_ <= current.stable_step * allowance)
    return StabilityCheck::fine;
  const std::string grown = "the stiffness grew: w_max " + std::to_string(current.max_frequency) +
                            " rad/s, stable step " + std::to_string(current.stable_step) +
                            " s < time step " + std::to_string(time_step_) + " s";
  if (settings_.time_step > 0.0) {
    if (!settings_.refuse_unstable_step)
      return StabilityCheck::fine; // the user runs an unstable step on purpose
    reason = grown + " (a given time_step is not changed; choose a smaller one)";
    return StabilityCheck::stop;
  }
  fallbacks_.push_back(
      {time_, "time step reduced to " + std::to_string(current.stable_step) + " s", grown});
  time_step_ = current.stable_step;
  stable_ = current;
  return StabilityCheck::reduced;
}

void ExplicitAnalysis::prepare() {
  if (prepared_)
    return;
  build_masses_and_step();
  prepared_ = true;
}

void ExplicitAnalysis::build_masses_and_step() {
  const Eigen::Index n = map_.equation_count();
  if (n == 0)
    throw std::invalid_argument("explicit analysis: the model has no free equation");

  // Lumped mass: T^T M T must be diagonal (see the header).
  const Eigen::SparseMatrix<double> reduced_mass = map_.reduced_mass(model_);
  physical_mass_ = Eigen::VectorXd::Zero(n);
  for (int column = 0; column < reduced_mass.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(reduced_mass, column); it; ++it) {
      if (it.row() == it.col()) {
        physical_mass_[it.row()] = it.value();
      } else if (it.value() != 0.0) {
        throw std::invalid_argument(
            "explicit analysis: the mass couples " + describe_equation(equation_dof_[it.row()]) +
            " and " + describe_equation(equation_dof_[it.col()]) +
            " (a rigid diaphragm whose slave nodes carry mass); the lumped-mass solver needs the "
            "floor's mass and rotational inertia at the diaphragm master, placed at the centre "
            "of mass");
      }
    }
  }

  // Initial tangent: mass scaling and the stable step.
  std::string reason;
  if (!assembler_.assemble(committed_nodes_, true, reason))
    throw std::runtime_error("explicit analysis: an element refuses the initial state: " + reason);
  const Eigen::SparseMatrix<double> tangent = assembler_.reduced_tangent();
  // row sums of |K0|: the Gershgorin radius of each equation
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(n);
  for (int column = 0; column < tangent.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(tangent, column); it; ++it)
      row_sum[it.row()] += std::abs(it.value());
  }
  const Eigen::VectorXd diagonal = tangent.diagonal().cwiseAbs();

  double target = settings_.time_step;
  if (target == 0.0) {
    // automatic: the diagonal estimate of the equations with mass sets the scaling target
    double highest = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (physical_mass_[i] > 0.0)
        highest = std::max(highest, std::sqrt(diagonal[i] / physical_mass_[i]));
    }
    if (highest == 0.0 && (physical_mass_.array() == 0.0).any())
      throw std::invalid_argument("explicit analysis: no equation with mass has stiffness; set "
                                  "time_step to scale the massless equations");
    target = highest > 0.0 ? settings_.stable_step_safety * 2.0 / highest : 0.0;
  }

  mass_ = physical_mass_;
  mass_scaling_ = {};
  for (Eigen::Index i = 0; i < n; ++i) {
    const int dof = equation_dof_[i];
    if (physical_mass_[i] <= 0.0) {
      if (!settings_.mass_scaling)
        throw std::invalid_argument("explicit analysis: " + describe_equation(dof) +
                                    " has no mass (enable mass_scaling or add mass)");
      if (!(diagonal[i] > 0.0))
        throw std::invalid_argument("explicit analysis: " + describe_equation(dof) +
                                    " has neither mass nor stiffness");
      // its Gershgorin bound on w^2 is then 1 / (dt_target^2 + a1 dt_target): with the
      // stiffness damping a1 the step limit stays 2 dt_target (see the header)
      mass_[i] = row_sum[i] * (target * target + damping_spec_.stiffness_factor * target);
      ++mass_scaling_.scaled_equations;
      (is_translation(dof) ? mass_scaling_.added_translational_mass
                           : mass_scaling_.added_rotational_inertia) += mass_[i];
    }
    (is_translation(dof) ? mass_scaling_.translational_mass : mass_scaling_.rotational_inertia) +=
        mass_[i];
  }

  // Damping: C = a0 M_phys (diagonal) + a1 K0 (of the included elements)
  mass_damping_ = damping_spec_.mass_factor * physical_mass_;
  stiffness_damping_.resize(n, n);
  if (damping_spec_.stiffness_factor > 0.0) {
    if (damping_spec_.include_in_stiffness_damping.empty()) {
      stiffness_damping_ = damping_spec_.stiffness_factor * tangent;
    } else {
      if (!assembler_.assemble(committed_nodes_, true, reason,
                               &damping_spec_.include_in_stiffness_damping))
        throw std::runtime_error("explicit analysis: an element refuses the initial state: " +
                                 reason);
      stiffness_damping_ = damping_spec_.stiffness_factor * assembler_.reduced_tangent();
    }
  }

  stable_ = estimate_stable_step(tangent);
  if (!(stable_.max_frequency > 0.0))
    throw std::invalid_argument("explicit analysis: the initial tangent has no stiffness (no "
                                "vibration frequency to set the step)");
  const double w = stable_.max_frequency;
  time_step_ = settings_.time_step > 0.0 ? settings_.time_step : stable_.stable_step;
  if (settings_.refuse_unstable_step && time_step_ > stable_.stable_step * (1.0 + 1e-12))
    throw std::invalid_argument(
        "explicit analysis: time_step " + std::to_string(time_step_) +
        " s exceeds the stable step " + std::to_string(stable_.stable_step) + " s (w_max " +
        std::to_string(w) + " rad/s, safety " + std::to_string(settings_.stable_step_safety) +
        "); use a smaller record substep (record_substep)");

  // the initial acceleration, with the initial velocity in the damping force
  static_reduced_ = reduced_load();
  if (!evaluate(displacement_, velocity_, 0.0, time_, forces_, acceleration_, reason))
    throw std::runtime_error("explicit analysis: the initial state cannot be evaluated: " + reason);
  if (!acceleration_.allFinite())
    throw std::runtime_error("explicit analysis: the initial acceleration is not finite");
  const element::ElementEnergy elements = assembler_.energy();
  for (const auto& element : model_.elements())
    element->revert_to_committed();
  committed_full_force_ = assembler_.full_force();
  energy_ = {};
  energy_.kinetic = 0.5 * velocity_.dot(mass_.cwiseProduct(velocity_));
  energy_.stored = elements.stored;
  energy_.dissipated = elements.dissipated;
  energy_.integration_misfit = elements.integration_misfit;
  energy_.static_work =
      energy_.kinetic + energy_.stored + energy_.dissipated + energy_.integration_misfit;
}

bool ExplicitAnalysis::evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& half_step_velocity,
                                double half_dt, double t, EquationForces& forces,
                                Eigen::VectorXd& acceleration, std::string& reason) {
  if (!q.allFinite() || !half_step_velocity.allFinite()) {
    reason = "the displacement or velocity became non-finite (the step exceeds the stable step "
             "of the current stiffness?)";
    return false;
  }
  std::copy(committed_nodes_.begin(), committed_nodes_.end(), trial_nodes_.begin());
  const Eigen::VectorXd increment = q - displacement_;
  model::apply_increment(map_, trial_nodes_, increment);
  if (!assembler_.assemble(trial_nodes_, false, reason))
    return false;
  forces.internal = assembler_.reduced_force();
  forces.ground = Eigen::VectorXd::Zero(q.size());
  for (std::size_t c = 0; c < ground_.size(); ++c)
    forces.ground += ground_[c].at(t) * physical_mass_.cwiseProduct(influence_[c]);
  // stiffness part at v_{n+1/2}; mass part at v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}, solved
  // per equation: (m + c_m dt/2) a = f - C_k v_{n+1/2} - c_m v_{n+1/2}
  const Eigen::VectorXd stiffness_damping = stiffness_damping_ * half_step_velocity;
  acceleration = (static_reduced_ - forces.internal - stiffness_damping - forces.ground -
                  mass_damping_.cwiseProduct(half_step_velocity))
                     .cwiseQuotient(mass_ + half_dt * mass_damping_);
  forces.damping =
      stiffness_damping + mass_damping_.cwiseProduct(half_step_velocity + half_dt * acceleration);
  if (!acceleration.allFinite() || !forces.damping.allFinite()) {
    reason = "the acceleration is not finite at t = " + std::to_string(t) +
             " s (a non-finite ground acceleration or damping force)";
    return false;
  }
  return true;
}

ExplicitStepReport ExplicitAnalysis::stop(double dt, std::string reason) {
  for (const auto& element : model_.elements())
    element->revert_to_committed();
  failure_ = FallbackRecord{time_, "explicit step of " + std::to_string(dt) + " s", reason};
  return {false, 0, "explicit analysis stopped at t = " + std::to_string(time_) + " s: " + reason};
}

ExplicitStepReport ExplicitAnalysis::advance(double dt) {
  if (failure_)
    return {false, 0,
            "explicit analysis stopped at t = " + std::to_string(failure_->time) +
                " s: " + failure_->reason};
  prepare();

  // velocity Verlet: q_{n+1} = q_n + dt v_n + dt^2/2 a_n, then the system gives a_{n+1};
  // the damping velocity is v_{n+1/2} = v_n + dt/2 a_n (see the header)
  EquationForces forces;
  std::string reason;
  bool evaluated = true;
  const auto system = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v_start,
                          Eigen::VectorXd& a, double t) {
    const Eigen::VectorXd half_step_velocity = v_start + 0.5 * dt * acceleration_;
    evaluated = evaluate(q, half_step_velocity, 0.5 * dt, t, forces, a, reason);
    if (!evaluated)
      a = Eigen::VectorXd::Zero(q.size());
  };
  Stepper stepper;
  Eigen::VectorXd q(displacement_.size()), v(velocity_.size()), a(acceleration_.size());
  // a step whose end state is too stiff for it is taken again with the reduced step
  constexpr int max_reductions = 8;
  for (int attempt = 0;; ++attempt) {
    stepper.do_step(system, displacement_, velocity_, acceleration_, q, v, a, time_, dt);
    if (!evaluated)
      return stop(dt, reason);
    if (!q.allFinite() || !v.allFinite() || !a.allFinite())
      return stop(dt, "the state became non-finite (the step exceeds the stable step of the "
                      "current stiffness?)");
    if (settings_.stability_check_interval <= 0 ||
        steps_since_check_ + 1 < settings_.stability_check_interval)
      break;
    const StabilityCheck check = check_stable_step(reason);
    if (check == StabilityCheck::stop)
      return stop(dt, reason);
    if (check == StabilityCheck::fine)
      break;
    for (const auto& element : model_.elements())
      element->revert_to_committed();
    if (attempt + 1 == max_reductions)
      return stop(dt, "the step was reduced " + std::to_string(max_reductions) +
                          " times without reaching a stable one");
    dt = std::min(dt, time_step_);
  }

  // energy increments, trapezoidal with the forces as evaluated
  const Eigen::VectorXd increment = q - displacement_;
  energy_.input -= 0.5 * (forces_.ground + forces.ground).dot(increment);
  energy_.damping += 0.5 * (forces_.damping + forces.damping).dot(increment);
  energy_.static_work += static_reduced_.dot(increment);
  energy_.kinetic = 0.5 * v.dot(mass_.cwiseProduct(v));
  const element::ElementEnergy elements = assembler_.energy();
  energy_.stored = elements.stored;
  energy_.dissipated = elements.dissipated;
  energy_.integration_misfit = elements.integration_misfit;

  for (const auto& element : model_.elements())
    element->commit();
  std::swap(committed_nodes_, trial_nodes_);
  committed_full_force_ = assembler_.full_force();
  // a coupling may change committed states at this fixed configuration (Model::
  // add_commit_coupling): it does no work, and the next step's evaluation sees the new state
  model_.apply_commit_couplings();
  displacement_ = std::move(q);
  velocity_ = std::move(v);
  acceleration_ = std::move(a);
  forces_ = std::move(forces);
  time_ += dt;
  ++steps_since_check_;
  return {true, 1, {}};
}

ExplicitStepReport ExplicitAnalysis::step() {
  prepare();
  return advance(time_step_);
}

ExplicitStepReport ExplicitAnalysis::run_to(double time) {
  prepare();
  ExplicitStepReport total{true, 0, {}};
  // a remainder below 1e-9 of a step is rounding, not a step
  while (time - time_ > 1e-9 * time_step_) {
    const ExplicitStepReport report = advance(std::min(time_step_, time - time_));
    total.steps += report.steps;
    if (!report.completed) {
      total.completed = false;
      total.failure = report.failure;
      return total;
    }
  }
  return total;
}

const StableStepEstimate& ExplicitAnalysis::stable_step_estimate() {
  prepare();
  return stable_;
}

double ExplicitAnalysis::time_step() {
  prepare();
  return time_step_;
}

const MassScalingReport& ExplicitAnalysis::mass_scaling() {
  prepare();
  return mass_scaling_;
}

const Eigen::VectorXd& ExplicitAnalysis::lumped_mass() {
  prepare();
  return mass_;
}

Eigen::VectorXd ExplicitAnalysis::displacement() const {
  return model::full_displacement(model_, committed_nodes_);
}

Eigen::VectorXd ExplicitAnalysis::velocity() const {
  return map_.expand(velocity_);
}

Eigen::VectorXd ExplicitAnalysis::acceleration() const {
  return map_.expand(acceleration_);
}

Eigen::Vector3d ExplicitAnalysis::ground_acceleration() const {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const GroundAcceleration& component : ground_)
    total += component.at(time_) * component.direction;
  return total;
}

} // namespace brb::analysis
