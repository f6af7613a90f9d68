// PenaltyFriction: core-casing interface (BRB_SOURCE_FACTS section 4). Normal contact by
// a penalty on the gap (force N = k_N <-g>, g >= 0 open), Coulomb friction with a
// tangential penalty k_T and a stick/slip return map |T| <= kappa N.
//
// Conventions: gap g in mm (positive open), N >= 0 is the compressive contact force (N),
// tangential relative displacement u_T and force T are 2-vectors (one component is
// enough for axial friction; leave the other zero).
#pragma once

#include "brb/io/state_archive.hpp"

#include <Eigen/Core>

namespace brb::material {

struct PenaltyFrictionParameters {
  double normal_stiffness = 0.0;     ///< k_N (N/mm), > 0
  double tangential_stiffness = 0.0; ///< k_T (N/mm), > 0
  double friction_coefficient = 0.1; ///< kappa (-), >= 0 (source: 0.1)

  /// Throws ParameterError naming the key (k_N, k_T, kappa).
  void validate() const;
};

struct FrictionState {
  Eigen::Vector2d slip = Eigen::Vector2d::Zero(); ///< irreversible tangential slip (mm)
  double dissipated_energy = 0.0;                 ///< friction work T . d(slip) (N mm)
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, FrictionState>
void state_fields(Archive& archive, Self& state) {
  archive(state.slip, state.dissipated_energy);
}

class PenaltyFriction {
public:
  using State = FrictionState;
  struct Response {
    double normal_force = 0.0;                                  ///< N >= 0
    Eigen::Vector2d tangential_force = Eigen::Vector2d::Zero(); ///< T
    /// d[N, T1, T2] / d[g, u_T1, u_T2]; non-symmetric when slipping.
    Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();
    bool in_contact = false;
    bool slipping = false;
    State state;
  };

  explicit PenaltyFriction(const PenaltyFrictionParameters& parameters);

  /// Linear normal penalty plus Coulomb friction.
  Response evaluate(const State& committed, double gap,
                    const Eigen::Vector2d& tangential_displacement) const;

  /// Coulomb return map for a normal force computed by another law (e.g. mortar bearing):
  /// normal_force >= 0 and its derivative with respect to the gap (<= 0 when closing).
  Response evaluate_with_normal(const State& committed, double normal_force,
                                double normal_force_gap_derivative,
                                const Eigen::Vector2d& tangential_displacement) const;

  const PenaltyFrictionParameters& parameters() const { return parameters_; }

private:
  PenaltyFrictionParameters parameters_;
};

} // namespace brb::material
