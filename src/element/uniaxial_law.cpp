#include "brb/element/uniaxial_law.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>
#include <type_traits>

namespace brb::element {

LinearElasticLaw::LinearElasticLaw(double youngs_modulus) : youngs_modulus_(youngs_modulus) {
  if (!(youngs_modulus > 0.0) || !std::isfinite(youngs_modulus))
    throw ParameterError("E", "the elastic modulus E must be > 0 and finite");
}

UniaxialLaw::State UniaxialLaw::initial_state() const {
  return std::visit([](const auto& law) -> State { return law.initial_state(); }, law_);
}

UniaxialLaw::Response UniaxialLaw::evaluate(const State& committed, double strain) const {
  return std::visit(
      [&](const auto& law) -> Response {
        using LawState = typename std::decay_t<decltype(law)>::State;
        const auto response = law.evaluate(std::get<LawState>(committed), strain);
        return {response.stress, response.tangent, response.state};
      },
      law_);
}

double UniaxialLaw::free_energy(const State& state, double strain) const {
  return std::visit(
      [&](const auto& law) {
        using LawState = typename std::decay_t<decltype(law)>::State;
        return law.free_energy(std::get<LawState>(state), strain);
      },
      law_);
}

double UniaxialLaw::dissipated_energy(const State& state) {
  return std::visit(
      [](const auto& law_state) {
        using LawState = std::decay_t<decltype(law_state)>;
        if constexpr (std::is_same_v<LawState, LinearElasticLaw::State>) {
          return LinearElasticLaw::dissipated_energy(law_state);
        } else if constexpr (std::is_same_v<LawState, material::SteelStateUniaxial>) {
          return material::SteelUniaxial::dissipated_energy(law_state);
        } else {
          return material::MortarUniaxial::dissipated_energy(law_state);
        }
      },
      state);
}

UniaxialLaw make_uniaxial_law(const UniaxialLawParameters& parameters, double characteristic_length,
                              material::LongElementRule rule) {
  return std::visit(
      [&](const auto& values) -> UniaxialLaw {
        using Values = std::decay_t<decltype(values)>;
        if constexpr (std::is_same_v<Values, ElasticLawParameters>) {
          return UniaxialLaw(LinearElasticLaw(values.youngs_modulus));
        } else if constexpr (std::is_same_v<Values, material::SteelParameters>) {
          return UniaxialLaw(material::SteelUniaxial(values, characteristic_length, rule));
        } else {
          return UniaxialLaw(material::MortarUniaxial(values, characteristic_length, rule));
        }
      },
      parameters);
}

} // namespace brb::element
