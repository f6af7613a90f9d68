// IsotropicElastic3D: linear isotropic elasticity S = C E with the interface of the 3D laws
// (SteelDamagePlasticity3D): evaluate(committed state, Voigt strain) -> stress, tangent,
// trial state. Used by the elastic checks of the 3D continuum model.
#pragma once

#include "brb/material/tensor6.hpp"

namespace brb::material {

class IsotropicElastic3D {
public:
  struct State {};
  struct Response {
    Vector6 stress;  ///< Voigt, MPa
    Matrix6 tangent; ///< Voigt, engineering shear strains
    State state;
  };

  IsotropicElastic3D(double youngs_modulus, double poissons_ratio)
      : elasticity_{youngs_modulus, poissons_ratio},
        tangent_(voigt_tangent_from_mandel(elasticity_.stiffness())) {}

  State initial_state() const { return {}; }
  Response evaluate(const State& /*committed*/, const Vector6& strain) const {
    return {tangent_ * strain, tangent_, {}};
  }
  /// Stored energy 1/2 eps : C : eps per unit volume.
  double free_energy(const State& /*state*/, const Vector6& strain) const {
    return 0.5 * strain.dot(tangent_ * strain);
  }
  double youngs_modulus() const { return elasticity_.youngs_modulus; }
  double poissons_ratio() const { return elasticity_.poissons_ratio; }

private:
  IsotropicElasticity elasticity_;
  Matrix6 tangent_;
};

} // namespace brb::material
