// UniaxialLaw: one value type for the uniaxial laws a frame's trusses and springs use, chosen
// at construction: linear elastic (E), the closed-form steel law (material::SteelUniaxial) or
// the uniaxial mortar law (material::MortarUniaxial), i.e. what io/material_input builds plus
// {"law": "elastic", "E"}. A std::variant of value types: one jump per evaluation, no virtual
// call, and the element owning it stays a plain value (copy_state_from copies it).
//
// Interface (the one CorotTruss expects): State, initial_state(), evaluate(committed, strain)
// -> {stress, tangent, state}, free_energy(state, strain), dissipated_energy(state).
#pragma once

#include "brb/material/exponential_softening.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_parameters.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <variant>

namespace brb::element {

/// sigma = E eps, free energy E eps^2 / 2, nothing dissipated.
class LinearElasticLaw {
public:
  struct State {};
  struct Response {
    double stress = 0.0;
    double tangent = 0.0;
    State state;
  };

  /// Throws ParameterError("E") unless E > 0 and finite.
  explicit LinearElasticLaw(double youngs_modulus);

  State initial_state() const { return {}; }
  Response evaluate(const State& /*committed*/, double strain) const {
    return {youngs_modulus_ * strain, youngs_modulus_, {}};
  }
  double free_energy(const State& /*state*/, double strain) const {
    return 0.5 * youngs_modulus_ * strain * strain;
  }
  static double dissipated_energy(const State& /*state*/) { return 0.0; }
  double youngs_modulus() const { return youngs_modulus_; }

private:
  double youngs_modulus_;
};

/// Parameters of the elastic law ({"law": "elastic", "E": MPa}).
struct ElasticLawParameters {
  double youngs_modulus = 0.0; ///< E (MPa), or N/mm for a spring used as force-deformation
};

/// The parameters of any uniaxial law (what a frame file's "materials" entry holds).
using UniaxialLawParameters =
    std::variant<ElasticLawParameters, material::SteelParameters, material::MortarParameters>;

class UniaxialLaw {
public:
  using Law = std::variant<LinearElasticLaw, material::SteelUniaxial, material::MortarUniaxial>;
  /// The state of the law at the same index (the state types are distinct).
  using State =
      std::variant<LinearElasticLaw::State, material::SteelStateUniaxial, material::MortarState>;
  struct Response {
    double stress = 0.0;  ///< MPa
    double tangent = 0.0; ///< MPa
    State state;
  };

  explicit UniaxialLaw(Law law) : law_(std::move(law)) {}

  State initial_state() const;
  /// The committed state must be of this law (it is, when it came from initial_state()).
  Response evaluate(const State& committed, double strain) const;
  double free_energy(const State& state, double strain) const;
  /// Energy dissipated so far per unit volume (MPa).
  static double dissipated_energy(const State& state);

  const Law& law() const { return law_; }

private:
  Law law_;
};

/// Builds the law of `parameters` with the characteristic length lc (mm) of its material
/// point (used by the softening of the damage laws only). Throws ParameterError naming the
/// parameter's key (E, fy, ..., as in the material files).
UniaxialLaw
make_uniaxial_law(const UniaxialLawParameters& parameters, double characteristic_length,
                  material::LongElementRule rule = material::LongElementRule::lower_strength);

} // namespace brb::element
