// What an AISC 341 brace check is asked to do (README "brb check", the check file): the
// brace, the story it sits in (given, or a frame model and the brace's id), the design story
// drift, the core's yield stress, Ry, the edition and the drift-capacity search.
#pragma once

#include "brb/design/edition.hpp"
#include "brb/design/kinematics.hpp"
#include "brb/model/brace_spec.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace brb::design {

/// How the design story drift was given.
enum class DriftSource { ratio, drift, elastic };

struct DesignDriftSpec {
  DriftSource source = DriftSource::ratio;
  double value = 0.0; ///< ratio (-), drift (mm) or delta_xe (mm), by source
  double Cd = 1.0;    ///< elastic: deflection amplification factor (ASCE 7)
  double Ie = 1.0;    ///< elastic: importance factor (ASCE 7)
};

/// The drift-capacity search: bisection on the design story drift ratio.
struct DriftCapacitySpec {
  double resolution = 0.0025; ///< drift ratio: the bisection stops when its bracket is narrower
  double upper = 0.05;        ///< drift ratio: the top of the search
};

struct CheckSpec {
  std::string name; ///< the check's name (default: the check file's name without extension)
  model::BraceSpec brace;
  std::string brace_source; ///< the brace file, or "<frame file> element <id>"
  /// The story from the check file's "story", or from the frame model.
  StoryGeometry story;
  /// With a frame model: the brace's own geometry in it (its kinematics are used).
  std::optional<FrameBraceGeometry> frame_brace;
  std::string frame_source; ///< the frame model file (empty without one)
  DesignDriftSpec design_drift;
  std::optional<double> fysc_specified; ///< MPa
  std::optional<double> fysc_measured;  ///< MPa (default: the brace's core fy when neither)
  double Ry = 1.0;
  EditionParameters edition;
  std::optional<double> beta_limit_override;
  double max_step = 0.1; ///< multiples of Delta_by: the largest deformation step of the test
  std::optional<DriftCapacitySpec> drift_capacity;

  /// The design story drift (mm) as given or from the elastic analysis (Cd delta_xe / Ie),
  /// before the 1 % floor.
  double design_story_drift() const;
  /// The beta limit in force (the override, or the edition's).
  double beta_limit() const;
};

} // namespace brb::design
