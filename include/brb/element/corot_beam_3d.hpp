// CorotBeam3D: a co-rotational 3D beam (corotational_frame.hpp) around a local
// small-strain beam with sections at the integration points of a BeamIntegration rule.
//
// Local beam. Bending is displacement-based (cubic Hermite transverse displacements): at
// xi = x / L0 the curvatures are
//   kappa_y = [(6 xi - 4) theta_iy + (6 xi - 2) theta_jy] / L0, and likewise kappa_z,
// with the section convention eps = e0 + z kappa_y - y kappa_z. The axial strain is not
// interpolated: each integration point has its own e0_k, solved so that the axial force
// is the same at every point (exact axial equilibrium, no distributed axial load) under
// the compatibility condition sum_k w_k e0_k L0 = u_bar. This removes the axial-bending
// locking of a constant-strain displacement element when sections yield unevenly
// (a plastic hinge shifts the neutral axis and needs a varying e0). Torsion is elastic.
//
// Local forces [N, m_i, m_j] follow from virtual work: N conjugate to u_bar, and
//   m_{i,y} = sum_k w_k (6 xi_k - 4) M_{y,k},  m_{j,y} = sum_k w_k (6 xi_k - 2) M_{y,k},
// (likewise z), the torques -/+ G J (theta_jx - theta_ix) / L0.
//
// Starting point of the equal-force solve: the strains of the last trial the solve converged
// at, moved by its tangent to this trial's elongation and curvatures (a first-order
// predictor; the committed strains shifted to the new mean after a revert or a failed
// solve). Between the iterates of a global Newton solve the points move little, so most
// solves converge at their first sweep of the points. Measured (session 31, idle machine, two
// runs each): Girona D3's cyclic test 28.3 -> 21.6 s, CB225's record 30.9 -> 25.0 s. Only
// for sections whose axial force grows with the axial strain at every curvature (steel fibers
// without a damage law: section_hardens), where the equal-force state is
// unique and the solution is the same to the solve's tolerance (1e-10 of the force) from any
// start. A section that can soften (a mortar fill cracking in tension, a damaging steel) may
// have several, and a start from elsewhere may find another: measured with the predictor on
// the casing beams too, the peaks of Girona D3's restrained core at three step sizes spread
// over 0.057 % (test RestrainedCore.PathThroughTheModeJumpsDoesNotHangOnTheStepSize: 0.05 %);
// so those beams start from the committed strains, as every beam with
// set_axial_predictor(false).
//
// Fallback: where a section softens (a mortar casing beam cracking through in bending, a
// crushed fill), the point whose force has passed its peak cannot carry the axial force the
// others ask for, and the equal-force solve has no solution (measured: the small BRB of
// BRB_SOURCE_FACTS section 6 driven to -43 dy, whose mortar casing cracks through next to the
// stopper; the run stopped there). The beam then takes a uniform axial strain e0_k = u_bar /
// L0 at every point (the displacement-based beam, with N = sum_k w_k N_k by virtual work) and
// keeps it: the form is part of its history, committed with the sections and reverted with
// them, so a failed step that is cut and retried starts from the equilibrated form. It is
// kept within a trial too: a beam whose form changed from one Newton iterate to the next
// (the equal-force solve failing at some iterates only) gave the pseudo-transient
// continuation no rest at the small BRB's crack-through (measured: the run stopped there
// again). The price: a far Newton iterate that needed the fallback and then converged keeps
// the beam uniform (measured: four core beams of UCSD G1, its compression yield force
// 2144.6 kN against 2139.3 kN before the fallback). Since the predicted start (session 31)
// the equal-force solve converges at G1's far iterates and none of its beams switches
// (2170.2 kN).
#pragma once

#include "brb/element/beam_integration.hpp"
#include "brb/element/corotational_frame.hpp"
#include "brb/element/element.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/section/fiber_section.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace brb::element {

/// How a local beam's axial strain varies between its integration points.
enum class AxialStrainField {
  equilibrated, ///< each point its own e0_k, one axial force at every point (the default)
  uniform,      ///< e0_k = u_bar / L0 at every point: the fallback of a softening section
};

/// Whether a section's axial force can only grow with its axial strain, whatever its
/// curvatures: fibers of steel without a damage law (every fiber's tangent is E or a
/// hardening modulus >= 0). Any other section may soften.
inline bool section_hardens(const section::FiberSection<material::SteelUniaxial>& section) {
  return !section.law().softening().has_value();
}
template <class Section> bool section_hardens(const Section&) {
  return false;
}

/// The local beam with constant axial force (after the fallback: uniform axial strain); owns
/// its sections (one per integration point).
template <class Section> class LocalBeam {
public:
  LocalBeam(double length, BeamIntegration integration, std::vector<Section> sections)
      : length_(length), integration_(std::move(integration)), sections_(std::move(sections)),
        axial_strain_(integration_.weights.size(), 0.0), committed_axial_strain_(axial_strain_) {
    for (const Section& section : sections_)
      sections_harden_ = sections_harden_ && section_hardens(section);
    predictor_.enabled = sections_harden_;
  }

  /// Local forces and tangent for local deformations d_l = [u_bar, theta_i, theta_j].
  /// Returns false only if a section's forces are not finite: where the equal-force axial
  /// solve fails, the beam falls back to a uniform axial strain (see the file comment).
  bool evaluate(const LocalVector& deformation, LocalVector& force, LocalMatrix& tangent,
                std::string& failure) {
    const std::size_t points = sections_.size();
    const double elongation = deformation[0];
    std::array<Eigen::Vector2d, kMaxPoints> curvature;
    for (std::size_t k = 0; k < points; ++k)
      curvature[k] = curvature_at(k, deformation);

    double axial_force = 0.0;
    axial_sweeps_ = 0;
    switch_work_ = committed_switch_work_;
    if (axial_field_ == AxialStrainField::equilibrated &&
        solve_equilibrated_axial_strains(elongation, curvature, axial_force)) {
      assemble_equilibrated(axial_force, force, tangent);
    } else {
      axial_field_ = AxialStrainField::uniform;
      for (std::size_t k = 0; k < points; ++k) {
        if (!evaluate_point(k, elongation / length_, curvature[k]) &&
            !section_response_[k].force.allFinite()) {
          failure = "local beam: non-finite section forces at a uniform axial strain";
          return false;
        }
      }
      if (committed_axial_field_ == AxialStrainField::equilibrated)
        switch_work_ += work_taken_at_switch();
      assemble_uniform(force, tangent);
      if (!tangent.allFinite()) {
        failure = "local beam: non-finite section tangent at a uniform axial strain";
        return false;
      }
    }

    const double torsion = torsional_stiffness() / length_;
    const double twist = deformation[4] - deformation[1];
    force[1] = -torsion * twist;
    force[4] = torsion * twist;
    tangent(1, 1) = tangent(4, 4) = torsion;
    tangent(1, 4) = tangent(4, 1) = -torsion;
    twist_ = twist;
    return true;
  }

  void commit() {
    for (auto& section : sections_)
      section.commit();
    committed_axial_strain_ = axial_strain_;
    committed_axial_field_ = axial_field_;
    committed_switch_work_ = switch_work_;
  }
  /// Splits every committed section along its mid-planes to the fractions (phi_y, phi_z)
  /// (FiberSection::split_halves: the fibers keep their strains and stresses, so the committed
  /// axial strains stay equilibrated; the moments drop). Between commits only.
  void split_sections(const std::array<double, 2>& fractions) requires requires(Section& section) {
    section.split_halves(fractions);
  }
  {
    for (auto& section : sections_)
      section.split_halves(fractions);
    revert_to_committed();
  }

  void revert_to_committed() {
    for (auto& section : sections_)
      section.revert_to_committed();
    axial_strain_ = committed_axial_strain_;
    predictor_.valid = false;
    axial_field_ = committed_axial_field_;
    switch_work_ = committed_switch_work_;
  }

  /// Checkpoints (io/state_archive.hpp): the committed state and the last evaluation's
  /// section responses, which the energies and outputs read; a reader follows with
  /// revert_to_committed().
  template <class Archive, class Self>
  requires io::state_of<Self, LocalBeam>
  friend void state_fields(Archive& archive, Self& beam) {
    archive(beam.sections_, beam.committed_axial_strain_, beam.committed_axial_field_,
            beam.committed_switch_work_, beam.section_response_, beam.axial_force_at_,
            beam.axial_stiffness_at_, beam.twist_);
  }

  ElementEnergy energy() const {
    ElementEnergy energy;
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      const double length = integration_.weights[k] * length_;
      const double stored = sections_[k].stored_energy();
      const double dissipated = sections_[k].dissipated_energy();
      energy.stored += length * stored;
      energy.dissipated += length * dissipated;
      // the laws' time discretisation (ElementEnergy::integration_misfit)
      energy.integration_misfit += length * (sections_[k].stress_work() - stored - dissipated);
    }
    // the points' work at the switch to a uniform axial strain that the end forces did not do
    energy.integration_misfit -= switch_work_;
    energy.stored += 0.5 * torsional_stiffness() / length_ * twist_ * twist_;
    return energy;
  }

  const std::vector<Section>& sections() const { return sections_; }
  const BeamIntegration& integration() const { return integration_; }
  double length() const { return length_; }
  /// Axial strain e0 at each integration point (trial).
  const std::vector<double>& axial_strains() const { return axial_strain_; }
  /// How the axial strain varies between the points (trial): `uniform` once the equal-force
  /// solve has failed (the fallback of a softening section).
  AxialStrainField axial_strain_field() const { return axial_field_; }
  /// The same, at the committed state.
  AxialStrainField committed_axial_strain_field() const { return committed_axial_field_; }
  /// Whether the equal-force solve starts from the last converged trial moved by its tangent
  /// (the default where every section hardens: section_hardens) or from the committed strains
  /// (see the file comment); a beam with a section that may soften keeps the committed start.
  void set_axial_predictor(bool enabled) {
    predictor_.enabled = enabled && sections_harden_;
    predictor_.valid = false;
  }
  /// Whether the predictor is in use (set_axial_predictor).
  bool axial_predictor() const { return predictor_.enabled; }
  /// Newton sweeps of the points (each evaluates every section) of the last evaluate()'s
  /// equal-force solve; the bracketed solve and the uniform fallback are not counted.
  int axial_sweeps() const { return axial_sweeps_; }

  static constexpr std::size_t kMaxPoints = 6;

private:
  static constexpr int kNewtonAxialIterations = 12;
  /// The bending DOF (theta_iy, theta_iz, theta_jy, theta_jz) in the local order
  /// [u, theta_ix, theta_iy, theta_iz, theta_jx, theta_jy, theta_jz].
  static constexpr std::array<int, 4> kBendingDofs{2, 3, 5, 6};
  static constexpr int kBracketIterations = 200;

  /// The point strains e0_k with one axial force at every point and sum_k w_k e0_k = u_bar /
  /// L0; false when there is none (a softening point past its peak) or it is not found.
  bool solve_equilibrated_axial_strains(double elongation,
                                        const std::array<Eigen::Vector2d, kMaxPoints>& curvature,
                                        double& axial_force) {
    if (predictor_.enabled && predictor_.valid)
      start_from_last_trial(elongation, curvature);
    else
      start_from_committed(elongation);
    predictor_.valid = false;
    // Newton's method on the strains e0_k with N from the linearised compatibility. Its
    // iterates can cycle where fibers cross between elastic and plastic branches (measured on
    // UCSD G1 at 2 dy: a period-4 cycle of iterates swinging between +-5e6 N, against a
    // force of 2e6 N); after kNewtonAxialIterations the bracketed solve takes over.
    for (int iteration = 0; iteration < kNewtonAxialIterations; ++iteration) {
      if (!evaluate_points(curvature)) {
        // An iterate left the laws' domain: a point whose fibers are all near their saturated
        // stress has an axial stiffness near zero, and (N - N_k) / a_k throws its strain far
        // away (measured: CB225's core at its Chaboche saturation, 1.75 % shortening, stopped
        // the whole run). The bracketed solve keeps every strain inside a bracket.
        break;
      }
      if (equilibrium_reached(elongation, axial_force)) {
        predictor_.valid = true;
        predictor_.elongation = elongation;
        predictor_.curvature = curvature;
        return true;
      }
      for (std::size_t k = 0; k < sections_.size(); ++k)
        axial_strain_[k] += (axial_force - axial_force_at_[k]) / axial_stiffness_at_[k];
    }
    start_from_committed(elongation);
    return solve_axial_in_brackets(elongation, curvature, axial_force);
  }

  /// Forces and the statically condensed tangent of the equilibrated beam (e0_k eliminated):
  ///   dN = [du/L0 + sum w_k c_k . G_k dtheta / a_k] / F,  F = sum w_k / a_k,
  ///   dm = sum w_k G_k^T [c_k de0_k + K_bb,k G_k dtheta] (times L0 / L0 = 1).
  void assemble_equilibrated(double axial_force, LocalVector& force, LocalMatrix& tangent) const {
    double flexibility = 0.0;
    Eigen::Matrix<double, 4, 1> coupling = Eigen::Matrix<double, 4, 1>::Zero(); // h
    Eigen::Matrix4d bending = Eigen::Matrix4d::Zero();
    Eigen::Matrix<double, 4, 1> end_moments = Eigen::Matrix<double, 4, 1>::Zero();
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      const section::SectionResponse& response = section_response_[k];
      const double a = response.tangent(0, 0);
      const Eigen::Vector2d c = response.tangent.block<2, 1>(1, 0);
      const Eigen::Matrix2d kbb = response.tangent.block<2, 2>(1, 1);
      const Eigen::Matrix<double, 2, 4> g = curvature_matrix(k);
      const double w = integration_.weights[k];
      flexibility += w / a;
      coupling += w * g.transpose() * c / a;
      bending += w * length_ * g.transpose() * (kbb - c * c.transpose() / a) * g;
      end_moments += w * length_ * g.transpose() * response.force.tail<2>();
    }
    bending += length_ * coupling * coupling.transpose() / flexibility;
    const Eigen::Matrix<double, 4, 1> axial_coupling = coupling / flexibility;
    write_local_response(axial_force, 1.0 / (length_ * flexibility), axial_coupling.transpose(),
                         axial_coupling, bending, end_moments, force, tangent);
  }

  /// Writes the beam's local response into the local DOF order (axial, then the four end
  /// rotations kBendingDofs): N and the end moments, and the tangent's axial entry, its
  /// axial-bending row and bending-axial column, and the bending block. Both forms of the
  /// beam (equilibrated, uniform) share it.
  static void write_local_response(double axial_force, double axial_stiffness,
                                   const Eigen::Matrix<double, 1, 4>& axial_bending,
                                   const Eigen::Matrix<double, 4, 1>& bending_axial,
                                   const Eigen::Matrix4d& bending,
                                   const Eigen::Matrix<double, 4, 1>& end_moments,
                                   LocalVector& force, LocalMatrix& tangent) {
    force.setZero();
    tangent.setZero();
    force[0] = axial_force;
    tangent(0, 0) = axial_stiffness;
    for (int r = 0; r < 4; ++r) {
      force[kBendingDofs[r]] = end_moments[r];
      tangent(0, kBendingDofs[r]) = axial_bending[r];
      tangent(kBendingDofs[r], 0) = bending_axial[r];
      for (int c = 0; c < 4; ++c)
        tangent(kBendingDofs[r], kBendingDofs[c]) = bending(r, c);
    }
  }

  /// The committed axial strains' weighted mean, sum_k w_k e0_k,c (= u_c / L0).
  double committed_mean_strain() const {
    double mean = 0.0;
    for (std::size_t k = 0; k < sections_.size(); ++k)
      mean += integration_.weights[k] * committed_axial_strain_[k];
    return mean;
  }

  /// The trapezoidal work the points take over the step that switches the beam from its
  /// committed equilibrated strains e0_k,c (one force N_c) to the uniform trial strain u / L0,
  /// beyond the work of the end forces, 0.5 (N_c + N) du (N mm). The bending work agrees in
  /// both forms (m = sum w_k L0 G_k^T M_k), and so does N_c's; what is left is
  ///   0.5 sum_k w_k L0 N_k (u_c / L0 - e0_k,c),  u_c / L0 = sum_k w_k e0_k,c,
  /// the trial forces N_k on the committed strains' spread about their mean. The energy
  /// balance books it with the laws' integration misfit (energy()), so that a switch is no
  /// error of the solution.
  double work_taken_at_switch() const {
    const double committed_mean = committed_mean_strain();
    double work = 0.0;
    for (std::size_t k = 0; k < sections_.size(); ++k)
      work += integration_.weights[k] * section_response_[k].force[0] *
              (committed_mean - committed_axial_strain_[k]);
    return 0.5 * length_ * work;
  }

  /// Forces and tangent of the displacement-based beam (e0_k = u_bar / L0 at every point), by
  /// virtual work: N = sum w_k N_k, m = sum w_k L0 G_k^T M_k, and their derivatives
  ///   dN = sum w_k [a_k du / L0 + (dN/dkappa)_k G_k dtheta],
  ///   dm = sum w_k G_k^T [(dM/de0)_k du + L0 K_bb,k G_k dtheta].
  void assemble_uniform(LocalVector& force, LocalMatrix& tangent) const {
    double axial_force = 0.0;
    double axial_stiffness = 0.0;
    Eigen::Matrix<double, 1, 4> axial_bending = Eigen::Matrix<double, 1, 4>::Zero();
    Eigen::Matrix<double, 4, 1> bending_axial = Eigen::Matrix<double, 4, 1>::Zero();
    Eigen::Matrix4d bending = Eigen::Matrix4d::Zero();
    Eigen::Matrix<double, 4, 1> end_moments = Eigen::Matrix<double, 4, 1>::Zero();
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      const section::SectionResponse& response = section_response_[k];
      const Eigen::Matrix<double, 2, 4> g = curvature_matrix(k);
      const double w = integration_.weights[k];
      axial_force += w * response.force[0];
      axial_stiffness += w * response.tangent(0, 0) / length_;
      axial_bending += w * response.tangent.block<1, 2>(0, 1) * g;
      bending_axial += w * g.transpose() * response.tangent.block<2, 1>(1, 0);
      bending += w * length_ * g.transpose() * response.tangent.block<2, 2>(1, 1) * g;
      end_moments += w * length_ * g.transpose() * response.force.tail<2>();
    }
    write_local_response(axial_force, axial_stiffness, axial_bending, bending_axial, bending,
                         end_moments, force, tangent);
  }

  /// The starting axial strains from the last converged trial (its strains e0_k, points'
  /// tangents and deformation): its linearisation a_k de0_k + b_k . dkappa_k = dN (a_k =
  /// dN/de0, b_k = dN/dkappa at point k) with the compatibility sum_k w_k de0_k = du / L0
  /// gives dN = (du / L0 + sum_k w_k b_k . dkappa_k / a_k) / sum_k w_k / a_k. Then shifted so
  /// that the compatibility holds to round-off. Without a positive axial stiffness at every
  /// point, the last trial's strains shifted to the new mean.
  void start_from_last_trial(double elongation,
                             const std::array<Eigen::Vector2d, kMaxPoints>& curvature) {
    const std::size_t points = sections_.size();
    std::array<double, kMaxPoints> coupled_force{}; // b_k . dkappa_k
    double flexibility = 0.0, coupled_strain = 0.0;
    bool linearisable = true;
    for (std::size_t k = 0; k < points; ++k) {
      const section::SectionResponse& response = section_response_[k];
      const double a = response.tangent(0, 0);
      coupled_force[k] =
          response.tangent.block<1, 2>(0, 1).dot(curvature[k] - predictor_.curvature[k]);
      if (!(a > 0.0 && std::isfinite(a) && std::isfinite(coupled_force[k]))) {
        linearisable = false;
        break;
      }
      flexibility += integration_.weights[k] / a;
      coupled_strain += integration_.weights[k] * coupled_force[k] / a;
    }
    if (linearisable) {
      const double force_change =
          ((elongation - predictor_.elongation) / length_ + coupled_strain) / flexibility;
      for (std::size_t k = 0; k < points; ++k)
        axial_strain_[k] += (force_change - coupled_force[k]) / section_response_[k].tangent(0, 0);
    }
    double mean = 0.0;
    for (std::size_t k = 0; k < points; ++k)
      mean += integration_.weights[k] * axial_strain_[k];
    for (std::size_t k = 0; k < points; ++k)
      axial_strain_[k] += elongation / length_ - mean;
  }

  /// The starting axial strains: the committed distribution shifted to the new mean strain
  /// u_bar / L0.
  void start_from_committed(double elongation) {
    const double committed_mean = committed_mean_strain();
    for (std::size_t k = 0; k < sections_.size(); ++k)
      axial_strain_[k] = committed_axial_strain_[k] + elongation / length_ - committed_mean;
  }

  /// Evaluates every section at its trial axial strain and the given curvatures; false if
  /// some point's axial stiffness is zero or its forces are not finite.
  bool evaluate_points(const std::array<Eigen::Vector2d, kMaxPoints>& curvature) {
    ++axial_sweeps_;
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      if (!evaluate_point(k, axial_strain_[k], curvature[k]))
        return false;
    }
    return true;
  }

  /// Evaluates section k at axial strain `strain`; false if its axial stiffness is zero or
  /// its forces are not finite.
  bool evaluate_point(std::size_t k, double strain, const Eigen::Vector2d& curvature) {
    axial_strain_[k] = strain;
    const auto& response =
        sections_[k].evaluate(section::SectionVector(strain, curvature[0], curvature[1]));
    section_response_[k] = response;
    axial_force_at_[k] = response.force[0];
    axial_stiffness_at_[k] = response.tangent(0, 0);
    return std::abs(axial_stiffness_at_[k]) > 0.0 && response.force.allFinite() &&
           std::isfinite(axial_stiffness_at_[k]);
  }

  /// Tolerance on the axial force mismatch between points: 1e-10 of the largest force plus
  /// the force of a strain of 1e-6 (axial_force_scale).
  double axial_tolerance() const {
    double force_scale = 0.0;
    for (std::size_t k = 0; k < sections_.size(); ++k)
      force_scale = std::max(force_scale, std::abs(axial_force_at_[k]));
    return 1e-10 * (force_scale + axial_force_scale());
  }

  /// From the evaluated points: the N that satisfies the linearised compatibility,
  /// sum_k w_k (e0_k + (N - N_k) / a_k) = u_bar / L0, and whether every N_k is within
  /// tolerance of it.
  bool equilibrium_reached(double elongation, double& axial_force) const {
    double flexibility = 0.0, mismatch = 0.0;
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      flexibility += integration_.weights[k] / axial_stiffness_at_[k];
      mismatch += integration_.weights[k] *
                  (axial_force_at_[k] / axial_stiffness_at_[k] - axial_strain_[k]);
    }
    axial_force = (elongation / length_ + mismatch) / flexibility;
    double worst = 0.0;
    for (std::size_t k = 0; k < sections_.size(); ++k)
      worst = std::max(worst, std::abs(axial_force_at_[k] - axial_force));
    return worst <= axial_tolerance();
  }

  /// One step of Newton's method for a root of an increasing function, kept inside the
  /// bracket [below, above] (the arguments where it was found negative and positive):
  /// bisection when the Newton step leaves the bracket or the last step did not halve the
  /// residual; without a bracket on one side, a step of at least `reach` towards it, doubled
  /// each time.
  static double bracketed_step(double argument, double value, double slope, double below,
                               double above, bool stalled, double& reach) {
    const bool bracketed = std::isfinite(below) && std::isfinite(above);
    if (bracketed && stalled)
      return 0.5 * (below + above);
    const double newton = argument - value / slope;
    if (slope > 0.0 && std::isfinite(newton) && newton > below && newton < above)
      return newton;
    if (bracketed)
      return 0.5 * (below + above);
    reach *= 2.0;
    return value < 0.0 ? argument + reach : argument - reach;
  }

  /// Axial strain of point k at which its axial force is `target`. The section's axial
  /// force increases with its axial strain while its fibers harden, so Newton's method in
  /// a shrinking bracket converges where the plain iteration can cycle between branches.
  bool match_point_force(std::size_t k, double target, const Eigen::Vector2d& curvature,
                         double tolerance) {
    double strain = axial_strain_[k];
    double below = -std::numeric_limits<double>::infinity();
    double above = std::numeric_limits<double>::infinity();
    double reach = 1e-6, last_residual = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < kBracketIterations; ++iteration) {
      if (!evaluate_point(k, strain, curvature))
        return false;
      const double residual = axial_force_at_[k] - target;
      if (std::abs(residual) <= tolerance)
        return true;
      (residual < 0.0 ? below : above) = strain;
      const bool stalled = std::abs(residual) > 0.5 * last_residual;
      last_residual = std::abs(residual);
      strain =
          bracketed_step(strain, residual, axial_stiffness_at_[k], below, above, stalled, reach);
      if (!(std::abs(strain) < 1.0)) // beyond 100 % strain: no such force
        return false;
    }
    return false;
  }

  /// The axial equilibrium as a root in N: each point's strain e0_k(N) matches N
  /// (match_point_force), and g(N) = sum_k w_k e0_k(N) - u_bar / L0, increasing with
  /// dg/dN = sum_k w_k / a_k, is zero. Newton's method in a shrinking bracket on N; the
  /// points are then in equilibrium to a quarter of the tolerance each way.
  bool solve_axial_in_brackets(double elongation,
                               const std::array<Eigen::Vector2d, kMaxPoints>& curvature,
                               double& axial_force) {
    if (!evaluate_points(curvature))
      return false;
    equilibrium_reached(elongation, axial_force); // the starting N
    double below = -std::numeric_limits<double>::infinity();
    double above = std::numeric_limits<double>::infinity();
    double reach = axial_force_scale(), last_mismatch = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < kBracketIterations; ++iteration) {
      const double tolerance = 0.25 * axial_tolerance();
      double compatibility = -elongation / length_, flexibility = 0.0;
      for (std::size_t k = 0; k < sections_.size(); ++k) {
        if (!match_point_force(k, axial_force, curvature[k], tolerance))
          return false;
        compatibility += integration_.weights[k] * axial_strain_[k];
        flexibility += integration_.weights[k] / axial_stiffness_at_[k];
      }
      const double mismatch = std::abs(compatibility) / flexibility; // as a force
      if (mismatch <= tolerance)
        return equilibrium_reached(elongation, axial_force);
      (compatibility < 0.0 ? below : above) = axial_force;
      const bool stalled = mismatch > 0.5 * last_mismatch;
      last_mismatch = mismatch;
      axial_force =
          bracketed_step(axial_force, compatibility, flexibility, below, above, stalled, reach);
    }
    return false;
  }

  double torsional_stiffness() const { return sections_.front().torsional_stiffness(); }
  /// A force scale for the axial tolerance: the axial stiffness times a strain of 1e-6.
  double axial_force_scale() const {
    double scale = 0.0;
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      scale = std::max(scale, std::abs(axial_stiffness_at_[k]) * 1e-6);
    }
    return scale;
  }

  /// d(kappa_y, kappa_z) / d(theta_iy, theta_iz, theta_jy, theta_jz) at point k.
  Eigen::Matrix<double, 2, 4> curvature_matrix(std::size_t k) const {
    const double xi = integration_.locations[k];
    const double near = (6.0 * xi - 4.0) / length_, far = (6.0 * xi - 2.0) / length_;
    Eigen::Matrix<double, 2, 4> g;
    g << near, 0.0, far, 0.0, 0.0, near, 0.0, far;
    return g;
  }

  Eigen::Vector2d curvature_at(std::size_t k, const LocalVector& deformation) const {
    const Eigen::Vector4d rotations(deformation[2], deformation[3], deformation[5], deformation[6]);
    return curvature_matrix(k) * rotations;
  }

  double length_;
  BeamIntegration integration_;
  std::vector<Section> sections_;
  std::vector<double> axial_strain_;
  std::vector<double> committed_axial_strain_;
  AxialStrainField axial_field_ = AxialStrainField::equilibrated;
  AxialStrainField committed_axial_field_ = AxialStrainField::equilibrated;
  double switch_work_ = 0.0; ///< N mm, work_taken_at_switch() once switched (trial)
  double committed_switch_work_ = 0.0;
  std::array<section::SectionResponse, kMaxPoints> section_response_{};
  std::array<double, kMaxPoints> axial_force_at_{};
  std::array<double, kMaxPoints> axial_stiffness_at_{};
  double twist_ = 0.0;
  /// The last trial the equal-force solve converged at (its strains are axial_strain_, its
  /// points' responses section_response_): the predictor's base while `valid`.
  struct AxialPredictor {
    bool enabled = true;
    bool valid = false;
    double elongation = 0.0;
    std::array<Eigen::Vector2d, kMaxPoints> curvature{};
  } predictor_;
  int axial_sweeps_ = 0;
  bool sections_harden_ = true;
};

/// The co-rotational beam element: two nodes, six DOF each.
template <class Section> class CorotBeam3D final : public Element {
public:
  /// `sections`: one per integration point, each built with the characteristic length
  /// w_k L0 of its point (see make_fiber_sections).
  CorotBeam3D(std::array<int, 2> nodes, const Vector3& position_i, const Vector3& position_j,
              const Vector3& vecxz, BeamIntegration integration, std::vector<Section> sections)
      : nodes_(nodes), frame_(position_i, position_j, vecxz),
        local_(frame_.initial_length(), std::move(integration), std::move(sections)) {}

  std::span<const int> nodes() const override { return nodes_; }

  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override {
    if (!frame_.update(configuration[0], configuration[1])) {
      failure = "co-rotational beam degenerated (zero length or director along the chord)";
      return false;
    }
    LocalVector local_force;
    LocalMatrix local_tangent;
    if (!local_.evaluate(frame_.local_deformation(), local_force, local_tangent, failure)) {
      return false;
    }
    GlobalVector global_force;
    GlobalMatrix global_tangent;
    frame_.global_response(local_force, local_tangent, global_force, global_tangent);
    force = global_force;
    tangent = global_tangent;
    local_force_ = local_force;
    return true;
  }

  void commit() override { local_.commit(); }
  void revert_to_committed() override { local_.revert_to_committed(); }
  /// LocalBeam::split_sections, between commits (a mortar casing's split: brace_model.cpp).
  void split_sections(const std::array<double, 2>& fractions) requires
      requires(LocalBeam<Section>& local) {
    local.split_sections(fractions);
  }
  { local_.split_sections(fractions); }
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  void save_state(io::StateWriter& out) const override { out(*this); }
  void load_state(io::StateReader& in) override {
    in(*this);
    local_.revert_to_committed();
  }
  /// Checkpoints: the frame, the local beam's committed state and the last local forces.
  template <class Archive, class Self>
  requires io::state_of<Self, CorotBeam3D>
  friend void state_fields(Archive& archive, Self& beam) {
    archive(beam.frame_, beam.local_, beam.local_force_);
  }
  ElementEnergy energy() const override { return local_.energy(); }

  const CorotationalFrame& frame() const { return frame_; }
  const LocalBeam<Section>& local_beam() const { return local_; }
  /// Local forces of the last evaluation: [N, m_i (3), m_j (3)] in the element frame.
  const LocalVector& local_force() const { return local_force_; }

private:
  std::array<int, 2> nodes_;
  CorotationalFrame frame_;
  LocalBeam<Section> local_;
  LocalVector local_force_ = LocalVector::Zero();
};

} // namespace brb::element
