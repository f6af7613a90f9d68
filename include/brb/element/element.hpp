// The element interface of the model layer. Elements see their nodes' current
// configuration (position and nodal triad) and return internal forces and a tangent with
// respect to nodal translations and spins (6 per node: du_x, du_y, du_z, dw_x, dw_y, dw_z).
// One virtual call per element per evaluation; the loops inside elements are not virtual.
#pragma once

#include "brb/io/state_archive.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>
#include <string>

namespace brb::element {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

/// Current configuration of a node: position x = X + u (mm) and nodal triad R (identity
/// in the initial configuration; rotated by spins, R <- exp([dw]x) R).
struct NodeConfiguration {
  Vector3 position = Vector3::Zero();
  Matrix3 rotation = Matrix3::Identity();
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, NodeConfiguration>
void state_fields(Archive& archive, Self& node) {
  archive(node.position, node.rotation);
}

/// Energies of an element's trial state (N mm).
struct ElementEnergy {
  double stored = 0.0;     ///< recoverable (free) energy
  double dissipated = 0.0; ///< plastic, damage and friction dissipation since the start
  /// The trapezoidal work of the stresses (forces) on the strains (displacements) at the
  /// integration points (contact faces, springs) since the start, minus stored and
  /// dissipated: the laws' time discretisation seen by the energy balance. The external
  /// work is summed with the trapezoidal rule; the laws book their exact energies of each
  /// backward-Euler update, and the two differ by O(step^2) where the stress-strain path
  /// has a kink inside a step (first yield, a contact closing). Elements whose laws are
  /// linear, or that do not track it, report 0 (their misfit, if any, stays in the balance).
  double integration_misfit = 0.0;
};

template <class Archive, class Self>
requires io::state_of<Self, ElementEnergy>
void state_fields(Archive& archive, Self& energy) {
  archive(energy.stored, energy.dissipated, energy.integration_misfit);
}

class Element {
public:
  virtual ~Element() = default;

  /// Model indices of the element's nodes.
  virtual std::span<const int> nodes() const = 0;

  /// Internal forces (N, N mm; 6 per node) and tangent at the trial configuration of the
  /// nodes (in the order of nodes()). Returns false with a reason when the element cannot
  /// evaluate that state (its local iteration failed); the solver then cuts the step and
  /// the element's committed state is untouched.
  virtual bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                        Eigen::MatrixXd& tangent, std::string& failure) = 0;

  virtual void commit() = 0;
  virtual void revert_to_committed() = 0;

  /// Energies of the last evaluated state.
  virtual ElementEnergy energy() const = 0;

  /// Path control of softening laws (NewtonSettings::max_correction_ratio): remember the
  /// last evaluated state as the last point of the followed path.
  virtual void mark_path_point() {}
  /// Whether the last evaluated state has gone past a softening law's peak since
  /// mark_path_point() without a point of the path near the peak: e.g. a bearing link whose
  /// mortar was intact at the last path point and is crushed now. A converged state like
  /// that is another equilibrium branch (the crushed one exists for any load) that Newton
  /// reached by overshooting, not the path: the path must pass the peak force, which steps
  /// short enough visit.
  virtual bool jumped_past_peak() const { return false; }

  /// Takes over the whole state (committed and trial) of `other`, an element of the same
  /// type built from the same data (a twin). A macro element that solves an internal model
  /// keeps a twin of it as its committed state (BRBElement), because the substeps of its
  /// internal solver commit the internal elements. Throws std::bad_cast for another type.
  virtual void copy_state_from(const Element& other) = 0;

  /// Checkpoints of a run (io/state_archive.hpp): writes the committed state, what the next
  /// step starts from, with the outputs of the last evaluation that reports read after a
  /// step (forces, flags). Called between steps, after a commit.
  virtual void save_state(io::StateWriter& out) const;
  /// Reads what save_state wrote into an element built from the same data, as its committed
  /// and trial state (io::CheckpointMismatch if the sizes differ). The defaults throw
  /// std::logic_error: an element that a checkpointed run meets must override both (every
  /// element of a brace model does; BRBElement, the frames' condensed brace, does not).
  virtual void load_state(io::StateReader& in);
};

/// copy_state_from for elements whose state is their value: a plain copy.
template <class Derived> void copy_element_value(Derived& target, const Element& source) {
  target = dynamic_cast<const Derived&>(source);
}

} // namespace brb::element
