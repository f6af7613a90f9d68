// Explicit central differences for the 3D continuum model (see solid_explicit.hpp).
#include "brb/solid/solid_explicit.hpp"
#include "brb/analysis/eigen_velocity_verlet.hpp"

#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"

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
  mass_.resize(static_cast<Eigen::Index>(free_dofs_.size()));
  for (std::size_t i = 0; i < free_dofs_.size(); ++i)
    mass_[i] = lumped[free_dofs_[i]];
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
void SolidExplicitSolver<Model>::set_initial_state(const Eigen::VectorXd& displacement,
                                                   const Eigen::VectorXd& velocity) {
  displacement_ = displacement;
  velocity_ = velocity;
  fill_prescribed(time_, displacement_);
  std::string reason;
  if (!model_.evaluate(displacement_, force_, reason))
    throw std::invalid_argument("solid explicit: the initial state cannot be evaluated: " + reason);
  model_.commit();
  acceleration_.resize(mass_.size());
  const double load_factor = loading_.load_history(time_);
  for (std::size_t i = 0; i < free_dofs_.size(); ++i) {
    const int dof = free_dofs_[i];
    const double external = loading_.load.size() ? load_factor * loading_.load[dof] : 0.0;
    acceleration_[i] = (external - force_[dof]) / mass_[i];
  }
  energy_ = {};
  for (std::size_t i = 0; i < free_dofs_.size(); ++i)
    energy_.kinetic += 0.5 * mass_[i] * velocity_[free_dofs_[i]] * velocity_[free_dofs_[i]];
  take_model_energies();
  // the work that brought the model to its initial state
  energy_.external = energy_.accounted();
}

template <class Model> bool SolidExplicitSolver<Model>::advance(double dt, std::string& failure) {
  const Eigen::Index m = mass_.size();
  Eigen::VectorXd q(m), v(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q[i] = displacement_[free_dofs_[i]];
    v[i] = velocity_[free_dofs_[i]];
  }
  Eigen::VectorXd full = displacement_;
  Eigen::VectorXd force;
  bool evaluated = true;
  const auto system = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& /*v*/,
                          Eigen::VectorXd& a, double t) {
    for (Eigen::Index i = 0; i < m; ++i)
      full[free_dofs_[i]] = x[i];
    fill_prescribed(t, full);
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
    const double load_factor = loading_.load_history(t);
    for (Eigen::Index i = 0; i < m; ++i) {
      const int dof = free_dofs_[i];
      const double external = loading_.load.size() ? load_factor * loading_.load[dof] : 0.0;
      a[i] = (external - force[dof]) / mass_[i];
    }
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
  if (loading_.load.size()) {
    const double before = loading_.load_history(time_), after = loading_.load_history(time_ + dt);
    for (int dof : free_dofs_)
      work += 0.5 * (before + after) * loading_.load[dof] * increment[dof];
  }
  model_.commit();
  energy_.external += work;
  take_model_energies();
  energy_.kinetic = 0.5 * v_new.dot(mass_.cwiseProduct(v_new));
  displacement_ = full;
  for (Eigen::Index i = 0; i < m; ++i)
    velocity_[free_dofs_[i]] = v_new[i];
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
