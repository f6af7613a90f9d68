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
//
// Split halves (split_halves()): a section cut through by a crack along its mid-plane y = 0
// (or z = 0) bends as two halves that slip along the crack, each about its own centroid.
// With split fractions phi_y, phi_z in [0, 1] and c_y, c_z the centroid of the fiber's half,
// the fiber strain is e0 + (z - phi_z c_z) kappa_y - (y - phi_y c_y) kappa_z + o, and the
// levers of the resultants are the same (work-conjugate), so at phi = 1 the bending stiffness
// is the sum of the halves' own, sum E A (y - c_y)^2, not the whole section's. The offsets o
// keep every fiber's strain (and so its stress) continuous when phi grows: the halves keep
// their axial forces (held by the member's ends and the crack's friction), the moment those
// forces made about the section's centroid leaves the resultants at once, and every energy
// of the section (stored, dissipated, stress work) stays continuous: the split does no work.
#pragma once

#include "brb/io/state_archive.hpp"
#include "brb/section/fiber_layout.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <concepts>
#include <stdexcept>
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
    deformation_ = deformation;
    return strain_offset_.empty() ? evaluate_fibers<false>(deformation)
                                  : evaluate_fibers<true>(deformation);
  }

  /// Splits the committed section along its mid-planes to the fractions (phi_y, phi_z), each
  /// in [0, 1] and not below its present value (a crack does not heal): phi_y frees the halves
  /// y > 0 and y < 0 (bending kappa_z), phi_z the halves z > 0 and z < 0 (kappa_y). The fiber
  /// strains and stresses stay as committed; last_response() becomes the committed state's
  /// response with the new levers. Call between commits only (the trial state is discarded).
  void split_halves(const std::array<double, 2>& fractions) {
    for (int axis = 0; axis < 2; ++axis) {
      if (!(fractions[axis] >= split_fraction_[axis] && fractions[axis] <= 1.0))
        throw std::invalid_argument("FiberSection::split_halves: a split fraction must lie in "
                                    "[its present value, 1]");
    }
    if (fractions == split_fraction_)
      return;
    if (half_centroid_y_.empty())
      locate_half_centroids();
    if (strain_offset_.empty())
      strain_offset_.assign(layout_.size(), 0.0);
    const double kappa_y = committed_deformation_[1], kappa_z = committed_deformation_[2];
    const double grow_y = fractions[0] - split_fraction_[0];
    const double grow_z = fractions[1] - split_fraction_[1];
    for (std::size_t i = 0; i < layout_.size(); ++i) {
      // e = e0 + (z - phi_z c_z) kappa_y - (y - phi_y c_y) kappa_z + o stays the same
      strain_offset_[i] +=
          grow_z * half_centroid_z_[i] * kappa_y - grow_y * half_centroid_y_[i] * kappa_z;
    }
    split_fraction_ = fractions;
    revert_to_committed();
    evaluate(committed_deformation_);
  }

  /// Split fractions (phi_y, phi_z) of the committed state (split_halves()).
  const std::array<double, 2>& split_fractions() const { return split_fraction_; }

  void commit() {
    committed_work_ = stress_work();
    committed_ = trial_;
    committed_stress_ = stress_;
    committed_strain_ = strain_;
    committed_deformation_ = deformation_;
  }
  void revert_to_committed() {
    trial_ = committed_;
    stress_ = committed_stress_;
    strain_ = committed_strain_;
    deformation_ = committed_deformation_;
  }

  /// Checkpoints (io/state_archive.hpp): the committed fibers and the last response; a
  /// reader follows with revert_to_committed().
  template <class Archive, class Self>
  requires io::state_of<Self, FiberSection>
  friend void state_fields(Archive& archive, Self& section) {
    archive(section.committed_, section.committed_stress_, section.committed_strain_,
            section.committed_work_, section.response_, section.committed_deformation_,
            section.split_fraction_, section.strain_offset_, section.half_centroid_y_,
            section.half_centroid_z_);
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
  template <bool with_split> const Response& evaluate_fibers(const SectionVector& deformation) {
    Response response;
    const double* y = layout_.y.data();
    const double* z = layout_.z.data();
    const double* area = layout_.area.data();
    for (std::size_t i = 0; i < layout_.size(); ++i) {
      double lever_z = z[i], lever_y = y[i], offset = 0.0;
      if constexpr (with_split) {
        lever_z -= split_fraction_[1] * half_centroid_z_[i];
        lever_y -= split_fraction_[0] * half_centroid_y_[i];
        offset = strain_offset_[i];
      }
      const double strain =
          deformation[0] + lever_z * deformation[1] - lever_y * deformation[2] + offset;
      const auto fiber = law_.evaluate(committed_[i], strain);
      trial_[i] = fiber.state;
      stress_[i] = fiber.stress;
      strain_[i] = strain;
      const double force = fiber.stress * area[i];
      response.force += SectionVector(force, force * lever_z, -force * lever_y);
      const SectionVector lever(1.0, lever_z, -lever_y);
      response.tangent.noalias() += (fiber.tangent * area[i]) * lever * lever.transpose();
    }
    response_ = response;
    return response_;
  }

  /// Area centroid of each fiber's half, y > 0 or y < 0 (0 on the plane), and z likewise.
  void locate_half_centroids() {
    const auto centroids = [this](const std::vector<double>& coordinate) {
      double moment_above = 0.0, area_above = 0.0, moment_below = 0.0, area_below = 0.0;
      for (std::size_t i = 0; i < layout_.size(); ++i) {
        if (coordinate[i] > 0.0) {
          moment_above += layout_.area[i] * coordinate[i];
          area_above += layout_.area[i];
        } else if (coordinate[i] < 0.0) {
          moment_below += layout_.area[i] * coordinate[i];
          area_below += layout_.area[i];
        }
      }
      std::vector<double> half_centroid(layout_.size(), 0.0);
      for (std::size_t i = 0; i < layout_.size(); ++i) {
        if (coordinate[i] > 0.0)
          half_centroid[i] = moment_above / area_above;
        else if (coordinate[i] < 0.0)
          half_centroid[i] = moment_below / area_below;
      }
      return half_centroid;
    };
    half_centroid_y_ = centroids(layout_.y);
    half_centroid_z_ = centroids(layout_.z);
  }

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
  SectionVector deformation_ = SectionVector::Zero();           ///< of the last evaluate()
  SectionVector committed_deformation_ = SectionVector::Zero(); ///< of the committed state
  std::array<double, 2> split_fraction_{}; ///< phi_y, phi_z (committed; split_halves())
  std::vector<double> strain_offset_;      ///< o per fiber (empty while never split)
  std::vector<double> half_centroid_y_;    ///< c_y per fiber (empty while never split)
  std::vector<double> half_centroid_z_;    ///< c_z per fiber
};

} // namespace brb::section
