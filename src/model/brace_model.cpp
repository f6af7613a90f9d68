#include "brb/model/brace_model.hpp"

#include "brb/analysis/static_analysis.hpp"
#include "brb/material/parameter_error.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <string>

namespace brb::model {
namespace {

struct Zone {
  double length;
  const SectionSpec* section;
  int elements;
  bool yielding;
};

/// Zones from start to end.
std::vector<Zone> zones_of(const BraceSpec& spec) {
  std::vector<Zone> zones;
  if (spec.connection) {
    zones.push_back(
        {spec.connection->length, &spec.connection->section, spec.connection->elements, false});
  }
  if (spec.transition) {
    zones.push_back(
        {spec.transition->length, &spec.transition->section, spec.transition->elements, false});
  }
  zones.push_back({spec.yielding_length, &spec.core_section, spec.core_elements, true});
  if (spec.transition) {
    zones.push_back(
        {spec.transition->length, &spec.transition->section, spec.transition->elements, false});
  }
  if (spec.connection) {
    zones.push_back(
        {spec.connection->length, &spec.connection->section, spec.connection->elements, false});
  }
  return zones;
}

void check(bool condition, const std::string& field, const std::string& expected) {
  if (!condition)
    throw ParameterError(field, expected);
}

/// Builds the model with nodes at `offsets` (lateral Y, Z per node; empty: straight).
BraceModel build(const BraceSpec& spec, const std::vector<std::pair<double, double>>& offsets) {
  check(spec.yielding_length > 0.0, "core/yielding_length", "must be > 0 mm");
  check(spec.core_elements >= 1, "core/elements", "must be >= 1");
  for (const auto* zone : {&spec.transition, &spec.connection}) {
    if (*zone) {
      check((*zone)->length > 0.0,
            zone == &spec.transition ? "transition/length" : "connection/length", "must be > 0 mm");
      check((*zone)->elements >= 1,
            zone == &spec.transition ? "transition/elements" : "connection/elements",
            "must be >= 1");
    }
  }
  const double youngs = spec.steel.youngs_modulus;
  const double shear = youngs / (2.0 * (1.0 + spec.steel.poissons_ratio));
  const auto integration =
      element::BeamIntegration::make(spec.integration_rule, spec.integration_points);

  BraceModel brace;
  const section::FiberLayout core_layout = spec.core_section.mesh();
  brace.core_area = core_layout.total_area();
  brace.yield_force = spec.steel.yield_stress * brace.core_area;

  double x = 0.0;
  const auto add_node = [&](double position) {
    const std::size_t index = brace.nodes.size();
    element::Vector3 point(position, 0.0, 0.0);
    if (!offsets.empty()) {
      point.y() = offsets[index].first;
      point.z() = offsets[index].second;
    }
    brace.nodes.push_back(brace.model.add_node(point));
  };
  add_node(0.0);
  double flexibility = 0.0; // sum L / (E A)
  for (const Zone& zone : zones_of(spec)) {
    const section::FiberLayout layout = zone.yielding ? core_layout : zone.section->mesh();
    flexibility += zone.length / (youngs * layout.total_area());
    const double element_length = zone.length / zone.elements;
    for (int e = 0; e < zone.elements; ++e) {
      x += element_length;
      add_node(x);
      const int first = brace.nodes[brace.nodes.size() - 2], second = brace.nodes.back();
      std::vector<CoreSection> sections;
      sections.reserve(integration.weights.size());
      for (const double weight : integration.weights) {
        // each fiber's characteristic length: its integration weight times the element length
        sections.emplace_back(layout, material::SteelUniaxial(spec.steel, weight * element_length),
                              shear);
      }
      brace.beams.push_back(&brace.model.add_element(std::make_unique<CoreBeam>(
          std::array<int, 2>{first, second}, brace.model.coordinates(first),
          brace.model.coordinates(second), element::Vector3(0.0, 0.0, 1.0), integration,
          std::move(sections))));
      brace.in_yielding_zone.push_back(zone.yielding);
    }
  }
  brace.yield_deformation = brace.yield_force * flexibility;
  brace.start_node = brace.nodes.front();
  brace.end_node = brace.nodes.back();

  Model& model = brace.model;
  for (const Dof dof : {ux, uy, uz, rx})
    model.fix(brace.start_node, dof);
  for (const Dof dof : {uy, uz})
    model.fix(brace.end_node, dof);
  if (spec.ends == EndCondition::fixed) {
    for (const Dof dof : {ry, rz})
      model.fix(brace.start_node, dof);
    for (const Dof dof : {rx, ry, rz})
      model.fix(brace.end_node, dof);
  }
  return brace;
}

} // namespace

BraceModel build_brace_model(const BraceSpec& spec) {
  const double total = spec.total_length();
  check(spec.imperfection.amplitude >= 0.0 && spec.imperfection.amplitude < total,
        "imperfection/amplitude",
        "must be >= 0 and shorter than the brace (" + std::to_string(total) + " mm)");
  // node x positions of a straight model, for the offsets
  BraceModel straight = build(spec, {});
  std::vector<std::pair<double, double>> offsets(straight.nodes.size(), {0.0, 0.0});
  const double amplitude = spec.imperfection.amplitude;
  if (amplitude > 0.0) {
    if (spec.imperfection.shape == ImperfectionShape::bow) {
      for (std::size_t n = 0; n < straight.nodes.size(); ++n) {
        const double x = straight.model.coordinates(straight.nodes[n]).x();
        const double offset = amplitude * std::sin(std::numbers::pi * x / total);
        (spec.imperfection.direction == BendingAxis::y ? offsets[n].first : offsets[n].second) =
            offset;
      }
    } else {
      offsets = first_buckling_mode(spec);
      for (auto& [y, z] : offsets) {
        y *= amplitude;
        z *= amplitude;
      }
    }
  }
  return build(spec, offsets);
}

std::vector<std::pair<double, double>> first_buckling_mode(const BraceSpec& spec) {
  // Linearised buckling of the perfect brace: K0 phi = lambda (K0 - K1) phi, with K1 the
  // tangent under a small elastic shortening; the geometric stiffness is linear in the
  // axial force for such a small step. The first mode has the largest 1/lambda.
  BraceModel brace = build(spec, {});
  analysis::StaticAnalysis analysis(brace.model);
  analysis.use_displacement_control(brace.end_node, ux);
  const Eigen::MatrixXd initial = Eigen::MatrixXd(analysis.free_tangent());
  const auto report = analysis.step_to(-1e-3 * brace.yield_deformation);
  if (!report.converged)
    throw std::runtime_error("buckling mode: " + report.failure);
  const Eigen::MatrixXd loaded = Eigen::MatrixXd(analysis.free_tangent());
  const Eigen::MatrixXd problem = initial.partialPivLu().solve(initial - loaded);
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(problem);
  Eigen::Index best = 0;
  for (Eigen::Index k = 1; k < solver.eigenvalues().size(); ++k) {
    if (solver.eigenvalues()[k].real() > solver.eigenvalues()[best].real())
      best = k;
  }
  const Eigen::VectorXd mode = solver.eigenvectors().col(best).real();
  std::vector<std::pair<double, double>> offsets(brace.nodes.size(), {0.0, 0.0});
  double largest = 0.0;
  const auto& free = analysis.free_dofs();
  for (std::size_t e = 0; e < free.size(); ++e) {
    const int node = free[e] / kDofPerNode, dof = free[e] % kDofPerNode;
    if (dof == uy)
      offsets[node].first = mode[static_cast<Eigen::Index>(e)];
    if (dof == uz)
      offsets[node].second = mode[static_cast<Eigen::Index>(e)];
  }
  for (const auto& [y, z] : offsets)
    largest = std::max(largest, std::hypot(y, z));
  for (auto& [y, z] : offsets) {
    y /= largest;
    z /= largest;
  }
  return offsets;
}

} // namespace brb::model
