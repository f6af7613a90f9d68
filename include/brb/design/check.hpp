// The AISC 341 check of a brace (README "brb check"): Delta_by from the brace model,
// Delta_bm from the design story drift (not less than 1 % of the story height) through the
// brace kinematics, the virtual qualification test at full fidelity with its criteria, the
// adjusted brace strengths, and (when asked) the drift capacity: the largest design story
// drift at which the brace still passes every criterion, by bisection.
#pragma once

#include "brb/design/check_spec.hpp"
#include "brb/design/qualification.hpp"

#include <optional>
#include <string>
#include <vector>

namespace brb::design {

/// From a design story drift to the brace's design deformation.
struct DriftDemand {
  double story_drift = 0.0;      ///< mm, as given (or Cd delta_xe / Ie)
  double minimum_drift = 0.0;    ///< mm, the edition's minimum ratio times the story height
  double used_story_drift = 0.0; ///< mm, the larger of the two
  double small_displacement_deformation = 0.0; ///< mm, Delta cos(theta)
  std::optional<double> frame_deformation;     ///< mm, with a frame model (exact geometry)
  double design_deformation = 0.0;             ///< Delta_bm, mm: the frame's when there is one
  std::string kinematics; ///< "small-displacement formula" or "frame geometry (...)"
};

/// The demand of story drift `story_drift` (mm) on the brace of `check`.
DriftDemand drift_demand(const CheckSpec& check, double story_drift);

/// The core's yield forces of a check (N).
struct YieldForces {
  double core_area = 0.0;   ///< Asc, mm^2
  double tested = 0.0;      ///< Pysc of the tested core: Asc Fysc,measured or Asc Ry Fysc
  double design = 0.0;      ///< Asc Fysc (specified when given, else measured)
  std::string tested_basis; ///< how `tested` was formed
};

YieldForces yield_forces(const CheckSpec& check, double core_area);

/// One trial of the drift-capacity search.
struct DriftTrial {
  double drift_ratio = 0.0;
  double design_deformation = 0.0; ///< mm
  bool passed = false;
  std::string failed; ///< failed criteria
};

struct DriftCapacity {
  /// The largest drift ratio found to pass (none: the brace fails at the minimum drift).
  std::optional<double> drift_ratio;
  /// Width of the final bracket (drift ratio): the capacity lies in
  /// [drift_ratio, drift_ratio + bracket); 0 when the search's upper end passed.
  double bracket = 0.0;
  double resolution = 0.0;        ///< asked for
  double upper = 0.0;             ///< top of the search
  bool upper_passed = false;      ///< the capacity is at least `upper`
  std::string limited_by;         ///< failed criteria at the smallest failing drift
  std::vector<DriftTrial> trials; ///< in the order run
};

struct CheckResult {
  double yield_deformation = 0.0; ///< Delta_by, mm (from the model)
  double yield_force = 0.0;       ///< fy A_core of the model, N
  YieldForces forces;
  DriftDemand demand;
  QualificationResult qualification;
  double adjusted_tension = 0.0;     ///< omega Ry Pysc, N
  double adjusted_compression = 0.0; ///< beta omega Ry Pysc, N
  std::optional<DriftCapacity> drift_capacity;
  std::vector<std::string> warnings;
  bool passed() const { return qualification.passed; }
};

/// The qualification of the brace of `check` at design deformation `design_deformation` (mm),
/// on a fresh model.
QualificationResult qualify(const CheckSpec& check, double design_deformation);

/// Runs the check (and the drift-capacity search when check.drift_capacity is set).
CheckResult run_check(const CheckSpec& check);

/// The drift-capacity search of `check` given the result at the design drift (`at_design`,
/// at drift ratio `design_ratio`, the floored one): bisection on the drift ratio in
/// [minimum ratio, spec.upper] until the bracket is narrower than spec.resolution. Each trial
/// is a qualification run on a fresh model.
DriftCapacity find_drift_capacity(const CheckSpec& check, const DriftCapacitySpec& spec,
                                  double design_ratio, bool passed_at_design,
                                  const std::string& failed_at_design);

} // namespace brb::design
