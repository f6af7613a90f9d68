// BraceTruss: the `truss` fidelity of the BRB element (DESIGN.md section 4). A two-node
// co-rotational truss between the outer nodes whose axial response is the yielding core
// (closed-form uniaxial steel law, SteelUniaxial, one material point over the yielding
// length) in series with the elastic end zones (connection and transition at both ends,
// flexibility f_e = sum L_i / (E A_i)).
//
// Series split, for the deformation Delta = l - L0 (change of the outer-node distance):
//   g(eps) = eps L_y + f_e A sigma(eps) - Delta = 0
// solved for the yielding-zone strain eps by a scalar Newton from the committed strain;
// N = A sigma(eps). Consistent tangent dN/dDelta = 1 / (L_y / (A E_t) + f_e), i.e.
// A E_t / g'(eps). Nodal forces N (-e, e), tangent (dN/dDelta) e e^T + (N / l)(I - e e^T)
// on the translations, as CorotTruss; rotations carry nothing (hold them in the model).
#pragma once

#include "brb/element/element.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <array>

namespace brb::element {

struct BraceTrussParameters {
  material::SteelParameters steel;
  double core_area = 0.0;       ///< yielding core's area A (mm^2)
  double yielding_length = 0.0; ///< L_y (mm)
  double end_flexibility = 0.0; ///< sum over the end zones of L_i / (E A_i) (mm/N), >= 0

  /// Throws ParameterError naming the key (core_area, yielding_length, end_flexibility).
  void validate() const;
};

class BraceTruss final : public Element {
public:
  /// The distance between the reference positions is the brace's length. `elastic_fast_path`:
  /// SteelUniaxial::set_elastic_fast_path of the core's material point.
  BraceTruss(std::array<int, 2> nodes, const Vector3& position_i, const Vector3& position_j,
             const BraceTrussParameters& parameters, bool elastic_fast_path = true);

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override;
  void revert_to_committed() override;
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  void save_state(io::StateWriter& out) const override { out(*this); }
  void load_state(io::StateReader& in) override {
    in(*this);
    revert_to_committed();
  }
  /// Checkpoints (io/state_archive.hpp): the committed state; a reader follows with
  /// revert_to_committed().
  template <class Archive, class Self>
  requires io::state_of<Self, BraceTruss>
  friend void state_fields(Archive& archive, Self& truss) {
    archive(truss.committed_, truss.committed_strain_, truss.committed_force_,
            truss.committed_work_, truss.deformation_);
  }
  ElementEnergy energy() const override;

  const BraceTrussParameters& parameters() const { return parameters_; }
  const material::SteelUniaxial& law() const { return law_; }
  /// Of the last evaluation (trial state): axial force N (N, tension positive), deformation
  /// Delta (mm), yielding-zone strain, damage of the core.
  double axial_force() const { return axial_force_; }
  double deformation() const { return deformation_; }
  double core_strain() const { return strain_; }
  double damage() const { return trial_.damage; }
  /// The elastic axial stiffness 1 / (L_y / (E A) + f_e) (N/mm).
  double elastic_stiffness() const;

private:
  std::array<int, 2> nodes_;
  double initial_length_;
  BraceTrussParameters parameters_;
  material::SteelUniaxial law_;
  material::SteelStateUniaxial committed_;
  material::SteelStateUniaxial trial_;
  double committed_strain_ = 0.0;
  double strain_ = 0.0;
  double axial_force_ = 0.0;
  double deformation_ = 0.0;
  double committed_force_ = 0.0;
  double committed_work_ = 0.0;

  /// The axial force's trapezoidal work on the core's elongation since the start (N mm; the
  /// elastic end zones' share is their stored energy exactly, so it is not summed).
  double core_stress_work() const;
};

} // namespace brb::element
