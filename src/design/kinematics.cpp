#include "brb/design/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

namespace brb::design {

std::string to_string(BraceConfiguration configuration) {
  return configuration == BraceConfiguration::chevron ? "chevron" : "diagonal";
}

double StoryGeometry::horizontal_span() const {
  return configuration == BraceConfiguration::chevron ? 0.5 * bay_width : bay_width;
}

double StoryGeometry::angle() const {
  return std::atan2(story_height, horizontal_span());
}

double StoryGeometry::brace_length() const {
  return std::hypot(story_height, horizontal_span());
}

double brace_deformation_small(const StoryGeometry& geometry, double story_drift) {
  // AISC341_NOTES.md: Delta_b = Delta cos(theta) (small displacements).
  return story_drift * std::cos(geometry.angle());
}

StoryGeometry FrameBraceGeometry::story_geometry() const {
  const element::Vector3 chord = upper_end - lower_end;
  const double horizontal = std::hypot(chord.x(), chord.y());
  return {story_height, horizontal, BraceConfiguration::diagonal};
}

FrameBraceGeometry frame_brace_geometry(const model::FrameSpec& frame, int brace_id) {
  const auto element = std::find_if(
      frame.elements.begin(), frame.elements.end(), [&](const model::FrameElementSpec& candidate) {
        return candidate.id == brace_id &&
               std::holds_alternative<model::BraceElementSpec>(candidate.kind);
      });
  if (element == frame.elements.end())
    throw std::invalid_argument("the frame has no brb element with id " + std::to_string(brace_id));
  element::Vector3 a = frame.node(element->nodes[0]).coordinates;
  element::Vector3 b = frame.node(element->nodes[1]).coordinates;
  if (a.z() > b.z())
    std::swap(a, b);
  constexpr double kLevelTolerance = 1.0; // mm: a node on a level
  for (const model::StorySpec& story : frame.stories) {
    const double bottom = frame.node(story.bottom).coordinates.z();
    const double top = frame.node(story.top).coordinates.z();
    if (std::abs(a.z() - bottom) <= kLevelTolerance && std::abs(b.z() - top) <= kLevelTolerance) {
      FrameBraceGeometry geometry;
      geometry.brace_id = brace_id;
      geometry.story = story.name;
      geometry.lower_end = a;
      geometry.upper_end = b;
      geometry.story_height = top - bottom;
      element::Vector3 horizontal(b.x() - a.x(), b.y() - a.y(), 0.0);
      // A vertical brace has no drift direction of its own: the frame's X is taken.
      geometry.drift_direction = horizontal.norm() > 0.0 ? element::Vector3(horizontal.normalized())
                                                         : element::Vector3::UnitX();
      return geometry;
    }
  }
  throw std::invalid_argument("brb element " + std::to_string(brace_id) +
                              " does not span a story of the frame's \"stories\" (its nodes "
                              "are not on the bottom and top levels of one story)");
}

double brace_deformation_in_frame(const FrameBraceGeometry& geometry, double story_drift) {
  const element::Vector3 moved = geometry.upper_end + story_drift * geometry.drift_direction;
  return (moved - geometry.lower_end).norm() - geometry.length();
}

double design_deformation_in_frame(const FrameBraceGeometry& geometry, double story_drift) {
  return std::max(std::abs(brace_deformation_in_frame(geometry, story_drift)),
                  std::abs(brace_deformation_in_frame(geometry, -story_drift)));
}

} // namespace brb::design
