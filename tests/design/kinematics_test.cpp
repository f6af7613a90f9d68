// From story drift to brace deformation (AISC341_NOTES.md "Kinematics"): the small-
// displacement formula, and the frame's own geometry (brbf3) against it.
#include "brb/design/kinematics.hpp"

#include "brb/io/frame_input.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::design {
namespace {

TEST(BraceKinematics, DiagonalBraceTakesDriftTimesCosTheta) {
  // h = 4000, b = 6000: cos(theta) = 6000 / sqrt(6000^2 + 4000^2) = 0.832050...
  const StoryGeometry story{4000.0, 6000.0, BraceConfiguration::diagonal};
  EXPECT_NEAR(brace_deformation_small(story, 40.0), 40.0 * 6000.0 / std::hypot(6000.0, 4000.0),
              1e-12);
  EXPECT_NEAR(story.brace_length(), std::hypot(6000.0, 4000.0), 1e-9);
}

TEST(BraceKinematics, ChevronBraceUsesTheHalfBay) {
  // h = 4000, b = 6000, chevron: horizontal projection 3000, cos(theta) = 3000 / 5000 = 0.6.
  const StoryGeometry story{4000.0, 6000.0, BraceConfiguration::chevron};
  EXPECT_NEAR(brace_deformation_small(story, 40.0), 24.0, 1e-12);
  EXPECT_NEAR(story.brace_length(), 5000.0, 1e-9);
}

TEST(BraceKinematics, ExactGeometryTendsToTheSmallDisplacementFormula) {
  // A 3-4-5 diagonal: at a tiny drift the exact change of length is Delta cos(theta).
  FrameBraceGeometry geometry;
  geometry.lower_end = element::Vector3(0.0, 0.0, 0.0);
  geometry.upper_end = element::Vector3(3000.0, 0.0, 4000.0);
  geometry.story_height = 4000.0;
  geometry.drift_direction = element::Vector3::UnitX();
  EXPECT_NEAR(brace_deformation_in_frame(geometry, 1e-3) / 1e-3, 0.6, 1e-6);
  // Exact at a large drift: sqrt(3400^2 + 4000^2) - 5000.
  EXPECT_NEAR(brace_deformation_in_frame(geometry, 400.0), std::hypot(3400.0, 4000.0) - 5000.0,
              1e-9);
  // The drift the other way shortens the brace by less (second order): the design value is
  // the larger magnitude.
  EXPECT_NEAR(design_deformation_in_frame(geometry, 400.0), std::hypot(3400.0, 4000.0) - 5000.0,
              1e-9);
}

TEST(BraceKinematics, Brbf3BracesAgreeWithTheFormulaWithinOnePercentAtTwoPercentDrift) {
  const model::FrameSpec frame =
      io::read_frame(std::filesystem::path(BRB_SOURCE_DIR) / "frames/brbf3/model.json");
  // Story 1 (h 4500, chevron to mid-bay, braces 2101 and 2102), story 2 (h 4000, 2201).
  for (const int id : {2101, 2102, 2201, 2302}) {
    const FrameBraceGeometry geometry = frame_brace_geometry(frame, id);
    const double drift = 0.02 * geometry.story_height;
    const double small = brace_deformation_small(geometry.story_geometry(), drift);
    const double exact = design_deformation_in_frame(geometry, drift);
    EXPECT_NEAR(exact / small, 1.0, 0.01) << "brace " << id;
    // Not identical: the exact value carries the second-order term.
    EXPECT_GT(std::abs(exact - small), 1e-6 * small) << "brace " << id;
  }
  const FrameBraceGeometry first = frame_brace_geometry(frame, 2101);
  EXPECT_EQ(first.story, "1");
  EXPECT_DOUBLE_EQ(first.story_height, 4500.0);
  // The chevron of story 1: nodes 1 (0, 0) and 102 (4500, 4500): 45 degrees.
  EXPECT_NEAR(first.story_geometry().angle(), std::atan(1.0), 1e-12);
  EXPECT_EQ(frame_brace_geometry(frame, 2201).story, "2");
}

TEST(BraceKinematics, AnIdThatIsNotABraceIsRejected) {
  const model::FrameSpec frame =
      io::read_frame(std::filesystem::path(BRB_SOURCE_DIR) / "frames/brbf3/model.json");
  EXPECT_THROW(frame_brace_geometry(frame, 101), std::invalid_argument); // a column
  EXPECT_THROW(frame_brace_geometry(frame, 9999), std::invalid_argument);
}

} // namespace
} // namespace brb::design
