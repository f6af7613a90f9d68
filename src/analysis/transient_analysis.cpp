// Implicit time-history analysis (transient_analysis.hpp): Newmark average acceleration and
// HHT-alpha on the equations of a DofMap, Newton-Raphson with a backtracking line search, and
// the fallbacks of a failed step (halved substeps, then modified Newton on the committed
// tangent, then Broyden's secant update).
//
// Unknown of a (sub)step: the equations' increment dq from the committed state (translations
// and spins, model::apply_increment). Velocity and acceleration are vectors on the equations,
// updated additively from dq (incremental Newmark, as OpenSees):
//   a1 = dq / (beta dt^2) - v0 / (beta dt) - (1 / (2 beta) - 1) a0
//   v1 = v0 + dt ((1 - gamma) a0 + gamma a1)
// HHT-alpha (Hilber, Hughes and Taylor 1977), with the committed forces kept:
//   M a1 + (1 + alpha) (f_int + C v)_1 - alpha (f_int + C v)_0 = (1 + alpha) p_1 - alpha p_0
// p(t) = T^T f_static - M sum_c r_c a_g,c(t); alpha = 0 is Newmark average acceleration.
// Effective tangent: M / (beta dt^2) + (1 + alpha) (K + gamma / (beta dt) C).
//
// Energy error measure. Every term is integrated by the trapezoidal rule over the converged
// (sub)step: input -1/2 (M r a_g,0 + M r a_g,1)^T dq, damping 1/2 (C v0 + C v1)^T dq, static
// work f_static^T dq (the trapezoid of the ramp during load steps); kinetic energy and the
// elements' stored and dissipated energies are state values. For Newmark average
// acceleration these sums balance exactly when each step is in equilibrium at its ends
// (dq = dt (v0 + v1) / 2 and dv = dt (a0 + a1) / 2 make the trapezoidal inertia work equal the
// change of kinetic energy; a linear f_int's trapezoidal work equals its stored energy), so
// TransientEnergy::absolute_error() measures (1) the Newton tolerance, (2) the trapezoidal
// rule's error for an element force path that is curved or kinked inside a step where the
// element does not book it as its integration misfit (the laws' own time discretisation at
// the integration points is set apart: TransientEnergy::integration_misfit; what is left is
// the elements' kinematics within a step and the elements that do not track it), and (3) for
// HHT, the method's numerical dissipation (its equilibrium is not at the step's end).
#include "brb/analysis/transient_analysis.hpp"

#include "brb/analysis/modal_analysis.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace brb::analysis {

namespace {

std::string readable(double value) {
  std::ostringstream text;
  text << std::setprecision(6) << value;
  return text.str();
}

double infinity_norm(const Eigen::VectorXd& vector) {
  return vector.size() == 0 ? 0.0 : vector.lpNorm<Eigen::Infinity>();
}

} // namespace

/// One (sub)step: a dynamic step from time `from` to `to`, or a static load step from the
/// load parameter `from` to `to` (load = base + parameter x delta).
struct TransientAnalysis::Increment {
  bool dynamic = true;
  double from = 0.0;
  double to = 0.0;
  // dynamic: Newmark constants of the step
  double dt = 0.0;
  double alpha = 0.0;
  double beta = 0.25;
  double gamma = 0.5;
  Eigen::VectorXd velocity;     // v0
  Eigen::VectorXd acceleration; // a0
  // right-hand side: dynamic (1 + alpha) p_1 - alpha p_0 + alpha (f_int + C v)_0; static: the
  // load at `to`
  Eigen::VectorXd external;
  Eigen::VectorXd external_from; // static: load at `from`
  Eigen::VectorXd ground_from;   // dynamic: -M r a_g at the ends, for the input energy
  Eigen::VectorXd ground_to;
  Eigen::VectorXd static_load; // T^T f_static held during a dynamic step

  Eigen::VectorXd acceleration_at(const Eigen::VectorXd& dq) const {
    return dq / (beta * dt * dt) - velocity / (beta * dt) - (0.5 / beta - 1.0) * acceleration;
  }
  Eigen::VectorXd velocity_at(const Eigen::VectorXd& dq) const {
    return velocity + dt * ((1.0 - gamma) * acceleration + gamma * acceleration_at(dq));
  }
};

TransientAnalysis::TransientAnalysis(model::Model& model, model::DofMap map,
                                     TransientSettings settings)
    : model_(model), map_(std::move(map)), settings_(settings), assembler_(model_, map_) {
  if (!(settings_.hht_alpha >= -1.0 / 3.0 && settings_.hht_alpha <= 0.0))
    throw std::invalid_argument("TransientSettings: hht_alpha must be in [-1/3, 0], got " +
                                readable(settings_.hht_alpha));
  if (settings_.max_iterations < 1 || settings_.max_halvings < 0 ||
      settings_.fallback_iterations < 1)
    throw std::invalid_argument("TransientSettings: max_iterations and fallback_iterations "
                                "must be >= 1 and max_halvings >= 0");
  if (!(settings_.relative_force_tolerance > 0.0) || !(settings_.position_round_off >= 0.0))
    throw std::invalid_argument("TransientSettings: relative_force_tolerance must be > 0 and "
                                "position_round_off >= 0");
  const int equations = map_.equation_count();
  mass_ = map_.reduced_mass(model_);
  damping_.resize(equations, equations);
  committed_nodes_ = model::initial_configuration(model_);
  trial_nodes_ = committed_nodes_;
  static_load_ = Eigen::VectorXd::Zero(model_.dof_count());
  velocity_ = Eigen::VectorXd::Zero(equations);
  acceleration_ = Eigen::VectorXd::Zero(equations);
  committed_full_force_ = Eigen::VectorXd::Zero(model_.dof_count());
  committed_reduced_force_ = Eigen::VectorXd::Zero(equations);
  for (int node = 0; node < model_.node_count(); ++node)
    model_extent_ = std::max(model_extent_, model_.coordinates(node).cwiseAbs().maxCoeff());
  equation_length_ = Eigen::VectorXd::Ones(equations);
  for (int dof = 0; dof < map_.full_dof_count(); ++dof) {
    const int equation = map_.independent_equation(dof);
    if (equation >= 0 && dof % model::kDofPerNode < 3)
      equation_length_[equation] = model_extent_;
  }
  round_off_floor_ = Eigen::VectorXd::Zero(equations);
  acceleration_consistent_ = false;

  // The committed start: forces and energies of the undeformed configuration.
  if (assembler_.assemble(committed_nodes_, false, initial_failure_)) {
    committed_full_force_ = assembler_.full_force();
    committed_reduced_force_ = assembler_.reduced_force();
    initial_element_energy_ = assembler_.energy();
  } else {
    initial_failure_ = "the initial state cannot be evaluated: " + initial_failure_;
  }
  for (const auto& element : model_.elements())
    element->revert_to_committed();
}

double TransientAnalysis::newmark_gamma() const {
  return settings_.integrator == TimeIntegrator::hht ? 0.5 - settings_.hht_alpha : 0.5;
}

double TransientAnalysis::newmark_beta() const {
  if (settings_.integrator != TimeIntegrator::hht)
    return 0.25;
  const double alpha = settings_.hht_alpha;
  return 0.25 * (1.0 - alpha) * (1.0 - alpha);
}

void TransientAnalysis::add_ground_acceleration(GroundAcceleration component) {
  if (!(component.dt > 0.0) || !std::isfinite(component.dt))
    throw std::invalid_argument("ground acceleration: dt must be > 0, got " +
                                readable(component.dt));
  if (std::abs(component.direction.norm() - 1.0) > 1e-9)
    throw std::invalid_argument("ground acceleration: the direction must be a unit vector");
  for (const double value : component.acceleration) {
    if (!std::isfinite(value))
      throw std::invalid_argument("ground acceleration: a sample is not finite");
  }
  influence_.push_back(map_.ground_influence(component.direction));
  ground_.push_back(std::move(component));
  acceleration_consistent_ = false;
}

Eigen::VectorXd TransientAnalysis::ground_force(double time) const {
  Eigen::VectorXd rigid = Eigen::VectorXd::Zero(map_.equation_count());
  for (std::size_t c = 0; c < ground_.size(); ++c)
    rigid += ground_[c].at(time) * influence_[c];
  return -(mass_ * rigid);
}

Eigen::Vector3d TransientAnalysis::ground_acceleration() const {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const GroundAcceleration& component : ground_)
    total += component.at(time_) * component.direction;
  return total;
}

Eigen::VectorXd TransientAnalysis::displacement() const {
  return model::full_displacement(model_, committed_nodes_);
}

Eigen::VectorXd TransientAnalysis::velocity() const {
  return map_.expand(velocity_);
}

Eigen::VectorXd TransientAnalysis::acceleration() const {
  return map_.expand(acceleration_);
}

Eigen::SparseMatrix<double> TransientAnalysis::tangent() {
  revert();
  std::string failure;
  const bool assembled = assembler_.assemble(committed_nodes_, true, failure);
  revert();
  if (!assembled)
    throw std::runtime_error("the tangent of the committed state cannot be assembled: " + failure);
  return assembler_.reduced_tangent();
}

void TransientAnalysis::set_damping(const DampingSpec& damping) {
  const auto element_count = model_.elements().size();
  if (!damping.include_in_stiffness_damping.empty() &&
      damping.include_in_stiffness_damping.size() != element_count)
    throw std::invalid_argument("damping: include_in_stiffness_damping has " +
                                std::to_string(damping.include_in_stiffness_damping.size()) +
                                " entries, the model has " + std::to_string(element_count) +
                                " elements");
  if (!(damping.mass_factor >= 0.0) || !(damping.stiffness_factor >= 0.0))
    throw std::invalid_argument("damping: the Rayleigh factors must be >= 0");
  for (const double ratio : damping.modal_ratios) {
    if (!(ratio >= 0.0) || !std::isfinite(ratio))
      throw std::invalid_argument("damping: each modal damping ratio must be >= 0");
  }
  const int equations = map_.equation_count();
  if (!damping.modal_ratios.empty()) {
    // C = M (sum_i 2 xi_i w_i phi_i phi_i^T) M (Chopra, Dynamics of Structures, eq. 11.5.5):
    // phi_j^T C phi_k = 2 xi_j w_j delta_jk for mass-normalised shapes.
    const std::vector<Mode> modes =
        modal_analysis(tangent(), mass_, map_, static_cast<int>(damping.modal_ratios.size()));
    Eigen::MatrixXd mass_shapes(equations, static_cast<Eigen::Index>(modes.size()));
    Eigen::VectorXd weights(static_cast<Eigen::Index>(modes.size()));
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const auto column = static_cast<Eigen::Index>(i);
      mass_shapes.col(column) = mass_ * modes[i].shape;
      weights[column] = 2.0 * damping.modal_ratios[i] * modes[i].circular_frequency;
    }
    const Eigen::MatrixXd dense = mass_shapes * weights.asDiagonal() * mass_shapes.transpose();
    damping_ = dense.sparseView();
  } else {
    Eigen::SparseMatrix<double> stiffness(equations, equations);
    if (damping.stiffness_factor > 0.0) {
      // K0: tangent of the committed state of the included elements (e.g. without braces)
      revert();
      std::string failure;
      const bool assembled = assembler_.assemble(committed_nodes_, true, failure,
                                                 damping.include_in_stiffness_damping.empty()
                                                     ? nullptr
                                                     : &damping.include_in_stiffness_damping);
      revert();
      if (!assembled)
        throw std::runtime_error("damping: the initial stiffness cannot be assembled: " + failure);
      stiffness = assembler_.reduced_tangent();
    }
    damping_ = damping.mass_factor * mass_ + damping.stiffness_factor * stiffness;
  }
  damping_.makeCompressed();
  acceleration_consistent_ = false;
}

void TransientAnalysis::revert() {
  trial_nodes_ = committed_nodes_;
  for (const auto& element : model_.elements())
    element->revert_to_committed();
}

void TransientAnalysis::remove_static_load() {
  static_load_.setZero();
  acceleration_consistent_ = false;
}

void TransientAnalysis::make_acceleration_consistent() {
  // M a0 = p(t) - f_int - C v on the equations with mass; massless equations carry no
  // inertia (their acceleration is set to zero; they are static at the end of each step).
  acceleration_consistent_ = true;
  const Eigen::Index equations = map_.equation_count();
  const Eigen::VectorXd out_of_balance = map_.reduce(static_load_) + ground_force(time_) -
                                         committed_reduced_force_ - damping_ * velocity_;
  std::vector<int> massive_index(static_cast<std::size_t>(equations), -1);
  int massive = 0;
  const Eigen::VectorXd diagonal = mass_.diagonal();
  for (Eigen::Index i = 0; i < equations; ++i) {
    if (diagonal[i] > 0.0)
      massive_index[static_cast<std::size_t>(i)] = massive++;
  }
  acceleration_.setZero();
  if (massive == 0)
    return;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd right(massive);
  for (Eigen::Index column = 0; column < equations; ++column) {
    const int j = massive_index[static_cast<std::size_t>(column)];
    if (j >= 0)
      right[j] = out_of_balance[column];
    for (Eigen::SparseMatrix<double>::InnerIterator entry(mass_, column); entry; ++entry) {
      const int i = massive_index[static_cast<std::size_t>(entry.row())];
      if (i >= 0 && j >= 0)
        triplets.emplace_back(i, j, entry.value());
    }
  }
  Eigen::SparseMatrix<double> massive_mass(massive, massive);
  massive_mass.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(massive_mass);
  const Eigen::VectorXd solution =
      factor.info() == Eigen::Success ? Eigen::VectorXd(factor.solve(right)) : Eigen::VectorXd();
  if (factor.info() != Eigen::Success || !solution.allFinite()) {
    fallbacks_.push_back({time_, "initial acceleration set to zero",
                          "the mass matrix of the equations with mass is singular"});
    return;
  }
  for (Eigen::Index i = 0; i < equations; ++i) {
    const int j = massive_index[static_cast<std::size_t>(i)];
    if (j >= 0)
      acceleration_[i] = solution[j];
  }
}

Eigen::VectorXd TransientAnalysis::residual(const Increment& increment,
                                            const Eigen::VectorXd& dq) const {
  const Eigen::VectorXd& internal = assembler_.reduced_force();
  if (!increment.dynamic)
    return increment.external - internal;
  const Eigen::VectorXd velocity = increment.velocity_at(dq);
  return increment.external - mass_ * increment.acceleration_at(dq) -
         (1.0 + increment.alpha) * (internal + damping_ * velocity);
}

Eigen::SparseMatrix<double> TransientAnalysis::effective_tangent(const Increment& increment) const {
  if (!increment.dynamic)
    return assembler_.reduced_tangent();
  const double weight = 1.0 + increment.alpha;
  Eigen::SparseMatrix<double> matrix =
      weight * assembler_.reduced_tangent() +
      (weight * increment.gamma / (increment.beta * increment.dt)) * damping_ +
      (1.0 / (increment.beta * increment.dt * increment.dt)) * mass_;
  return matrix;
}

bool TransientAnalysis::factorize(const Eigen::SparseMatrix<double>& matrix) {
  // The pattern (hence the ordering) is analysed again only when it changes.
  std::vector<int> pattern(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.outerSize() + 1);
  pattern.insert(pattern.end(), matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
  if (pattern != solver_pattern_) {
    solver_.analyzePattern(matrix);
    solver_pattern_ = std::move(pattern);
  }
  solver_.factorize(matrix);
  return solver_.info() == Eigen::Success;
}

bool TransientAnalysis::converged(const Increment& increment, const Eigen::VectorXd& dq,
                                  const Eigen::VectorXd& residual) const {
  if (residual.size() == 0)
    return true;
  // Scale: the largest element force (round-off of cancelling element forces at the nodes),
  // the largest inertia, damping and external force, and 1 N; floor (per equation): node
  // positions carry a relative error of position_round_off of the model's size (triads: of
  // 1 rad), which the element tangent turns into force. Inertia and damping forces come
  // from dq, not from positions: the mass does not enter the floor.
  double scale = assembler_.force_scale() + infinity_norm(increment.external) + 1.0;
  if (increment.dynamic) {
    scale += std::max(infinity_norm(mass_ * increment.acceleration_at(dq)),
                      infinity_norm(damping_ * increment.velocity_at(dq)));
  }
  return ((residual.cwiseAbs() - round_off_floor_).maxCoeff()) <=
         settings_.relative_force_tolerance * scale;
}

TransientAnalysis::Attempt TransientAnalysis::solve(const Increment& increment, Algorithm algorithm,
                                                    int max_iterations) {
  Attempt attempt;
  revert();
  const Eigen::Index equations = map_.equation_count();
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(equations);
  // Predictor: the committed configuration (dq = 0) with Newmark's velocity and acceleration.
  // The first assembly always carries the tangent: modified Newton and Broyden keep it.
  if (!assembler_.assemble(trial_nodes_, true, attempt.failure))
    return attempt;
  const bool full_newton = algorithm == Algorithm::newton;
  // Broyden's second ("bad") method on the inverse: H_k+1 = H_k + (s - H_k y) y^T / (y^T y),
  // with s the accepted increment and y the residual's drop (secant H y = s); H_0 is the
  // factorised committed tangent. H v = H_0 v + sum_j u_j (y_j^T v).
  std::vector<Eigen::VectorXd> secant_u, secant_y;
  const auto apply_inverse = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd result = solver_.solve(v);
    for (std::size_t j = 0; j < secant_u.size(); ++j)
      result += secant_u[j] * secant_y[j].dot(v);
    return result;
  };
  for (int iteration = 0;; ++iteration) {
    const Eigen::VectorXd out_of_balance = residual(increment, dq);
    if (!out_of_balance.allFinite()) {
      attempt.failure = "non-finite residual";
      return attempt;
    }
    if ((iteration > 0 || equations == 0) && converged(increment, dq, out_of_balance)) {
      attempt.converged = true;
      attempt.iterations = iteration;
      attempt.increment = std::move(dq);
      return attempt;
    }
    if (iteration == max_iterations) {
      attempt.iterations = iteration;
      attempt.failure = "did not converge in " + std::to_string(max_iterations) +
                        " iterations (residual " +
                        readable(out_of_balance.lpNorm<Eigen::Infinity>()) + " N)";
      return attempt;
    }
    if (full_newton || iteration == 0) {
      // Per equation, not the largest entry: a diaphragm's rotation carries stiffnesses
      // k arm^2 (N mm/rad, 1e15 on a building) that would make a floor of 1e5 N for the
      // force equations (measured: residuals of 190 kN accepted on a 3D frame).
      round_off_floor_ = settings_.position_round_off *
                         (assembler_.reduced_tangent().cwiseAbs() * equation_length_);
      if (!factorize(effective_tangent(increment))) {
        attempt.failure = "singular effective tangent";
        return attempt;
      }
    }
    const Eigen::VectorXd direction = algorithm == Algorithm::broyden
                                          ? apply_inverse(out_of_balance)
                                          : Eigen::VectorXd(solver_.solve(out_of_balance));
    if (!direction.allFinite()) {
      attempt.failure = "non-finite increment";
      return attempt;
    }

    // Backtracking line search on the residual norm (up to 6 halvings; the last one is
    // taken if the elements accept it). The trial configuration is always the committed one
    // moved by the whole dq in one exponential, R = exp([dq]x) R_0, never by a product of
    // the corrections' exponentials: those differ by their commutators (rotations about
    // different axes), so the nodes would not be where dq (hence v, a and the trapezoidal
    // work) says, an error of O(dt^2) per step in the energy balance (measured on a 3D frame
    // with diaphragms: 4 % of the input, halving with dt). The Newton matrix then ignores
    // the Jacobian of exp (I + O(|dq|) for a step's rotation): exact for translations and
    // rotations about one axis, a quasi-Newton for the rest.
    const double start_norm = out_of_balance.norm();
    double step = 1.0;
    Eigen::VectorXd next_residual;
    for (int search = 0;; ++search) {
      trial_nodes_ = committed_nodes_;
      model::apply_increment(map_, trial_nodes_, dq + step * direction);
      std::string failure;
      const bool evaluated = assembler_.assemble(trial_nodes_, full_newton, failure);
      if (evaluated)
        next_residual = residual(increment, dq + step * direction);
      const bool accept =
          evaluated && next_residual.allFinite() &&
          (!settings_.line_search || search == 6 || next_residual.norm() < start_norm);
      if (accept)
        break;
      if (search == 6 || (!settings_.line_search && !evaluated)) {
        attempt.iterations = iteration + 1;
        attempt.failure = !evaluated                  ? failure
                          : next_residual.allFinite() ? "line search failed"
                                                      : "non-finite residual";
        return attempt;
      }
      step *= 0.5;
    }
    const Eigen::VectorXd accepted = step * direction;
    dq += accepted;
    if (algorithm == Algorithm::broyden) {
      const Eigen::VectorXd drop = out_of_balance - next_residual;
      const double norm2 = drop.squaredNorm();
      if (norm2 > 0.0) {
        secant_u.push_back((accepted - apply_inverse(drop)) / norm2);
        secant_y.push_back(drop);
      }
    }
  }
}

void TransientAnalysis::commit(const Increment& increment, const Eigen::VectorXd& dq) {
  const element::ElementEnergy elements = assembler_.energy();
  if (increment.dynamic) {
    const Eigen::VectorXd acceleration = increment.acceleration_at(dq);
    const Eigen::VectorXd velocity = increment.velocity_at(dq);
    const double input = 0.5 * (increment.ground_from + increment.ground_to).dot(dq);
    const double static_work = increment.static_load.dot(dq);
    energy_.input += input;
    energy_.static_work += static_work;
    energy_.gross_input += std::abs(input) + std::abs(static_work);
    energy_.damping += 0.5 * (damping_ * (increment.velocity + velocity)).dot(dq);
    energy_.kinetic = 0.5 * velocity.dot(mass_ * velocity);
    velocity_ = velocity;
    acceleration_ = acceleration;
    time_ = increment.to;
  } else {
    const double static_work = 0.5 * (increment.external_from + increment.external).dot(dq);
    energy_.static_work += static_work;
    energy_.gross_input += std::abs(static_work);
    static_fraction_ = increment.to;
  }
  energy_.stored = elements.stored - initial_element_energy_.stored;
  energy_.dissipated = elements.dissipated - initial_element_energy_.dissipated;
  energy_.integration_misfit =
      elements.integration_misfit - initial_element_energy_.integration_misfit;
  for (const auto& element : model_.elements())
    element->commit();
  committed_nodes_ = trial_nodes_;
  committed_full_force_ = assembler_.full_force();
  committed_reduced_force_ = assembler_.reduced_force();
  if (model_.apply_commit_couplings()) {
    // a coupling changed committed states at a fixed configuration (Model::
    // add_commit_coupling): no work is done; the committed forces are those of the new state
    std::string failure;
    for (const auto& element : model_.elements())
      element->revert_to_committed();
    if (assembler_.assemble(committed_nodes_, false, failure)) {
      committed_full_force_ = assembler_.full_force();
      committed_reduced_force_ = assembler_.reduced_force();
    }
  }
}

TransientAnalysis::Increment TransientAnalysis::make_increment(bool dynamic, double from,
                                                               double to) const {
  Increment increment;
  increment.dynamic = dynamic;
  increment.from = from;
  increment.to = to;
  if (!dynamic) {
    increment.external_from = map_.reduce(static_base_ + from * static_delta_);
    increment.external = map_.reduce(static_base_ + to * static_delta_);
    return increment;
  }
  increment.dt = to - from;
  increment.alpha = settings_.integrator == TimeIntegrator::hht ? settings_.hht_alpha : 0.0;
  increment.beta = newmark_beta();
  increment.gamma = newmark_gamma();
  increment.velocity = velocity_;
  increment.acceleration = acceleration_;
  increment.static_load = map_.reduce(static_load_);
  increment.ground_from = ground_force(from);
  increment.ground_to = ground_force(to);
  const double alpha = increment.alpha;
  // (1 + alpha) p_1 - alpha p_0 + alpha (f_int + C v)_0, with the committed internal force
  increment.external = increment.static_load + (1.0 + alpha) * increment.ground_to -
                       alpha * increment.ground_from +
                       alpha * (committed_reduced_force_ + damping_ * velocity_);
  return increment;
}

bool TransientAnalysis::try_increment(bool dynamic, double from, double to, int depth,
                                      TransientStepReport& report) {
  const Increment increment = make_increment(dynamic, from, to);
  const double record_time = dynamic ? from : time_;
  const std::string prefix = dynamic ? "" : "static load: ";
  const auto attempt = [&](Algorithm algorithm, int iterations) {
    Attempt result = solve(increment, algorithm, iterations);
    report.iterations += result.iterations;
    if (result.converged) {
      commit(increment, result.increment);
      ++report.substeps;
    } else {
      revert();
    }
    return result;
  };
  Attempt result = attempt(Algorithm::newton, settings_.max_iterations);
  if (result.converged)
    return true;
  if (depth < settings_.max_halvings) {
    fallbacks_.push_back(
        {record_time,
         prefix + "substeps of 1/" + std::to_string(1L << (depth + 1)) + " of the step",
         result.failure});
    const double middle = 0.5 * (from + to);
    return try_increment(dynamic, from, middle, depth + 1, report) &&
           try_increment(dynamic, middle, to, depth + 1, report);
  }
  fallbacks_.push_back(
      {record_time, prefix + "modified Newton (committed tangent)", result.failure});
  result = attempt(Algorithm::modified_newton, settings_.fallback_iterations);
  if (result.converged)
    return true;
  fallbacks_.push_back({record_time, prefix + "Broyden", result.failure});
  result = attempt(Algorithm::broyden, settings_.fallback_iterations);
  if (result.converged)
    return true;
  report.failure = prefix + "step from " + readable(from) + " to " + readable(to) +
                   (dynamic ? " s" : " (load fraction)") +
                   ": every fallback failed; last (Broyden): " + result.failure;
  return false;
}

TransientStepReport TransientAnalysis::step(double dt) {
  TransientStepReport report;
  report.substeps = 0;
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    report.failure = "the time step must be > 0 and finite, got " + readable(dt);
    return report;
  }
  if (!initial_failure_.empty()) {
    report.failure = initial_failure_;
    return report;
  }
  if (!acceleration_consistent_)
    make_acceleration_consistent();
  report.converged = try_increment(true, time_, time_ + dt, 0, report);
  return report;
}

TransientStepReport TransientAnalysis::apply_static_load(const Eigen::VectorXd& load, int steps) {
  TransientStepReport report;
  report.substeps = 0;
  if (load.size() != model_.dof_count() || !load.allFinite()) {
    report.failure = "static load: expected a finite vector of " +
                     std::to_string(model_.dof_count()) + " DOF (6 per node), got " +
                     std::to_string(load.size()) + " entries";
    return report;
  }
  if (steps < 1) {
    report.failure =
        "static load: the number of load steps must be >= 1, got " + std::to_string(steps);
    return report;
  }
  if (!initial_failure_.empty()) {
    report.failure = initial_failure_;
    return report;
  }
  static_base_ = static_load_;
  static_delta_ = load;
  static_fraction_ = 0.0;
  acceleration_consistent_ = false;
  report.converged = true;
  for (int step = 1; step <= steps && report.converged; ++step)
    report.converged =
        try_increment(false, static_fraction_, static_cast<double>(step) / steps, 0, report);
  // Substeps commit as they go: the held load is the one the committed state balances.
  static_load_ = static_base_ + static_fraction_ * static_delta_;
  return report;
}

} // namespace brb::analysis
