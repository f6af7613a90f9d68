// SolidInteraction: a force between nodes of a solid model that is not an element's, such as
// the penalty contact with Coulomb friction between the core and the casing
// (BRB_SOURCE_FACTS section 4). The explicit solver adds it to the elements' internal forces
// at every step; it follows the same trial / commit contract as the material laws, so a
// failed step leaves its committed state (stick anchors, slips) untouched.
//
// Conventions: full DOF vectors, node-major (3 n + i, i = x, y, z), as SolidModel; the force
// is added in the internal-force sense (it enters the equation of motion as M a = f_ext -
// f_int - f_interaction), so a contact spring pushing node a away from a surface adds
// -push to a's entries.
#pragma once

#include <Eigen/Core>

#include <string>

namespace brb::solid {

class SolidInteraction {
public:
  virtual ~SolidInteraction() = default;

  /// Trial response at displacement `displacement` (mm) of the nodes whose reference
  /// coordinates the interaction was built with: adds its forces (N) to `force`. Returns
  /// false, with `reason`, when the state is not admissible (e.g. a penetration deeper than
  /// the interaction can resolve, or a non-finite force).
  virtual bool add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                         std::string& reason) = 0;
  /// Accepts the last add_force() (stick anchors, slips, dissipated energy).
  virtual void commit() = 0;

  /// Energy stored in the penalty springs of the committed state (N mm).
  virtual double stored_energy() const = 0;
  /// Energy dissipated by friction up to the committed state (N mm).
  virtual double dissipated_energy() const = 0;

  /// Upper bound of the squared circular frequency (rad^2/s^2) the interaction's springs add
  /// to any DOF, given the lumped mass per DOF (tonne): for a spring k between masses m1 and
  /// m2, k (1/m1 + 1/m2). The explicit solver adds it to the element bound's w^2 when it
  /// chooses the stable step, so a stiff penalty cannot make the integration unstable.
  virtual double frequency_bound_squared(const Eigen::VectorXd& lumped_mass) const = 0;
};

} // namespace brb::solid
