// What a brace did beyond its force (issue "BRB element" outputs), followed over its
// converged states. One tracker serves the cyclic test (`brb cyclic`, the brace as the whole
// model) and the condensed BRBElement (the brace solved inside an element).
#pragma once

#include "brb/model/brace_model.hpp"

#include <functional>
#include <vector>

namespace brb::analysis {

/// Flags follow stated rules (constants in brace_indicators.cpp):
///  - core fracture: some core fiber's damage reached 0.9;
///  - casing failure: the mortar under some station crushed (or, with casing/splitting, split)
///    through: its residual strength fell to 0.1 of its onset stress (in a mortar-only casing
///    also a fill fiber's). The residual strength exp(A (1 - r / r0)), not the damage d, since
///    only it is objective: the same crack opening gives a larger d in a shorter element (see
///    ExponentialSoftening::residual_strength). Residual 0.1 means d > 0.9 at any size, and
///    about 90 % of the fracture energy spent;
///  - global buckling: the casing (or, without casing, the core) bowed laterally by more than
///    L_y / 250 (its offset from the current chord of the brace's outer nodes, less the
///    clearance (gap) per direction for a casing, which may shift sideways by that much
///    without the brace bowing), and over a step that shortened the brace the bow grew by
///    more than the shortening while the brace stiffened by less than half its elastic
///    stiffness P_y / d_y (the shortening went into the bow: an elastic buckle, or a force
///    drop). A bow alone is not instability: a casing on gaps at pinned ends can swing
///    sideways at small load and then hold (the brace keeps its stiffness, the bow stops).
struct BraceIndicators {
  double max_steel_damage = 0.0;  ///< largest damage of a core fiber
  double max_mortar_damage = 0.0; ///< largest damage of a bearing face or mortar fill fiber
  /// Largest damage of the mortar under a station (the contact links' bearing faces and, with
  /// casing/splitting, the split walls beside the opening), which casing_failure flags. The fill
  /// fibers of the casing beams are left out: they crack in tension as soon as the casing bends
  /// (strain ft / E, about 1.3e-4), which in a steel tube is not a casing failure (in a mortar-only
  /// casing it is: the flag's rule).
  double max_bearing_damage = 0.0;
  /// Smallest residual strength of the mortar under a station, as a fraction of its onset
  /// stress (f_c for a bearing face, f_t for split walls): casing_failure when it falls to
  /// kCrushedResidualStrength. 1 while the mortar there has not passed its peak.
  double min_bearing_residual_strength = 1.0;
  /// Smallest residual strength of the casing's mortar fill fibers (1 without casing): the
  /// casing_failure rule of a mortar-only casing.
  double min_fill_residual_strength = 1.0;
  double max_core_lateral_displacement = 0.0;   ///< mm, core nodes from their initial place
  double max_casing_lateral_displacement = 0.0; ///< mm (0 without casing)
  /// Largest number of half-waves of the yielding core's lateral displacement (relative to
  /// the casing when there is one) while in compression: sign changes along the core + 1,
  /// over values above 10 % of the largest, in the direction where the core moved most.
  int max_buckling_half_waves = 0;
  /// Sum over the steps of |d(delta) - dF / K0| / dy, K0 = Py / dy: the cumulative inelastic
  /// deformation in multiples of the yield deformation (AISC 341 K3 uses it).
  double cumulative_inelastic_deformation = 0.0;
  /// Beams of the brace (core and casing) whose axial strain fell back to uniform over their
  /// points: the equal-force solve of a softening section had no solution (corot_beam_3d.hpp)
  int uniform_axial_strain_beams = 0;
  bool core_fracture = false;
  bool casing_failure = false;
  bool global_buckling = false;
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, BraceIndicators>
void state_fields(Archive& archive, Self& indicators) {
  archive(indicators.max_steel_damage, indicators.max_mortar_damage, indicators.max_bearing_damage,
          indicators.min_bearing_residual_strength, indicators.min_fill_residual_strength,
          indicators.max_core_lateral_displacement, indicators.max_casing_lateral_displacement,
          indicators.max_buckling_half_waves, indicators.cumulative_inelastic_deformation,
          indicators.uniform_axial_strain_beams, indicators.core_fracture,
          indicators.casing_failure, indicators.global_buckling);
}

/// Steel damage at which a core fiber counts as fractured (the core-fracture flag).
inline constexpr double kFractureDamage = 0.9;
/// Residual strength (fraction of the onset stress) at or below which the mortar under a
/// station counts as crushed or split through (the casing-failure flag).
inline constexpr double kCrushedResidualStrength = 0.1;
/// A lateral deflection beyond L_y / this (less the clearance) can flag global buckling.
inline constexpr double kGlobalBucklingRatio = 250.0;

/// The increment of the cumulative inelastic deformation (multiples of dy) over a step that
/// changed the brace's deformation by d_deformation (mm) and its force by d_force (N):
/// |d(delta) - dF / K0| / dy with K0 = Py / dy (BraceIndicators). One rule for the full
/// element (BraceIndicatorTracker) and the truss (the frame recorders).
double inelastic_deformation_increment(double d_deformation, double d_force, double yield_force,
                                       double yield_deformation);

/// Updates BraceIndicators with each converged state of a brace. Lateral motions are
/// measured in the brace's section axes (BraceHandles::axes).
class BraceIndicatorTracker {
public:
  /// Current position of a node of the brace's model (global, mm).
  using Positions = std::function<const element::Vector3&(int node)>;

  /// `brace` and `model`: the brace's handles and the model that holds them (its initial
  /// node coordinates are the reference); both must outlive the tracker's observe() calls.
  BraceIndicatorTracker(const model::BraceHandles& brace, const model::Model& model);

  /// Observes a converged state: node positions, the brace's deformation (mm) and axial
  /// force (N, tension positive).
  void observe(const Positions& position, double deformation, double force);

  const BraceIndicators& indicators() const { return indicators_; }

  /// Follows the same brace in a twin model (same nodes and elements) from now on.
  void rebind(const model::BraceHandles& brace, const model::Model& model) {
    brace_ = &brace;
    model_ = &model;
  }

  /// Largest lateral motion of a node of the brace (core and casing) in the state `position`.
  double max_lateral_displacement(const Positions& position) const;

  /// Checkpoints (io/state_archive.hpp): what the tracker carries from step to step.
  template <class Archive, class Self>
  requires io::state_of<Self, BraceIndicatorTracker>
  friend void state_fields(Archive& archive, Self& tracker) {
    archive(tracker.previous_deformation_, tracker.previous_force_, tracker.previous_bow_,
            tracker.indicators_);
  }

private:
  const model::BraceHandles* brace_;
  const model::Model* model_;
  std::vector<element::Vector3> initial_positions_; ///< of brace_->nodes
  double yielding_length_ = 0.0;
  double previous_deformation_ = 0.0;
  double previous_force_ = 0.0;
  double previous_bow_ = 0.0; ///< the global bow of the previous observed state (mm)
  BraceIndicators indicators_;
};

} // namespace brb::analysis
