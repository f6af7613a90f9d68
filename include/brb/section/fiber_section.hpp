// FiberSection: a cross-section integrated over its fibers, each following a uniaxial law
// (the closed-form steel law on the hot path, or any law with the same value interface).
//
// Kinematics (plane sections, Bernoulli): fiber strain eps = e0 + z kappa_y - y kappa_z,
// resultants N = sum sigma A, M_y = sum sigma A z, M_z = -sum sigma A y (OpenSees'
// convention). Deformation and force vectors are (e0, kappa_y, kappa_z) and (N, M_y, M_z),
// in mm, 1/mm, N, N mm. Torsion is elastic: T = G J twist.
//
// The section owns the fibers' committed and trial states in contiguous arrays; the loop
// over fibers calls the law directly (no virtual call per fiber).
#pragma once

#include "brb/io/state_archive.hpp"
#include "brb/section/fiber_layout.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <concepts>
#include <vector>

namespace brb::section {

using SectionVector = Eigen::Vector3d;
using SectionMatrix = Eigen::Matrix3d;

/// Section resultants and their tangent.
struct SectionResponse {
  SectionVector force = SectionVector::Zero();   ///< (N, M_y, M_z)
  SectionMatrix tangent = SectionMatrix::Zero(); ///< d force / d deformation (symmetric)
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, SectionResponse>
void state_fields(Archive& archive, Self& response) {
  archive(response.force, response.tangent);
}

template <class UniaxialLaw> class FiberSection {
public:
  using FiberState = typename UniaxialLaw::State;
  using Response = SectionResponse;

  /// shear_modulus G (MPa) for the elastic torsion stiffness G J.
  FiberSection(FiberLayout layout, UniaxialLaw law, double shear_modulus)
      : layout_(std::move(layout)), law_(std::move(law)), shear_modulus_(shear_modulus),
        committed_(layout_.size(), law_.initial_state()), trial_(committed_),
        stress_(layout_.size(), 0.0), strain_(layout_.size(), 0.0), committed_stress_(stress_),
        committed_strain_(strain_) {}

  /// Trial response at a section deformation; fiber trial states are kept until
  /// commit() or revert_to_committed().
  const Response& evaluate(const SectionVector& deformation) {
    Response response;
    const double* y = layout_.y.data();
    const double* z = layout_.z.data();
    const double* area = layout_.area.data();
    for (std::size_t i = 0; i < layout_.size(); ++i) {
      const double strain = deformation[0] + z[i] * deformation[1] - y[i] * deformation[2];
      const auto fiber = law_.evaluate(committed_[i], strain);
      trial_[i] = fiber.state;
      stress_[i] = fiber.stress;
      strain_[i] = strain;
      const double force = fiber.stress * area[i];
      response.force += SectionVector(force, force * z[i], -force * y[i]);
      const SectionVector lever(1.0, z[i], -y[i]);
      response.tangent.noalias() += (fiber.tangent * area[i]) * lever * lever.transpose();
    }
    response_ = response;
    return response_;
  }

  void commit() {
    committed_work_ = stress_work();
    committed_ = trial_;
    committed_stress_ = stress_;
    committed_strain_ = strain_;
  }
  void revert_to_committed() {
    trial_ = committed_;
    stress_ = committed_stress_;
    strain_ = committed_strain_;
  }

  /// Checkpoints (io/state_archive.hpp): the committed fibers and the last response; a
  /// reader follows with revert_to_committed().
  template <class Archive, class Self>
  requires io::state_of<Self, FiberSection>
  friend void state_fields(Archive& archive, Self& section) {
    archive(section.committed_, section.committed_stress_, section.committed_strain_,
            section.committed_work_, section.response_);
  }

  double torsional_stiffness() const { return shear_modulus_ * layout_.torsion_constant; }
  const FiberLayout& layout() const { return layout_; }
  const UniaxialLaw& law() const { return law_; }
  const std::vector<FiberState>& committed_states() const { return committed_; }
  const std::vector<FiberState>& trial_states() const { return trial_; }
  /// Fiber stresses of the last evaluate() (MPa).
  const std::vector<double>& fiber_stresses() const { return stress_; }
  const Response& last_response() const { return response_; }

  /// Fiber strains of the last evaluate().
  const std::vector<double>& fiber_strains() const { return strain_; }

  /// Free energy of the trial state per unit length (N mm / mm), fibers only.
  double stored_energy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < layout_.size(); ++i) {
      energy += layout_.area[i] * law_.free_energy(trial_[i], strain_[i]);
    }
    return energy;
  }

  /// Energy dissipated by the fibers per unit length (N mm / mm), trial state.
  double dissipated_energy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < layout_.size(); ++i) {
      energy += layout_.area[i] * UniaxialLaw::dissipated_energy(trial_[i]);
    }
    return energy;
  }

  /// Work of the fiber stresses on the fiber strains since the start per unit length
  /// (N mm / mm), summed over committed steps with the trapezoidal rule,
  /// sum_i A_i (sigma_c + sigma_t) (eps_t - eps_c) / 2: the rule by which the external work
  /// is summed (StaticAnalysis), so that the two agree up to the kinematics and the
  /// equilibrium tolerance, while stored + dissipated follow the law's own exact energy
  /// bookkeeping of its backward-Euler update.
  double stress_work() const {
    double work = 0.0;
    for (std::size_t i = 0; i < layout_.size(); ++i) {
      work += layout_.area[i] * (committed_stress_[i] + stress_[i]) *
              (strain_[i] - committed_strain_[i]);
    }
    return committed_work_ + 0.5 * work;
  }

  /// Largest fiber damage in the trial state.
  double max_damage() const {
    double worst = 0.0;
    for (const auto& state : trial_)
      worst = std::max(worst, state.damage);
    return worst;
  }

  /// Smallest fiber residual strength (a fraction of the onset stress, 1 if the section has
  /// no fibers) in the trial state, for laws that define it (MortarUniaxial::residual_strength).
  double min_residual_strength() const requires
      requires(const UniaxialLaw& law, const FiberState& state) {
    { law.residual_strength(state) } -> std::convertible_to<double>;
  }
  {
    double weakest = 1.0;
    for (const auto& state : trial_)
      weakest = std::min(weakest, law_.residual_strength(state));
    return weakest;
  }

private:
  FiberLayout layout_;
  UniaxialLaw law_;
  double shear_modulus_;
  std::vector<FiberState> committed_;
  std::vector<FiberState> trial_;
  std::vector<double> stress_;
  std::vector<double> strain_;
  std::vector<double> committed_stress_;
  std::vector<double> committed_strain_;
  double committed_work_ = 0.0; ///< stress_work() of the committed state
  Response response_;
};

} // namespace brb::section
