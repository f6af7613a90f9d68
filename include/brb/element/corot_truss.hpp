// CorotTruss: a two-node co-rotational truss with any uniaxial law (value interface:
// State, evaluate(state, strain) -> {stress, tangent, state}, free_energy, dissipated_energy).
// Exact for large rotations: the engineering strain eps = (l - L0) / L0 of the current
// chord, N = A sigma(eps), nodal forces N (-e, e) with e the chord direction, tangent
//   K = (A E_t / L0) e e^T + (N / l)(I - e e^T)   on (u_i, u_j); rotations carry nothing,
// so nodes joined only by trusses need their rotations restrained.
#pragma once

#include "brb/element/element.hpp"

#include <array>
#include <cmath>

namespace brb::element {

/// Nodal forces and tangent (12 DOF, rotations carry nothing) of an axial force N along the
/// current chord (unit `direction`, `length` l) with axial stiffness dN/dl:
///   f = N (-e, e),  K = (dN/dl) e e^T + (N / l)(I - e e^T)  on (u_i, u_j).
inline void chord_force_and_tangent(const Vector3& direction, double length, double axial_force,
                                    double axial_stiffness, Eigen::VectorXd& force,
                                    Eigen::MatrixXd& tangent) {
  const Matrix3 along = direction * direction.transpose();
  const Matrix3 block =
      axial_stiffness * along + axial_force / length * (Matrix3::Identity() - along);
  force = Eigen::VectorXd::Zero(12);
  tangent = Eigen::MatrixXd::Zero(12, 12);
  force.segment<3>(0) = -axial_force * direction;
  force.segment<3>(6) = axial_force * direction;
  tangent.block<3, 3>(0, 0) = block;
  tangent.block<3, 3>(6, 6) = block;
  tangent.block<3, 3>(0, 6) = -block;
  tangent.block<3, 3>(6, 0) = -block;
}

template <class UniaxialLaw> class CorotTruss final : public Element {
public:
  /// area A (mm^2); the law's characteristic length should be L0 (one integration point).
  CorotTruss(std::array<int, 2> nodes, const Vector3& position_i, const Vector3& position_j,
             double area, UniaxialLaw law)
      : nodes_(nodes), initial_length_((position_j - position_i).norm()), area_(area),
        law_(std::move(law)), committed_(law_.initial_state()), trial_(committed_) {}

  std::span<const int> nodes() const override { return nodes_; }

  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override {
    const Vector3 chord = configuration[1].position - configuration[0].position;
    const double length = chord.norm();
    if (!(length > 0.0)) {
      failure = "co-rotational truss of zero length";
      return false;
    }
    const Vector3 direction = chord / length;
    strain_ = (length - initial_length_) / initial_length_;
    const auto response = law_.evaluate(committed_, strain_);
    trial_ = response.state;
    axial_force_ = area_ * response.stress;
    chord_force_and_tangent(direction, length, axial_force_,
                            area_ * response.tangent / initial_length_, force, tangent);
    return true;
  }

  void commit() override {
    committed_work_ = stress_work();
    committed_ = trial_;
    committed_strain_ = strain_;
    committed_force_ = axial_force_;
  }
  void revert_to_committed() override {
    trial_ = committed_;
    strain_ = committed_strain_;
    axial_force_ = committed_force_;
  }
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  void save_state(io::StateWriter& out) const override { out(*this); }
  void load_state(io::StateReader& in) override {
    in(*this);
    revert_to_committed();
  }
  /// Checkpoints: the committed state; a reader follows with revert_to_committed().
  template <class Archive, class Self>
  requires io::state_of<Self, CorotTruss>
  friend void state_fields(Archive& archive, Self& truss) {
    archive(truss.committed_, truss.committed_strain_, truss.committed_force_,
            truss.committed_work_);
  }

  ElementEnergy energy() const override {
    const double volume = area_ * initial_length_;
    ElementEnergy energy{volume * law_.free_energy(trial_, strain_),
                         volume * UniaxialLaw::dissipated_energy(trial_)};
    energy.integration_misfit = stress_work() - energy.stored - energy.dissipated;
    return energy;
  }

  double axial_force() const { return axial_force_; }
  double strain() const { return strain_; }

private:
  std::array<int, 2> nodes_;
  double initial_length_;
  double area_;
  UniaxialLaw law_;
  typename UniaxialLaw::State committed_;
  typename UniaxialLaw::State trial_;
  double strain_ = 0.0;
  double axial_force_ = 0.0;
  double committed_strain_ = 0.0;
  double committed_force_ = 0.0;
  double committed_work_ = 0.0;

  /// The axial force's trapezoidal work on the elongation since the start (N mm).
  double stress_work() const {
    return committed_work_ + 0.5 * (committed_force_ + axial_force_) *
                                 (strain_ - committed_strain_) * initial_length_;
  }
};

} // namespace brb::element
