// Explicit central differences for the 3D continuum model (see solid_explicit.hpp).
#include "brb/solid/solid_explicit.hpp"
#include "brb/analysis/eigen_velocity_verlet.hpp"

#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace brb::solid {

namespace {

using Stepper = analysis::EigenVelocityVerlet;

} // namespace

double smooth_ramp(double time, double duration) {
  if (time <= 0.0)
    return 0.0;
  if (time >= duration)
    return 1.0;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * time / duration));
}

double SolidExplicitEnergy::relative_error() const {
  const double stored = accounted();
  return std::abs(external - stored) / std::max({std::abs(external), std::abs(stored), 1e-30});
}

template <class Model>
SolidExplicitSolver<Model>::SolidExplicitSolver(Model& model, SolidLoading loading,
                                                SolidExplicitSettings settings)
    : model_(model), loading_(std::move(loading)) {
  const int n = model_.dof_count();
  std::vector<bool> prescribed(n, false);
  for (int dof : loading_.prescribed.dofs) {
    if (dof < 0 || dof >= n)
      throw std::invalid_argument("solid explicit: prescribed DOF " + std::to_string(dof) +
                                  " is not a DOF of the model");
    prescribed[dof] = true;
  }
  if (loading_.load.size() != 0 && loading_.load.size() != n)
    throw std::invalid_argument("solid explicit: the load vector does not match the model's DOFs");
  for (int dof = 0; dof < n; ++dof)
    if (!prescribed[dof])
      free_dofs_.push_back(dof);
  const Eigen::VectorXd lumped = model_.lumped_mass();
  // Pivoting faces: the mass centre and the principal axes of the x masses' inertia about it
  // in the face's (y, z) plane; J_k = e_k^T S e_k is the eigenvalue of S = sum m r r^T.
  std::vector<double> inertias;
  for (const PivotingFace& face : loading_.pivoting_faces) {
    if (face.nodes.empty() || face.positions.cols() != static_cast<Eigen::Index>(face.nodes.size()))
      throw std::invalid_argument(
          "solid explicit: a pivoting face needs its nodes and one (y, z) position per node");
    Pivot pivot;
    double total = 0.0;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < face.nodes.size(); ++i) {
      const int dof = 3 * face.nodes[i];
      if (dof < 0 || dof >= n || !prescribed[dof])
        throw std::invalid_argument("solid explicit: node " + std::to_string(face.nodes[i]) +
                                    " of a pivoting face needs its x DOF prescribed");
      pivot.dofs.push_back(dof);
      total += lumped[dof];
      centre += lumped[dof] * face.positions.col(static_cast<Eigen::Index>(i));
    }
    if (!(total > 0.0))
      throw std::invalid_argument("solid explicit: a pivoting face has no mass");
    centre /= total;
    Eigen::Matrix2d second_moment = Eigen::Matrix2d::Zero();
    for (std::size_t i = 0; i < face.nodes.size(); ++i) {
      const Eigen::Vector2d arm = face.positions.col(static_cast<Eigen::Index>(i)) - centre;
      second_moment += lumped[pivot.dofs[i]] * arm * arm.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(second_moment);
    for (int k = 0; k < 2; ++k) {
      if (!(principal.eigenvalues()[k] > 1e-12 * second_moment.trace()))
        throw std::invalid_argument(
            "solid explicit: a pivoting face's nodes lie on a line: it cannot pivot about it");
      const Eigen::Vector2d axis = principal.eigenvectors().col(k);
      for (std::size_t i = 0; i < face.nodes.size(); ++i)
        pivot.lever[static_cast<std::size_t>(k)].push_back(
            axis.dot(face.positions.col(static_cast<Eigen::Index>(i)) - centre));
      inertias.push_back(principal.eigenvalues()[k]);
    }
    pivots_.push_back(std::move(pivot));
  }
  mass_.resize(static_cast<Eigen::Index>(free_dofs_.size() + inertias.size()));
  for (std::size_t i = 0; i < free_dofs_.size(); ++i)
    mass_[i] = lumped[free_dofs_[i]];
  for (std::size_t j = 0; j < inertias.size(); ++j)
    mass_[static_cast<Eigen::Index>(free_dofs_.size() + j)] = inertias[j];
  if (!(settings.mass_damping >= 0.0) || !std::isfinite(settings.mass_damping))
    throw std::invalid_argument("solid explicit: the mass damping alpha must be finite and >= 0 "
                                "(1/s), got " +
                                std::to_string(settings.mass_damping));
  // empty without damping, so that an undamped step does none of its work
  const auto& directions = settings.damped_directions;
  if (settings.mass_damping > 0.0 && (directions[0] || directions[1] || directions[2])) {
    damping_ = Eigen::VectorXd::Zero(mass_.size());
    for (std::size_t i = 0; i < free_dofs_.size(); ++i)
      if (directions[static_cast<std::size_t>(free_dofs_[i] % 3)])
        damping_[static_cast<Eigen::Index>(i)] = settings.mass_damping * mass_[i];
  }
  stable_step_ = model_.stable_time_step(settings.stable_step_safety);
  time_step_ = settings.time_step > 0.0 ? settings.time_step : stable_step_;
  if (time_step_ > stable_step_ * (1.0 + 1e-12))
    throw std::invalid_argument("solid explicit: time step " + std::to_string(time_step_) +
                                " s exceeds the stable step " + std::to_string(stable_step_) +
                                " s");
  set_initial_state(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n));
}

template <class Model>
void SolidExplicitSolver<Model>::fill_prescribed(double t, Eigen::VectorXd& full) const {
  const double factor = loading_.history(t);
  for (std::size_t i = 0; i < loading_.prescribed.dofs.size(); ++i)
    full[loading_.prescribed.dofs[i]] = factor * loading_.prescribed.values[i];
}

template <class Model>
void SolidExplicitSolver<Model>::add_pivot_rotations(const Eigen::VectorXd& angles,
                                                     Eigen::VectorXd& full) const {
  for (std::size_t p = 0; p < pivots_.size(); ++p) {
    const Pivot& pivot = pivots_[p];
    const double first = angles[static_cast<Eigen::Index>(2 * p)];
    const double second = angles[static_cast<Eigen::Index>(2 * p + 1)];
    for (std::size_t i = 0; i < pivot.dofs.size(); ++i)
      full[pivot.dofs[i]] += first * pivot.lever[0][i] + second * pivot.lever[1][i];
  }
}

template <class Model>
void SolidExplicitSolver<Model>::accelerations(const Eigen::VectorXd& force, double t,
                                               Eigen::VectorXd& acceleration) const {
  acceleration.resize(mass_.size());
  const double load_factor = loading_.load_history(t);
  const auto net = [&](int dof) {
    const double external = loading_.load.size() ? load_factor * loading_.load[dof] : 0.0;
    return external - force[dof];
  };
  for (std::size_t i = 0; i < free_dofs_.size(); ++i)
    acceleration[static_cast<Eigen::Index>(i)] =
        net(free_dofs_[i]) / mass_[static_cast<Eigen::Index>(i)];
  // a pivot's angle: the moment of the net x forces about its axis over its inertia
  for (std::size_t p = 0; p < pivots_.size(); ++p) {
    for (std::size_t k = 0; k < 2; ++k) {
      double moment = 0.0;
      for (std::size_t i = 0; i < pivots_[p].dofs.size(); ++i)
        moment += net(pivots_[p].dofs[i]) * pivots_[p].lever[k][i];
      const auto j = static_cast<Eigen::Index>(free_dofs_.size() + 2 * p + k);
      acceleration[j] = moment / mass_[j];
    }
  }
}

template <class Model>
void SolidExplicitSolver<Model>::set_initial_state(const Eigen::VectorXd& displacement,
                                                   const Eigen::VectorXd& velocity) {
  displacement_ = displacement;
  velocity_ = velocity;
  pivot_angle_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * pivots_.size()));
  pivot_rate_ = pivot_angle_;
  fill_prescribed(time_, displacement_);
  std::string reason;
  if (!model_.evaluate(displacement_, force_, reason))
    throw std::invalid_argument("solid explicit: the initial state cannot be evaluated: " + reason);
  model_.commit();
  accelerations(force_, time_, acceleration_);
  // the damping force of the initial velocity (state vector: free DOFs, then the angles at rest)
  if (damping_.size() != 0) {
    for (std::size_t i = 0; i < free_dofs_.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      acceleration_[k] -= damping_[k] * velocity_[free_dofs_[i]] / mass_[k];
    }
  }
  energy_ = {};
  for (std::size_t i = 0; i < free_dofs_.size(); ++i)
    energy_.kinetic += 0.5 * mass_[i] * velocity_[free_dofs_[i]] * velocity_[free_dofs_[i]];
  take_model_energies();
  // the work that brought the model to its initial state
  energy_.external = energy_.accounted();
}

template <class Model> bool SolidExplicitSolver<Model>::advance(double dt, std::string& failure) {
  // the state vector: the free DOFs, then the pivoting faces' angles
  const Eigen::Index m = mass_.size();
  const auto free_count = static_cast<Eigen::Index>(free_dofs_.size());
  const Eigen::Index angle_count = m - free_count;
  Eigen::VectorXd q(m), v(m);
  for (Eigen::Index i = 0; i < free_count; ++i) {
    q[i] = displacement_[free_dofs_[i]];
    v[i] = velocity_[free_dofs_[i]];
  }
  q.tail(angle_count) = pivot_angle_;
  v.tail(angle_count) = pivot_rate_;
  Eigen::VectorXd full = displacement_;
  Eigen::VectorXd force;
  bool evaluated = true;
  // mass damping at v_{n+1}, solved per equation (header): the half-step velocity it starts from
  const bool damped = damping_.size() != 0;
  Eigen::VectorXd half_step_velocity;
  if (damped)
    half_step_velocity = v + 0.5 * dt * acceleration_;
  const auto system = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& /*v*/,
                          Eigen::VectorXd& a, double t) {
    for (Eigen::Index i = 0; i < free_count; ++i)
      full[free_dofs_[i]] = x[i];
    fill_prescribed(t, full);
    add_pivot_rotations(x.tail(angle_count), full);
    a.resize(m);
    if (!full.allFinite()) {
      evaluated = false;
      failure = "the displacement became non-finite";
      a.setZero();
      return;
    }
    evaluated = model_.evaluate(full, force, failure);
    if (!evaluated) {
      a.setZero();
      return;
    }
    accelerations(force, t, a);
    if (damped)
      a = (mass_.cwiseProduct(a) - damping_.cwiseProduct(half_step_velocity))
              .cwiseQuotient(mass_ + 0.5 * dt * damping_);
  };
  Stepper stepper;
  Eigen::VectorXd q_new(m), v_new(m), a_new(m);
  stepper.do_step(system, q, v, acceleration_, q_new, v_new, a_new, time_, dt);
  if (!evaluated)
    return false;
  if (!q_new.allFinite() || !v_new.allFinite() || !a_new.allFinite()) {
    failure = "the state became non-finite at t = " + std::to_string(time_ + dt) + " s";
    return false;
  }
  // external work, trapezoidal: reactions on the prescribed DOFs, loads on the free ones
  const Eigen::VectorXd increment = full - displacement_;
  double work = 0.0;
  for (int dof : loading_.prescribed.dofs)
    work += 0.5 * (force_[dof] + force[dof]) * increment[dof];
  // a pivoting face's rotation is a free motion, not the drive's: take its part out of the
  // reactions' work (the angles' kinetic energy and the elements' work account for it)
  for (std::size_t p = 0; p < pivots_.size(); ++p) {
    const double first = q_new[free_count + 2 * p] - q[free_count + 2 * p];
    const double second = q_new[free_count + 2 * p + 1] - q[free_count + 2 * p + 1];
    for (std::size_t i = 0; i < pivots_[p].dofs.size(); ++i) {
      const int dof = pivots_[p].dofs[i];
      work -= 0.5 * (force_[dof] + force[dof]) *
              (first * pivots_[p].lever[0][i] + second * pivots_[p].lever[1][i]);
    }
  }
  if (loading_.load.size()) {
    const double before = loading_.load_history(time_), after = loading_.load_history(time_ + dt);
    for (int dof : free_dofs_)
      work += 0.5 * (before + after) * loading_.load[dof] * increment[dof];
  }
  // the damping forces' work, trapezoidal: c v_n at the start, c v_{n+1} at the end
  if (damped)
    energy_.damping += 0.5 * (damping_.cwiseProduct(v + v_new)).dot(q_new - q);
  model_.commit();
  energy_.external += work;
  take_model_energies();
  energy_.kinetic = 0.5 * v_new.dot(mass_.cwiseProduct(v_new));
  displacement_ = full;
  for (Eigen::Index i = 0; i < free_count; ++i)
    velocity_[free_dofs_[i]] = v_new[i];
  pivot_angle_ = q_new.tail(angle_count);
  pivot_rate_ = v_new.tail(angle_count);
  // velocities of the prescribed DOFs: the history's, by central difference over the step
  for (std::size_t i = 0; i < loading_.prescribed.dofs.size(); ++i)
    velocity_[loading_.prescribed.dofs[i]] = increment[loading_.prescribed.dofs[i]] / dt;
  acceleration_ = a_new;
  force_ = force;
  time_ += dt;
  ++steps_;
  return true;
}

template <class Model> bool SolidExplicitSolver<Model>::run_to(double time, std::string& failure) {
  while (time - time_ > 1e-9 * time_step_) {
    if (!advance(std::min(time_step_, time - time_), failure))
      return false;
  }
  return true;
}

template <class Model> void SolidExplicitSolver<Model>::take_model_energies() {
  const SolidEnergy model = model_.energy();
  energy_.internal = model.internal;
  energy_.hourglass = model.hourglass;
  energy_.interaction = model.interaction;
  energy_.friction = model.friction;
}

template class SolidExplicitSolver<SolidModel<material::IsotropicElastic3D>>;
template class SolidExplicitSolver<SolidModel<material::SteelDamagePlasticity3D>>;
template class SolidExplicitSolver<SolidModel<material::MortarDamage3D>>;
template class SolidExplicitSolver<SolidBody>;

} // namespace brb::solid
