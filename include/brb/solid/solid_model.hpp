// SolidModel: a mesh of one-point hexahedra (hex8.hpp) with one 3D law per element, its
// committed and trial material states, lumped masses and energies. The law is a template
// parameter so the element loop calls the law directly (no virtual call per integration
// point); the states and the reference geometry live in contiguous arrays, one entry per
// element. Instantiated for material::IsotropicElastic3D, material::SteelDamagePlasticity3D
// and material::MortarDamage3D.
//
// Degrees of freedom: the displacements of the nodes, node-major (3 n + i, i = x, y, z).
// Trial / commit as the laws: evaluate() changes only the trial states; commit() accepts
// them (a failed Newton iteration just evaluates again).
//
// Threads: evaluate() shares the elements among set_threads() threads in contiguous blocks;
// each element writes only its own slots (force, tangent, energies), and the nodal sums are
// then made in element order by one thread, so the results are bitwise the same for every
// thread count.
#pragma once

#include "brb/model/thread_team.hpp"
#include "brb/solid/hex8.hpp"
#include "brb/solid/hex_mesh.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <functional>
#include <string>
#include <vector>

namespace brb::solid {

/// Energies of a state (N mm).
struct SolidEnergy {
  double internal = 0.0; ///< work of the centre-point stresses, int S : dE dV (stored + dissipated)
  /// Hourglass energy: the stored energy of the elastic stiffness form; in the tangent form
  /// (HourglassControl), the work of the hourglass forces (stored and dissipated).
  double hourglass = 0.0;
  /// Energy stored in the springs of non-element interactions (SolidBody; 0 for one model).
  double interaction = 0.0;
  /// Energy dissipated by friction in those interactions (SolidBody; 0 for one model).
  double friction = 0.0;
};

/// How the hourglass stiffness of hex8.hpp follows the law.
/// - elastic (follow_tangent false): the stiffness form P_alpha = K_alpha q_alpha with the
///   elastic moduli, also when the law yields. The linear part of the strain inside an
///   element then stays elastic: at a plastic hinge only a few elements across, the
///   in-element bending is overstiff and its elastic energy is spurious.
/// - tangent: incremental hourglass stresses, each component (mode alpha, element axis m, in
///   which K_alpha is diagonal with moduli k) a spring that loads with s_e k and unloads with k:
///     dP = s_e k dq while P dq > 0 (|P| grows), dP = k dq otherwise,
///   where s_e is the element's ratio of its law's response to the elastic one over its last
///   committed step, s_e = clamp(dS : dE / (dE : C_el : dE), min_scale, 1): 1 while the
///   element is elastic or unloads, about E_t / E while it yields (H / (H + 3 G) in J2 shear),
///   min_scale where the law softens (cracked mortar), a floor of stiffness against spurious
///   modes. This is the idea of basing the hourglass stiffness on the material's current
///   tangent moduli (Belytschko, Liu & Moran, Nonlinear Finite Elements, sec. 8.7), made with
///   the step's secant so that any law (a hardening steel, a softening mortar) gives its
///   scalar. Unloading with k is what keeps it thermodynamically sound: with the stored energy
///   psi = P^2 / (2 k) of each spring, the dissipation is dW - dpsi = (1 - s) P dq >= 0 when
///   loading and 0 when unloading, so the hourglass work W = psi + D never falls below zero.
///   (A stiffness that followed s_e both ways would create energy: loaded at k, unloaded at
///   s k, the spring keeps pushing long after it passed its start.) The scale is the last
///   committed step's and the branch is chosen from the committed P, so Newton's tangent is
///   exact within a branch. The hourglass energy is then the hourglass forces' work, int P dq
///   (trapezoidal; exact for these piecewise linear springs).
struct HourglassControl {
  bool follow_tangent = false;
  double min_scale = 0.05; ///< floor of s_e, in (0, 1]
};

template <class Law> class SolidModel {
public:
  using State = typename Law::State;
  /// law_for(lc): the law of an element whose characteristic length is lc = V^(1/3) (mm): the
  /// one-point element's integration weight is its volume V, so a softening law dissipates
  /// Gf per unit area over a band one element wide. density: tonne / mm^3, > 0.
  /// Throws std::invalid_argument for an inverted element, a bad density or a hourglass
  /// floor outside (0, 1].
  SolidModel(HexMesh mesh, const std::function<Law(double)>& law_for, double density,
             HourglassControl hourglass = {});

  const HexMesh& mesh() const { return mesh_; }
  int node_count() const { return mesh_.node_count(); }
  int dof_count() const { return 3 * mesh_.node_count(); }
  int element_count() const { return mesh_.element_count(); }
  const std::vector<Hex8Reference>& references() const { return references_; }
  const std::vector<Law>& laws() const { return laws_; }

  /// Trial state at nodal displacements u: internal forces (dof_count) and, when `tangent`
  /// is not null, the consistent tangent d force / d u. Returns false, with `reason`, when an
  /// element inverts (det F <= 0) or a stress is not finite.
  bool evaluate(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                Eigen::SparseMatrix<double>* tangent, std::string& reason);
  /// The internal forces only (what the explicit solver needs; the same call as SolidBody's).
  bool evaluate(const Eigen::VectorXd& displacement, Eigen::VectorXd& force, std::string& reason) {
    return evaluate(displacement, force, nullptr, reason);
  }
  /// Accepts the last evaluate(): states, strains, stresses and the internal work.
  void commit();

  /// Threads of the element loop (>= 1; default 1). Throws std::invalid_argument below 1.
  void set_threads(int threads);
  int threads() const { return team_.threads(); }

  /// Second Piola-Kirchhoff stress and Green-Lagrange strain (Voigt) of each element, as of
  /// the last evaluate().
  const std::vector<material::Vector6>& trial_stress() const { return trial_stress_; }
  const std::vector<material::Vector6>& trial_strain() const { return trial_strain_; }
  const std::vector<material::Vector6>& stress() const { return committed_stress_; }
  const std::vector<State>& states() const { return committed_states_; }
  const std::vector<State>& trial_states() const { return trial_states_; }
  /// Energies of the committed state, and of the last evaluate().
  const SolidEnergy& energy() const { return committed_energy_; }
  const SolidEnergy& trial_energy() const { return trial_energy_; }

  const HourglassControl& hourglass_control() const { return hourglass_control_; }
  /// Each element's hourglass stiffness scale s_e for the next step (all 1 in the elastic
  /// form; HourglassControl).
  const std::vector<double>& hourglass_scales() const { return hourglass_scale_; }

  /// Lumped (row-sum) mass per DOF: rho V / 8 from each element to each of its nodes.
  Eigen::VectorXd lumped_mass() const;
  double density() const { return density_; }
  /// Stable central-difference step: safety x min over elements of 2 / w_max (hex8.hpp).
  double stable_time_step(double safety) const;
  /// The largest element bound w_max (rad/s) of hex8_max_frequency over the elements, with
  /// each element's own lumped mass rho V / 8 per node (what Irons' element eigenvalue theorem
  /// needs: the assembled mass is the sum of these shares, also where parts share a node).
  double max_frequency() const;

private:
  /// The element's trial response into its own slots; false when it inverts or its stress is
  /// not finite (recorded in element_jacobian_ / element_finite_).
  bool evaluate_element(std::size_t e, const Eigen::Matrix3Xd& displacement, bool with_tangent);

  HexMesh mesh_;
  model::ThreadTeam team_;
  double density_ = 0.0;
  std::vector<Law> laws_;
  std::vector<Hex8Reference> references_;
  HourglassControl hourglass_control_;
  std::vector<HourglassStiffness> hourglass_;
  std::vector<double> dilatational_modulus_; // lambda + 2 mu of each element's law
  std::vector<double> shear_modulus_;        // mu of each element's law
  // the tangent hourglass form's state: hourglass displacements (reference axes) and
  // stresses (element axes, where K_alpha is diagonal with the moduli k), and the scale
  std::vector<HourglassMatrix> hourglass_moduli_; // k(m, alpha) in the element's axes
  std::vector<HourglassMatrix> committed_hourglass_q_, trial_hourglass_q_;
  std::vector<HourglassMatrix> committed_hourglass_P_, trial_hourglass_P_;
  std::vector<double> hourglass_scale_;
  std::vector<State> committed_states_, trial_states_;
  std::vector<material::Vector6> committed_stress_, trial_stress_;
  std::vector<material::Vector6> committed_strain_, trial_strain_;
  SolidEnergy committed_energy_, trial_energy_;
  // per-element results of the last evaluate()
  std::vector<NodeMatrix> element_force_;
  std::vector<ElementMatrix> element_tangent_;
  std::vector<double> element_work_, element_hourglass_, element_jacobian_;
  std::vector<char> element_failed_;
};

} // namespace brb::solid
