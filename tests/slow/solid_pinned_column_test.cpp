// brb solid's pinned end faces (solid.end_faces "pinned": each face stays plane and pivots
// about its centre, solid_explicit.hpp's PivotingFace) against the theory of a bowed pinned
// column, and against the default faces, which cannot rotate. Slow: two explicit runs of an
// elastic bar, about 15 s.
#include "brb/solid/brace_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace brb::solid {
namespace {

/// A slender elastic bare core 10 x 10 mm, 200 mm long, bowed by e0 = L / 500 in z (the
/// first mode of a pinned column), 4 hexahedra across, 10 mm along (320 elements).
model::BraceSpec slender_elastic_core(model::SolidEndFaces end_faces) {
  model::BraceSpec brace;
  brace.core_section.shape = model::SectionShape::rectangle;
  brace.core_section.width = 10.0;
  brace.core_section.depth = 10.0;
  brace.steel.youngs_modulus = 210000.0;
  brace.steel.poissons_ratio = 0.3;
  brace.steel.yield_stress = 2000.0; // elastic throughout (the Euler stress is 432 MPa)
  brace.steel.kinematic_hardening = 2100.0;
  brace.yielding_length = 200.0;
  brace.imperfection = {model::ImperfectionShape::bow, 200.0 / 500.0, model::BendingAxis::z};
  model::SolidMeshSpec solid;
  solid.elements_across_core = 4;
  solid.axial_element_size = 10.0;
  solid.end_faces = end_faces;
  brace.solid = solid;
  return brace;
}

struct BowedColumnRun {
  double force = 0.0;       ///< N, compression positive, at the end of the ramp
  double mid_lateral = 0.0; ///< mm: the bow's growth at mid-length (u_z of the core's axis)
};

/// Shortened by 0.6 of the pinned Euler shortening P_E L / (E A) over a slow 1 - cos ramp
/// (15 ms: about 5 periods of the pinned column's lateral mode softened at 0.6 P_E).
BowedColumnRun shorten_bowed_column(model::SolidEndFaces end_faces, double euler) {
  const model::BraceSpec brace = slender_elastic_core(end_faces);
  const double shortening = 0.6 * euler * 200.0 / (210000.0 * 100.0);
  SolidBraceRunSettings settings;
  settings.duration = 0.015;
  BowedColumnRun result;
  const SolidBraceRun run =
      run_solid_brace(brace, {-shortening}, settings, nullptr, [&](const SolidBraceState& state) {
        // the nodes at mid-length (x = 100 mm): their mean u_z
        double sum = 0.0;
        int count = 0;
        for (int node = 0; node < state.mesh.nodes.cols(); ++node) {
          if (std::abs(state.mesh.nodes(0, node) - 100.0) < 1e-6) {
            sum += state.displacement[3 * node + 2];
            ++count;
          }
        }
        result.mid_lateral = sum / count;
      });
  EXPECT_TRUE(run.completed) << run.failure;
  result.force = -run.records.back().force;
  return result;
}

TEST(SolidPinnedColumn, PinnedEndFacesPivotAndTheBowGrowsAsAPinnedColumns) {
  // Reference (theory, Timoshenko & Gere, Theory of Elastic Stability, sec. 1.11): a pinned
  // column bowed e0 sin(pi x / L) under P grows at mid-length by e0 (P / P_E) / (1 - P / P_E),
  // P_E = pi^2 E I / L^2 = 43.2 kN here; at 0.6 P_E that is 1.5 e0 = 0.6 mm. With the faces
  // held along x over their whole area (centre_lines) the ends cannot rotate: a fixed column,
  // four times the Euler load, whose bow grows several times less at the same shortening.
  const double inertia = 10.0 * 1000.0 / 12.0;
  const double euler = std::numbers::pi * std::numbers::pi * 210000.0 * inertia / (200.0 * 200.0);
  const double e0 = 200.0 / 500.0;
  const BowedColumnRun pinned = shorten_bowed_column(model::SolidEndFaces::pinned, euler);
  const BowedColumnRun fixed = shorten_bowed_column(model::SolidEndFaces::centre_lines, euler);
  const double load_ratio = pinned.force / euler;
  const double expected = e0 * load_ratio / (1.0 - load_ratio);
  RecordProperty("pinned_force_over_euler", std::to_string(load_ratio));
  RecordProperty("pinned_growth_over_theory", std::to_string(pinned.mid_lateral / expected));
  RecordProperty("fixed_growth_over_pinned",
                 std::to_string(fixed.mid_lateral / pinned.mid_lateral));
  // the shortening is shared between the axial strain and the bow: the force stays below 0.6
  ASSERT_GT(load_ratio, 0.4);
  ASSERT_LT(load_ratio, 0.6);
  EXPECT_NEAR(pinned.mid_lateral / expected, 1.0, 0.1);
  EXPECT_LT(std::abs(fixed.mid_lateral), 0.3 * std::abs(pinned.mid_lateral));
  EXPECT_GT(fixed.force, pinned.force);
}

} // namespace
} // namespace brb::solid
