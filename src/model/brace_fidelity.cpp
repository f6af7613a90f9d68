#include "brb/model/brace_fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace brb::model {

double casing_assembly_flexural_rigidity(const BraceSpec& spec) {
  if (!spec.casing)
    return 0.0;
  const CasingSpec& casing = *spec.casing;
  const section::FiberLayout core = spec.core_section.mesh();
  const section::FiberLayout fill = casing.fill_mesh(spec.core_section);
  double rigidity_y = spec.steel.youngs_modulus * core.second_moment_y() +
                      casing.mortar.youngs_modulus * fill.second_moment_y();
  double rigidity_z = spec.steel.youngs_modulus * core.second_moment_z() +
                      casing.mortar.youngs_modulus * fill.second_moment_z();
  if (casing.steel_tube) {
    const section::FiberLayout tube = casing.tube.mesh();
    rigidity_y += casing.tube_steel.youngs_modulus * tube.second_moment_y();
    rigidity_z += casing.tube_steel.youngs_modulus * tube.second_moment_z();
  }
  return std::min(rigidity_y, rigidity_z);
}

FidelityChoice choose_auto_fidelity(const BraceSpec& spec) {
  FidelityChoice choice;
  std::ostringstream reason;
  if (!spec.casing) {
    choice.reason = "full: bare core (it buckles; a truss cannot)";
    return choice;
  }
  const double yield_force = spec.steel.yield_stress * spec.core_section.mesh().total_area();
  choice.euler_ratio = std::pow(std::numbers::pi / spec.yielding_length, 2) *
                       casing_assembly_flexural_rigidity(spec) / yield_force;
  if (!spec.casing->steel_tube) {
    choice.reason = "full: mortar-only casing (it can crack and crush)";
    return choice;
  }
  if (choice.euler_ratio < kEulerMargin) {
    reason << "full: casing Euler load " << choice.euler_ratio << " P_y < " << kEulerMargin
           << " P_y (global buckling possible)";
    choice.reason = reason.str();
    return choice;
  }
  if (spec.casing->friction_coefficient > kTrussFrictionLimit) {
    reason << "full: friction " << spec.casing->friction_coefficient << " > " << kTrussFrictionLimit
           << " (compression overstrength)";
    choice.reason = reason.str();
    return choice;
  }
  reason << "truss: casing Euler load " << choice.euler_ratio << " P_y >= " << kEulerMargin
         << " P_y, friction " << spec.casing->friction_coefficient;
  choice.fidelity = Fidelity::truss;
  choice.reason = reason.str();
  return choice;
}

} // namespace brb::model
