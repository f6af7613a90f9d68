// Explicit central differences for a SolidModel or a SolidBody: lumped (row-sum) mass,
// Boost.Odeint's velocity Verlet (the central-difference method in velocity form, as in
// analysis::ExplicitAnalysis; Belytschko, Liu, Moran, Box 6.1), on the free DOFs, with
// prescribed displacements that follow a history in time (smooth_ramp for quasi-static
// loading) and external nodal forces that follow another.
//
// Stable step: the model's stable_time_step(safety): safety x min over elements of 2 / w_max,
// w_max from the Flanagan-Belytschko element bound (hex8.hpp); the assembled mesh's highest
// frequency is not above the largest element one (Irons' element eigenvalue theorem), so the
// bound holds for the mesh. A SolidBody adds its interactions' springs (solid_body.hpp).
//
// Energy, per step: kinetic 1/2 v^T M v (free DOFs), internal work of the centre stresses
// (trapezoidal in the strain), stored hourglass energy, and for a SolidBody the energy stored
// in its interactions' springs and dissipated by their friction; external work trapezoidal in
// the displacements: the reactions (internal plus interaction forces) of the prescribed DOFs
// times their increments plus the external forces times the free DOFs' increments. The
// balance W_ext = KE + IE + HG + interaction + friction + damping holds up to the
// central-difference error O(dt^2).
//
// Mass-proportional damping (optional, SolidExplicitSettings::mass_damping alpha, 1/s, on the
// directions chosen: `brb solid --lateral-damping` damps y and z only, as LS-DYNA's
// *DAMPING_GLOBAL with its per-direction factors). The force c_i v_i, c_i = alpha m_i, is
// diagonal, so it is taken at v_{n+1} = v_{n+1/2} + dt/2 a_{n+1} and solved per equation,
//   (m_i + c_i dt/2) a_i = f_i - c_i v_{n+1/2,i},   v_{n+1/2} = v_n + dt/2 a_n,
// as analysis::ExplicitAnalysis does (Belytschko, Liu, Moran, Box 6.1): second-order, and the
// stable step 2 / w_max is not lowered. A mode of frequency w gets the damping ratio
// alpha / (2 w): the low lateral modes of a buckling brace the most, the axial waves of the
// loading nothing. Its work, trapezoidal (1/2 (c v_n + c v_{n+1}) . dq), is the energy
// `damping`. It regularises a dynamic snap (global buckling, pieces of split mortar that nothing
// holds any more) toward the quasi-static path, at the price of a viscous force alpha m v on
// the slow lateral motions of the loading: report the damping energy beside the result.
//
// The solver is a template on the model (SolidExplicitSolver<Model>, Model = SolidModel<Law>
// or SolidBody, instantiated for both); SolidExplicit<T> names it for a law (SolidModel<T>),
// a SolidModel<Law> or a SolidBody.
#pragma once

#include "brb/solid/solid_body.hpp"
#include "brb/solid/solid_model.hpp"
#include "brb/solid/solid_static.hpp"

#include <Eigen/Core>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace brb::solid {

/// 0 at t <= 0, (1 - cos(pi t / T)) / 2 up to T, 1 after: a displacement history with zero
/// velocity at both ends (no velocity jump, so no stress wave from the start of the loading).
double smooth_ramp(double time, double duration);

struct SolidExplicitSettings {
  double stable_step_safety = 0.9; ///< on the element bound 2 / w_max
  double time_step = 0.0;          ///< s; 0: the stable step (a larger one is refused)
  /// alpha of the mass-proportional damping C = alpha M (1/s, >= 0; 0: none; see the header).
  double mass_damping = 0.0;
  /// The directions (x, y, z) of the nodes' DOFs that the damping acts on (DOF 3 n + k is
  /// damped when damped_directions[k]); a pivoting face's angles are never damped.
  std::array<bool, 3> damped_directions{true, true, true};
};

/// A face that stays plane and may rotate freely about the two axes across x through its
/// mass centre (a rigid end plate on a spherical pin; `brb solid`'s pinned end faces). The x
/// DOFs of its nodes must be prescribed: they follow their prescribed values (the plate's
/// translation) plus theta_1 l_i1 + theta_2 l_i2, where the two angles are free DOFs of the
/// solver with the inertia J_k = sum_i m_i l_ik^2 of the nodes' x masses, and the lever arms
/// l_ik = r_i . e_k are the nodes' (y, z) offsets from the mass centre along the principal
/// axes e_k of that inertia (so the two angles do not couple through the mass, and the
/// plate's translation does not couple to them). Small rotations: the x displacements are
/// linear in the angles, the nodes' y and z stay free (or held by other prescribed DOFs).
struct PivotingFace {
  std::vector<int> nodes;
  Eigen::Matrix2Xd positions; ///< (y, z) of each node in the reference configuration (mm)
};

/// Displacements u_d(t) = values_d x history(t) of the prescribed DOFs (history(0) = 0 for a
/// start at rest), plus the rotations of the pivoting faces, and external forces
/// f(t) = load x load_history(t).
struct SolidLoading {
  PrescribedDisplacements prescribed;
  std::vector<PivotingFace> pivoting_faces;
  std::function<double(double)> history = [](double) { return 1.0; };
  Eigen::VectorXd load; ///< full DOF vector (N); empty: none
  std::function<double(double)> load_history = [](double) { return 1.0; };
};

struct SolidExplicitEnergy {
  double kinetic = 0.0;
  double internal = 0.0;    ///< work of the centre stresses
  double hourglass = 0.0;   ///< stored hourglass energy
  double interaction = 0.0; ///< energy stored in the interactions' springs (SolidBody)
  double friction = 0.0;    ///< energy dissipated by the interactions' friction (SolidBody)
  double damping = 0.0;     ///< energy dissipated by the mass-proportional damping
  double external = 0.0;    ///< work of the reactions and external forces
  /// The energy the model holds or has dissipated: KE + IE + HG + interaction + friction +
  /// damping.
  double accounted() const {
    return kinetic + internal + hourglass + interaction + friction + damping;
  }
  /// |W_ext - accounted| / max(W_ext, accounted, 1e-30)
  double relative_error() const;
};

template <class Model> class SolidExplicitSolver {
public:
  /// Starts at rest from the model's committed state (zero displacement). Throws
  /// std::invalid_argument for a time step above the stable one.
  SolidExplicitSolver(Model& model, SolidLoading loading, SolidExplicitSettings settings = {});

  /// Starts from displacement u0 and velocity v0 (full DOF vectors; the prescribed DOFs take
  /// their history's values). The energies start from the state's stored energy as work done
  /// (the damping energy from 0).
  void set_initial_state(const Eigen::VectorXd& displacement, const Eigen::VectorXd& velocity);

  /// Steps up to `time` (s), the last step shortened to land on it. False, with `failure`,
  /// when an element inverts or the state becomes non-finite (the committed state stays).
  bool run_to(double time, std::string& failure);

  double time() const { return time_; }
  double time_step() const { return time_step_; }
  double stable_time_step() const { return stable_step_; }
  long steps() const { return steps_; }
  const Eigen::VectorXd& displacement() const { return displacement_; }
  const Eigen::VectorXd& velocity() const { return velocity_; }
  /// Internal forces of the committed state (reactions on the prescribed DOFs).
  const Eigen::VectorXd& internal_force() const { return force_; }
  /// The pivoting faces' angles about their principal axes (rad; two per face, in order).
  const Eigen::VectorXd& pivot_angles() const { return pivot_angle_; }
  const SolidExplicitEnergy& energy() const { return energy_; }

private:
  bool advance(double dt, std::string& failure);
  void take_model_energies();
  void fill_prescribed(double t, Eigen::VectorXd& full) const;
  /// Accelerations of the state vector (free DOFs, then the pivots' angles) under the internal
  /// forces `force` (full DOFs) and the loads at time t.
  void accelerations(const Eigen::VectorXd& force, double t, Eigen::VectorXd& acceleration) const;
  /// Adds the pivoting faces' rotations `angles` to the x DOFs of their nodes in `full`.
  void add_pivot_rotations(const Eigen::VectorXd& angles, Eigen::VectorXd& full) const;

  /// A pivoting face as the solver uses it: its nodes' x DOFs and their lever arms about
  /// the two principal axes.
  struct Pivot {
    std::vector<int> dofs;
    std::array<std::vector<double>, 2> lever;
  };

  Model& model_;
  SolidLoading loading_;
  std::vector<int> free_dofs_;
  std::vector<Pivot> pivots_;
  Eigen::VectorXd mass_;    // free DOFs, then the pivots' inertias (two per face)
  Eigen::VectorXd damping_; // c_i = alpha m_i of the damped free DOFs, else 0 (as mass_);
                            // empty without damping
  double stable_step_ = 0.0;
  double time_step_ = 0.0;
  double time_ = 0.0;
  long steps_ = 0;
  Eigen::VectorXd displacement_, velocity_, force_; // full DOFs
  Eigen::VectorXd acceleration_;                    // free DOFs, then the pivots' angles
  Eigen::VectorXd pivot_angle_, pivot_rate_;        // rad, rad/s: two per pivoting face
  SolidExplicitEnergy energy_;
};

namespace detail {
/// The model a SolidExplicit<T> integrates: SolidModel<T> for a law T, else T itself.
template <class T> struct ExplicitModelOf { using type = SolidModel<T>; };
template <class Law> struct ExplicitModelOf<SolidModel<Law>> { using type = SolidModel<Law>; };
template <> struct ExplicitModelOf<SolidBody> { using type = SolidBody; };
} // namespace detail

/// SolidExplicit<Law> (a SolidModel<Law>), SolidExplicit<SolidModel<Law>>,
/// SolidExplicit<SolidBody>.
template <class T>
using SolidExplicit = SolidExplicitSolver<typename detail::ExplicitModelOf<T>::type>;

} // namespace brb::solid
