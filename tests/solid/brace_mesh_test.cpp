// The brace mesher: exact part volumes, structured node and element counts, contact faces
// facing the gap, the half model as the full model's half, the homogenised tube, the bare
// core's E A / L, and the errors of a bad spec.
#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/solid/brace_mesh.hpp"
#include "brb/solid/hex8.hpp"
#include "brb/solid/solid_static.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::solid {
namespace {

using model::SectionShape;

model::SectionSpec rectangle(double width, double depth) {
  model::SectionSpec section;
  section.shape = SectionShape::rectangle;
  section.width = width;
  section.depth = depth;
  return section;
}

/// A plate core 40 x 10 mm, yielding length 600 mm, transition 60 x 12 mm over 60 mm and
/// connection 80 x 16 mm over 80 mm at each end, in a 100 x 60 x 4 mm tube with 1 mm gaps,
/// bowed by 0.6 mm along z.
model::BraceSpec plate_brace() {
  model::BraceSpec brace;
  brace.core_section = rectangle(40.0, 10.0);
  brace.steel.youngs_modulus = 210000.0;
  brace.steel.poissons_ratio = 0.3;
  brace.steel.yield_stress = 355.0;
  brace.yielding_length = 600.0;
  brace.transition = model::ZoneSpec{60.0, rectangle(60.0, 12.0), 1};
  brace.connection = model::ZoneSpec{80.0, rectangle(80.0, 16.0), 1};
  brace.imperfection = {model::ImperfectionShape::bow, 0.6, model::BendingAxis::z};
  model::CasingSpec casing;
  casing.tube.shape = SectionShape::rectangular_tube;
  casing.tube.width = 100.0;
  casing.tube.depth = 60.0;
  casing.tube.wall = 4.0;
  casing.tube_steel = brace.steel;
  casing.mortar.youngs_modulus = 17520.0;
  casing.mortar.poissons_ratio = 0.2;
  casing.gap_y = casing.gap_z = 1.0;
  brace.casing = casing;
  return brace;
}

model::SolidMeshSpec mesh_spec(double axial_size) {
  model::SolidMeshSpec solid;
  solid.axial_element_size = axial_size;
  return solid;
}

double part_volume(const BracePartMesh& part) {
  double volume = 0.0;
  for (const HexConnectivity& hex : part.mesh.elements) {
    NodeMatrix coordinates;
    for (int a = 0; a < 8; ++a)
      coordinates.col(a) = part.mesh.nodes.col(hex[a]);
    volume += hex8_reference(coordinates).volume;
  }
  return volume;
}

/// Volume of a layer of length h whose rectangle grows linearly from w0 x d0 to w1 x d1:
/// h int_0^1 (w0 + dw t)(d0 + dd t) dt.
double taper(double w0, double d0, double w1, double d1, double h) {
  const double dw = w1 - w0, dd = d1 - d0;
  return h * (w0 * d0 + 0.5 * (w0 * dd + d0 * dw) + dw * dd / 3.0);
}

TEST(BraceMesh, PartVolumesAreTheExactVolumes) {
  // Theory: the core is the yielding plate plus the two end zones, whose first element layer
  // (10 mm: the zones' lengths are multiples of the 10 mm axial size) tapers from the smaller
  // section (brace_mesh.hpp); the rectangle zones are matched exactly by the scaled grid (area
  // and weak-axis I of a rectangle fix both sides). Mortar: the ring between the tube's inside
  // (92 x 52) and the opening (42 x 12) over the casing's 600 mm; the bow shifts the opening
  // without changing its area. Tube: its wall ring.
  const BraceMesh mesh = mesh_brace(plate_brace(), mesh_spec(10.0));
  const double transition = 720.0 * 50.0 + taper(40.0, 10.0, 60.0, 12.0, 10.0);
  const double connection = 1280.0 * 70.0 + taper(60.0, 12.0, 80.0, 16.0, 10.0);
  const double core = 400.0 * 600.0 + 2.0 * (transition + connection);
  EXPECT_NEAR(part_volume(mesh.core) / core, 1.0, 1e-12);
  EXPECT_NEAR(part_volume(mesh.mortar) / ((92.0 * 52.0 - 42.0 * 12.0) * 600.0), 1.0, 1e-12);
  EXPECT_NEAR(part_volume(mesh.tube) / ((100.0 * 60.0 - 92.0 * 52.0) * 600.0), 1.0, 1e-12);
  EXPECT_NEAR(mesh.core_area, 400.0, 1e-9);
  EXPECT_DOUBLE_EQ(mesh.casing_start, 140.0);
  EXPECT_DOUBLE_EQ(mesh.casing_end, 740.0);
}

TEST(BraceMesh, NodeAndElementCountsFollowTheStructuredNumbering) {
  // Core grid: 2 elements across the 10 mm side (5 mm), 8 across 40 mm; stations every 10 mm
  // over 880 mm: 89. Casing grid in y: tube 1, mortar 2, opening 42 mm / 5 mm -> 8, mortar 2,
  // tube 1 (14 cells); in z: 1, 2, 12 / 5 -> 2, 2, 1 (8 cells); the opening's 7 x 1 interior
  // grid nodes are no node. Casing stations: 61 (x = 140 .. 740).
  const BraceMesh mesh = mesh_brace(plate_brace(), mesh_spec(10.0));
  const int core_per_station = 9 * 3, stations = 89;
  const int casing_per_station = 15 * 9 - 7 * 1, casing_stations = 61;
  EXPECT_EQ(mesh.stations.size(), static_cast<std::size_t>(stations));
  EXPECT_EQ(mesh.nodes.cols(), core_per_station * stations + casing_per_station * casing_stations);
  EXPECT_EQ(mesh.core.mesh.node_count(), core_per_station * stations);
  EXPECT_EQ(mesh.core.mesh.element_count(), 8 * 2 * (stations - 1));
  // tube: the outer and inner outlines' nodes; mortar: inner outline and everything inside
  const int tube_nodes = 2 * (14 + 8) + 2 * (12 + 6);
  const int mortar_nodes = casing_per_station - 2 * (14 + 8);
  EXPECT_EQ(mesh.tube.mesh.node_count(), tube_nodes * casing_stations);
  EXPECT_EQ(mesh.mortar.mesh.node_count(), mortar_nodes * casing_stations);
  EXPECT_EQ(mesh.tube.mesh.element_count(), (14 * 8 - 12 * 6) * (casing_stations - 1));
  EXPECT_EQ(mesh.mortar.mesh.element_count(), (12 * 6 - 8 * 2) * (casing_stations - 1));
  EXPECT_EQ(mesh.loaded_end.size(), static_cast<std::size_t>(core_per_station));
  EXPECT_EQ(mesh.fixed_end.size(), static_cast<std::size_t>(core_per_station));
  EXPECT_TRUE(mesh.symmetry_plane.empty());
  EXPECT_EQ(mesh.stopper_casing.size(), static_cast<std::size_t>(casing_per_station));
  for (int node : mesh.loaded_end)
    EXPECT_DOUBLE_EQ(mesh.nodes(0, node), 880.0);
  for (int node : mesh.stopper_core) // the stopper at mid-length
    EXPECT_DOUBLE_EQ(mesh.nodes(0, node), 440.0);
  // mortar and tube share the nodes of the tube's inner outline
  std::vector<int> shared;
  std::vector<int> tube = mesh.tube.global_nodes, mortar = mesh.mortar.global_nodes;
  std::sort(tube.begin(), tube.end());
  std::sort(mortar.begin(), mortar.end());
  std::set_intersection(tube.begin(), tube.end(), mortar.begin(), mortar.end(),
                        std::back_inserter(shared));
  EXPECT_EQ(shared.size(), static_cast<std::size_t>(2 * (12 + 6) * casing_stations));
}

TEST(BraceMesh, ContactFacesPointIntoTheGap) {
  // Each face's right-hand normal (p1 - p0) x (p3 - p0) must point out of its own body into the
  // gap: away from the bowed core axis for core faces, towards it for casing faces; the core
  // faces lie on the core's outline and the casing faces 1 mm (the gap) farther out.
  const model::BraceSpec brace = plate_brace();
  const BraceMesh mesh = mesh_brace(brace, mesh_spec(10.0));
  const double total = brace.total_length();
  const auto check = [&](const std::vector<QuadFace>& faces, double sign, double half_y,
                         double half_z) {
    for (const QuadFace& face : faces) {
      const Eigen::Vector3d p0 = mesh.nodes.col(face[0]);
      const Eigen::Vector3d normal =
          (mesh.nodes.col(face[1]) - p0).cross(mesh.nodes.col(face[3]) - p0).normalized();
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int node : face)
        centre += 0.25 * mesh.nodes.col(node);
      Eigen::Vector3d axis(centre.x(), 0.0, 0.6 * std::sin(std::numbers::pi * centre.x() / total));
      const Eigen::Vector3d radial = centre - axis;
      ASSERT_GT(sign * normal.dot(radial), 0.0);
      // a face of the outline: its normal is +-y or +-z, at the outline's distance
      if (std::abs(normal.y()) > 0.999)
        EXPECT_NEAR(std::abs(radial.y()), half_y, 1e-9);
      else
        EXPECT_NEAR(std::abs(radial.z()), half_z, 2e-3); // the bow's chord over one element
      EXPECT_GE(centre.x(), mesh.casing_start);
      EXPECT_LE(centre.x(), mesh.casing_end);
    }
  };
  check(mesh.core_faces, 1.0, 20.0, 5.0);
  check(mesh.casing_faces, -1.0, 21.0, 6.0);
  // per layer: the core's outline 2 (8 + 2) faces, the opening's 2 (8 + 2)
  EXPECT_EQ(mesh.core_faces.size(), static_cast<std::size_t>(20 * 60));
  EXPECT_EQ(mesh.casing_faces.size(), static_cast<std::size_t>(20 * 60));
}

TEST(BraceMesh, HalfLengthMeshIsTheFullMeshsHalf) {
  model::BraceSpec brace = plate_brace();
  model::SolidMeshSpec solid = mesh_spec(10.0);
  const BraceMesh full = mesh_brace(brace, solid);
  solid.half_length = true;
  const BraceMesh half = mesh_brace(brace, solid);
  ASSERT_EQ(half.stations.size(), (full.stations.size() + 1) / 2);
  for (std::size_t k = 0; k < half.stations.size(); ++k)
    EXPECT_DOUBLE_EQ(half.stations[k], full.stations[k + full.stations.size() / 2]);
  EXPECT_DOUBLE_EQ(half.x_start, 440.0);
  EXPECT_TRUE(half.fixed_end.empty());
  EXPECT_TRUE(half.stopper_core.empty());
  // the symmetry plane holds the core's and the casing's mid-length nodes
  EXPECT_EQ(half.symmetry_plane.size(), static_cast<std::size_t>(27 + 15 * 9 - 7));
  for (int node : half.symmetry_plane)
    EXPECT_DOUBLE_EQ(half.nodes(0, node), 440.0);
  EXPECT_NEAR(part_volume(half.mortar) / part_volume(full.mortar), 0.5, 1e-12);
  EXPECT_NEAR(part_volume(half.core) / part_volume(full.core), 0.5, 1e-12);
  // a stopper away from mid-length has no place in a half model
  brace.casing->stopper_position = 0.3;
  EXPECT_THROW(mesh_brace(brace, solid), ParameterError);
}

TEST(BraceMesh, CircleCruciformAndHomogenisedTube) {
  // Circle core d = 22 as the equal-area square (the source), cruciform core as its exact area
  // (W t + D t - t^2), a circular tube as the square ring of equal wall and area pi (D - t) t,
  // and the homogenised tube: a square whose weak-axis E_c I equals the mortar's plus the
  // tube ring's E_s I, i.e. a_h^4 = a_i^4 + n_E (a_o^4 - a_i^4) (closed form for a square).
  model::BraceSpec brace = plate_brace();
  brace.transition.reset();
  brace.connection.reset();
  brace.imperfection.amplitude = 0.0;
  brace.core_section = {};
  brace.core_section.shape = SectionShape::circle;
  brace.core_section.diameter = 22.0;
  brace.casing->tube = {};
  brace.casing->tube.shape = SectionShape::circular_tube;
  brace.casing->tube.diameter = 90.0;
  brace.casing->tube.wall = 3.0;
  brace.casing->gap_y = brace.casing->gap_z = 0.5;
  const BraceMesh round = mesh_brace(brace, mesh_spec(20.0));
  EXPECT_NEAR(part_volume(round.core) / (std::numbers::pi * 121.0 * 600.0), 1.0, 1e-12);
  EXPECT_NEAR(part_volume(round.tube) / (std::numbers::pi * 87.0 * 3.0 * 600.0), 1.0, 1e-12);
  const double a_o = std::numbers::pi * 87.0 / 4.0 + 3.0, a_i = a_o - 6.0;
  const double b = 11.0 * std::sqrt(std::numbers::pi) + 1.0; // opening side
  EXPECT_NEAR(part_volume(round.mortar) / ((a_i * a_i - b * b) * 600.0), 1.0, 1e-12);

  model::SolidMeshSpec homogenised = mesh_spec(20.0);
  homogenised.tube = model::SolidTube::homogenised;
  const BraceMesh merged = mesh_brace(brace, homogenised);
  EXPECT_TRUE(merged.tube.empty());
  const double n = 210000.0 / 17520.0;
  const double a_h = std::pow(std::pow(a_i, 4) + n * (std::pow(a_o, 4) - std::pow(a_i, 4)), 0.25);
  EXPECT_NEAR(part_volume(merged.mortar) / ((a_h * a_h - b * b) * 600.0), 1.0, 1e-9);
  RecordProperty("homogenised_side_mm", std::to_string(a_h));

  brace.core_section = {};
  brace.core_section.shape = SectionShape::cruciform;
  brace.core_section.width = 50.0;
  brace.core_section.depth = 30.0;
  brace.core_section.thickness = 10.0;
  brace.casing->gap_y = brace.casing->gap_z = 1.0;
  const BraceMesh cross = mesh_brace(brace, mesh_spec(20.0));
  EXPECT_NEAR(part_volume(cross.core) / ((500.0 + 300.0 - 100.0) * 600.0), 1.0, 1e-12);
  // contact faces: only the four arm tips (2 elements across each), 30 layers
  EXPECT_EQ(cross.core_faces.size(), static_cast<std::size_t>(4 * 2 * 30));
}

TEST(BraceMesh, BareElasticCoreGivesEAOverL) {
  // Theory: a prismatic bar in uniaxial stress (ends on rollers, lateral contraction free),
  // St Venant-Kirchhoff: F = A lambda E (lambda^2 - 1) / 2, to 1e-6 (the bar check).
  model::BraceSpec brace = plate_brace();
  brace.transition.reset();
  brace.connection.reset();
  brace.casing.reset();
  brace.imperfection.amplitude = 0.0;
  const BraceMesh mesh = mesh_brace(brace, mesh_spec(20.0));
  EXPECT_TRUE(mesh.mortar.empty());
  EXPECT_TRUE(mesh.core_faces.empty());
  SolidModel<material::IsotropicElastic3D> bar(
      mesh.core.mesh, [](double) { return material::IsotropicElastic3D(210000.0, 0.3); }, 7.85e-9);
  const auto nearest = [&](const Eigen::Vector3d& point) {
    Eigen::Index best = 0;
    (mesh.nodes.colwise() - point).colwise().squaredNorm().minCoeff(&best);
    return static_cast<int>(best);
  };
  const double delta = 0.3;
  PrescribedDisplacements supports;
  for (int node : mesh.fixed_end)
    supports.add(node, 0, 0.0);
  for (int node : mesh.loaded_end)
    supports.add(node, 0, delta);
  const int centre = nearest(Eigen::Vector3d(0, 0, 0));
  supports.add(centre, 1, 0.0);
  supports.add(centre, 2, 0.0);
  supports.add(nearest(Eigen::Vector3d(0, 20, 0)), 2, 0.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(bar.dof_count()), reactions;
  const auto report = solve_static(bar, u, supports, Eigen::VectorXd::Zero(bar.dof_count()),
                                   {30, 1e-12}, &reactions);
  ASSERT_TRUE(report.converged) << report.failure;
  double force = 0.0;
  for (int node : mesh.loaded_end)
    force += reactions[3 * node];
  const double lambda = 1.0 + delta / 600.0;
  EXPECT_NEAR(force / (400.0 * lambda * 210000.0 * 0.5 * (lambda * lambda - 1.0)), 1.0, 1e-6);
}

TEST(BraceMesh, RefusesABadSpec) {
  const model::BraceSpec brace = plate_brace();
  const auto field_of = [](const model::BraceSpec& b, const model::SolidMeshSpec& s) {
    try {
      (void)mesh_brace(b, s);
    } catch (const ParameterError& error) {
      return error.field();
    }
    return std::string("none");
  };
  model::SolidMeshSpec solid = mesh_spec(10.0);
  solid.steel_density = 0.0;
  EXPECT_EQ(field_of(brace, solid), "solid/steel_density");
  solid = mesh_spec(10.0);
  solid.mortar_density = -2.35e-9;
  EXPECT_EQ(field_of(brace, solid), "solid/mortar_density");
  solid = mesh_spec(10.0);
  solid.elements_across_core = 1;
  EXPECT_EQ(field_of(brace, solid), "solid/elements_across_core");
  solid = mesh_spec(10.0);
  solid.elements_through_mortar = 1;
  EXPECT_EQ(field_of(brace, solid), "solid/elements_through_mortar");
  solid = mesh_spec(150.0); // 150 mm along, 5 mm across: 30
  EXPECT_EQ(field_of(brace, solid), "solid/axial_element_size");
  model::BraceSpec negative_gap = brace;
  negative_gap.casing->gap_z = -0.1;
  EXPECT_EQ(field_of(negative_gap, mesh_spec(10.0)), "casing/gap");
  model::BraceSpec large_bow = brace; // 23 mm mortar along z less the bow
  large_bow.imperfection.amplitude = 25.0;
  EXPECT_EQ(field_of(large_bow, mesh_spec(10.0)), "casing/tube");
  model::BraceSpec thin_arm = brace; // arms 1 mm beyond the centre: under one 5 mm element
  thin_arm.core_section = {};
  thin_arm.core_section.shape = SectionShape::cruciform;
  thin_arm.core_section.width = 12.0;
  thin_arm.core_section.depth = 12.0;
  thin_arm.core_section.thickness = 10.0;
  EXPECT_EQ(field_of(thin_arm, mesh_spec(10.0)), "solid/elements_across_core");
  model::BraceSpec tube_core = brace;
  tube_core.core_section.shape = SectionShape::rectangular_tube;
  tube_core.core_section.wall = 2.0;
  EXPECT_EQ(field_of(tube_core, mesh_spec(10.0)), "core/section/shape");
}

} // namespace
} // namespace brb::solid
