// AxialTie: a penalty spring between the mean axial (x) displacements of two node sets, the
// stopper of the 3D brace (brace_mesh.hpp) that ties the core to the casing at one station
// (the reduced model's stopper is a zero-length spring between a core and a casing node).
//
// With g = (1 / n_A on the x DOFs of set A, -1 / n_B on those of set B), the spring's
// elongation is e = g . u, its force f = k e, its nodal forces f g (internal-force sense), its
// energy k e^2 / 2. Its stiffness k g g^T has rank one, so its highest squared frequency with
// the lumped mass M is exactly k g^T M^-1 g = k (sum_A 1 / (n_A^2 m_a) + sum_B 1 / (n_B^2 m_b)).
#pragma once

#include "brb/solid/solid_interaction.hpp"

#include <vector>

namespace brb::solid {

class AxialTie final : public SolidInteraction {
public:
  /// Throws std::invalid_argument for an empty set, a negative node or k <= 0.
  AxialTie(std::vector<int> set_a, std::vector<int> set_b, double stiffness);

  bool add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                 std::string& reason) override;
  void commit() override { elongation_ = trial_elongation_; }
  double stored_energy() const override { return 0.5 * stiffness_ * elongation_ * elongation_; }
  double dissipated_energy() const override { return 0.0; }
  double frequency_bound_squared(const Eigen::VectorXd& lumped_mass) const override;

  double stiffness() const { return stiffness_; }
  /// Force of the committed state (N, positive when A is pulled away from B along +x).
  double force() const { return stiffness_ * elongation_; }

private:
  std::vector<int> set_a_, set_b_;
  double stiffness_;
  double elongation_ = 0.0, trial_elongation_ = 0.0;
};

} // namespace brb::solid
