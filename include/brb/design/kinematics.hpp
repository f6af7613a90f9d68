// From the design story drift to the brace's axial deformation Delta_bm (AISC341_NOTES.md,
// "Kinematics"): the small-displacement formula for a diagonal or chevron brace, and the
// exact (large-displacement) change of length of a brace of a frame model whose story is
// given the drift.
#pragma once

#include "brb/model/frame_spec.hpp"

#include <string>

namespace brb::design {

/// How the brace spans its story: `diagonal` from one corner of the bay to the other,
/// `chevron` from a corner to the middle of the beam (half-bay geometry).
enum class BraceConfiguration { diagonal, chevron };

std::string to_string(BraceConfiguration configuration);

/// The story a brace sits in, in the plane of the frame (mm).
struct StoryGeometry {
  double story_height = 0.0;
  double bay_width = 0.0;
  BraceConfiguration configuration = BraceConfiguration::diagonal;

  /// Horizontal projection of the brace: the bay, or half of it for a chevron.
  double horizontal_span() const;
  /// Angle of the brace to the horizontal (rad).
  double angle() const;
  /// Work-point length of the brace.
  double brace_length() const;
};

/// Small-displacement brace deformation for a story drift (mm): Delta cos(theta).
double brace_deformation_small(const StoryGeometry& geometry, double story_drift);

/// A brace of a frame model and its story, from the frame's own geometry.
struct FrameBraceGeometry {
  int brace_id = 0;
  std::string story;                ///< the story's name
  element::Vector3 lower_end;       ///< mm, the work point on the story's bottom level
  element::Vector3 upper_end;       ///< mm, the work point on the story's top level
  double story_height = 0.0;        ///< mm
  element::Vector3 drift_direction; ///< unit, horizontal, in the brace's vertical plane
  double length() const { return (upper_end - lower_end).norm(); }
  /// The equivalent StoryGeometry: a diagonal whose bay is the brace's horizontal
  /// projection (a chevron brace is the same, with its half bay).
  StoryGeometry story_geometry() const;
};

/// The geometry of the `brb` element `brace_id` of `frame`: its story is the one of
/// `frame.stories` whose bottom and top levels (Z of their nodes) hold the brace's two
/// nodes. Throws std::invalid_argument when there is no such element or story (the check
/// reader turns it into an InputError at the right JSON path).
FrameBraceGeometry frame_brace_geometry(const model::FrameSpec& frame, int brace_id);

/// The brace's change of length (mm, elongation positive) when the story's top level
/// translates rigidly by `story_drift` (mm, signed along drift_direction) relative to its
/// bottom level: |upper + drift - lower| - |upper - lower|, exact for any drift (no small-
/// angle approximation; the floors stay rigid and level).
double brace_deformation_in_frame(const FrameBraceGeometry& geometry, double story_drift);

/// The larger magnitude of brace_deformation_in_frame for the drift applied each way: the
/// design deformation Delta_bm the qualification sequence uses (its cycles go both ways).
double design_deformation_in_frame(const FrameBraceGeometry& geometry, double story_drift);

} // namespace brb::design
