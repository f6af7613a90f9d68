// A cyclic run of the 3D continuum brace (see brace_run.hpp).
#include "brb/solid/brace_run.hpp"

#include "brb/material/mortar_damage.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/solid/axial_tie.hpp"
#include "brb/solid/solid_body.hpp"
#include "brb/solid/solid_explicit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>

namespace brb::solid {

namespace {

using Steel = material::SteelDamagePlasticity3D;
using Mortar = material::MortarDamage3D;

/// The protocol in time. Consecutive points that go on in the same direction form one
/// excursion (from a reversal to the next), driven by one 1 - cos ramp of duration
/// time_per_deformation x |excursion|: the brace moves smoothly through the points inside it
/// and stops only where the protocol turns. (A ramp per point started and stopped the brace
/// at every d_y / 10: measured on Girona D3, KE / IE up to 0.134 in the elastic cycles.) Point
/// k of an excursion from d_a at t_a to d_b, duration T, is passed at
///   t_k = t_a + (T / pi) acos(1 - 2 (d_k - d_a) / (d_b - d_a)),
/// the inverse of d(t) = d_a + (d_b - d_a) (1 - cos(pi (t - t_a) / T)) / 2.
/// T is at least min_excursion_time: the short excursions of a protocol's first cycles would
/// otherwise pass zero deformation at the full ramp speed while the internal energy is still
/// small (measured on Girona D3: KE / IE 0.219 in its 1 d_y cycle, at most 0.001 from its
/// 2 d_y cycle's second excursion on).
struct Protocol {
  struct Excursion {
    double start = 0.0, duration = 0.0, from = 0.0, to = 0.0;
  };
  std::vector<double> point_times; // t_k: when the ramp passes d_k (t_0 = 0)
  std::vector<Excursion> excursions;

  /// `targets`: d_0 = 0, d_1, ... (at least two).
  Protocol(const std::vector<double>& targets, double time_per_deformation,
           double min_excursion_time) {
    point_times.push_back(0.0);
    double start = 0.0;
    std::size_t first = 0; // the excursion's first point
    while (first + 1 < targets.size()) {
      const double direction = targets[first + 1] - targets[first];
      std::size_t last = first + 1;
      while (last + 1 < targets.size() && (targets[last + 1] - targets[last]) * direction > 0.0)
        ++last;
      const double duration = std::max(
          time_per_deformation * std::abs(targets[last] - targets[first]), min_excursion_time);
      Excursion excursion{start, duration, targets[first], targets[last]};
      for (std::size_t k = first + 1; k < last; ++k) {
        const double fraction = (targets[k] - excursion.from) / (excursion.to - excursion.from);
        point_times.push_back(start + excursion.duration / std::numbers::pi *
                                          std::acos(std::clamp(1.0 - 2.0 * fraction, -1.0, 1.0)));
      }
      start += excursion.duration;
      point_times.push_back(start);
      excursions.push_back(excursion);
      first = last;
    }
  }

  double at(double t) const {
    for (const Excursion& excursion : excursions)
      if (t < excursion.start + excursion.duration)
        return excursion.from + (excursion.to - excursion.from) *
                                    smooth_ramp(t - excursion.start, excursion.duration);
    return excursions.back().to; // the last point
  }
};

/// The lateral supports (node, direction 1 = y or 2 = z) of an end face of the core
/// (model::SolidEndFaces). Centre lines: u_y held on the face's nodes nearest the line y = y_c
/// (its centroid's), u_z on those nearest z = z_c: no sideways motion or twist, free Poisson
/// strain (the nodes on a centre line do not move across it when the section contracts
/// symmetrically). A face with an odd number of elements across has no node on the line, and
/// the column nearest it is held.
std::vector<std::pair<int, int>> lateral_supports(const Eigen::Matrix3Xd& nodes,
                                                  const std::vector<int>& face,
                                                  model::SolidEndFaces end_faces) {
  std::vector<std::pair<int, int>> supports;
  if (face.empty())
    return supports;
  if (end_faces == model::SolidEndFaces::clamped) {
    for (int node : face)
      for (int direction : {1, 2})
        supports.emplace_back(node, direction);
    return supports;
  }
  for (int direction : {1, 2}) {
    double centre = 0.0, low = nodes(direction, face.front()), high = low;
    for (int node : face) {
      centre += nodes(direction, node);
      low = std::min(low, nodes(direction, node));
      high = std::max(high, nodes(direction, node));
    }
    centre /= static_cast<double>(face.size());
    double nearest = std::numeric_limits<double>::infinity();
    for (int node : face)
      nearest = std::min(nearest, std::abs(nodes(direction, node) - centre));
    const double tolerance = nearest + 1e-9 * (high - low);
    for (int node : face)
      if (std::abs(nodes(direction, node) - centre) <= tolerance)
        supports.emplace_back(node, direction);
  }
  return supports;
}

} // namespace

double core_first_axial_period(const model::BraceSpec& brace, const model::SolidMeshSpec& solid) {
  const double length = brace.total_length(); // the whole core, also for a half model
  // the physical density: the loading rate is the real brace's, so mass scaling lengthens the
  // stable step (by sqrt(scaling)) without lengthening the loading (header)
  const double density = solid.steel_density;
  return 4.0 * length / std::sqrt(brace.steel.youngs_modulus / density);
}

SolidBraceRun run_solid_brace(const model::BraceSpec& brace,
                              const std::vector<double>& deformations,
                              const SolidBraceRunSettings& settings, const ContactFactory& contact,
                              const SolidBraceObserver& observer) {
  if (deformations.empty())
    throw std::invalid_argument("solid brace run: the protocol has no deformation");
  for (double d : deformations)
    if (!std::isfinite(d))
      throw std::invalid_argument("solid brace run: a protocol deformation is not finite");
  if (!(settings.time_per_deformation >= 0.0) || !(settings.duration >= 0.0) ||
      !(settings.min_excursion_time >= 0.0) || settings.outputs_per_segment < 1 ||
      !(settings.stable_step_safety > 0.0 && settings.stable_step_safety <= 1.0) ||
      !(settings.lateral_damping >= 0.0) || !std::isfinite(settings.lateral_damping))
    throw std::invalid_argument("solid brace run: time per deformation, duration, the "
                                "shortest excursion time and the lateral damping must be >= 0, "
                                "outputs per segment >= 1, the step safety in (0, 1]");
  // A floor on the excursions would lengthen the protocol past a total duration asked for.
  if (settings.duration > 0.0 && settings.min_excursion_time > 0.0)
    throw std::invalid_argument("solid brace run: a total duration and a shortest excursion "
                                "time exclude each other");
  brace.steel.validate();
  const model::SolidMeshSpec solid = brace.solid.value_or(model::SolidMeshSpec{});
  const BraceMesh mesh = mesh_brace(brace, solid);

  SolidBody body(mesh.nodes);
  const double steel_density = solid.steel_density * solid.mass_scaling;
  const HourglassControl hourglass{solid.hourglass == model::SolidHourglass::tangent,
                                   solid.hourglass_min_scale};
  body.add_part("core",
                SolidModel<Steel>(
                    mesh.core.mesh, [&](double lc) { return Steel(brace.steel, lc); },
                    steel_density, hourglass),
                mesh.core.global_nodes);
  if (brace.casing) {
    const model::CasingSpec& casing = *brace.casing;
    casing.mortar.validate();
    if (!mesh.mortar.empty())
      body.add_part("mortar",
                    SolidModel<Mortar>(
                        mesh.mortar.mesh, [&](double lc) { return Mortar(casing.mortar, lc); },
                        solid.mortar_density * solid.mass_scaling, hourglass),
                    mesh.mortar.global_nodes);
    if (!mesh.tube.empty()) {
      casing.tube_steel.validate();
      body.add_part("tube",
                    SolidModel<Steel>(
                        mesh.tube.mesh, [&](double lc) { return Steel(casing.tube_steel, lc); },
                        steel_density, hourglass),
                    mesh.tube.global_nodes);
    }
    if (!mesh.stopper_core.empty())
      body.add_interaction(std::make_unique<AxialTie>(mesh.stopper_core, mesh.stopper_casing,
                                                      mesh.stopper_stiffness));
    if (contact && !mesh.core_faces.empty())
      body.add_interaction(contact(mesh.core_faces, mesh.casing_faces, mesh.nodes));
  }
  body.set_threads(solid.threads);

  // the protocol's timing
  SolidBraceRun run;
  run.first_axial_period = core_first_axial_period(brace, solid);
  std::vector<double> targets{0.0};
  targets.insert(targets.end(), deformations.begin(), deformations.end());
  double path = 0.0;
  for (std::size_t i = 1; i < targets.size(); ++i)
    path += std::abs(targets[i] - targets[i - 1]);
  if (!(path > 0.0))
    throw std::invalid_argument("solid brace run: the protocol does not move");
  const double yield_deformation =
      brace.steel.yield_stress / brace.steel.youngs_modulus * brace.yielding_length;
  run.time_per_deformation = settings.duration > 0.0 ? settings.duration / path
                             : settings.time_per_deformation > 0.0
                                 ? settings.time_per_deformation
                                 : 20.0 * run.first_axial_period / yield_deformation;
  run.min_excursion_time = settings.min_excursion_time;
  const Protocol protocol(targets, run.time_per_deformation, settings.min_excursion_time);

  // supports and the driven face (its displacement: the brace elongation, halved in a half model)
  SolidLoading loading;
  const double drive = mesh.half_length ? 0.5 : 1.0;
  for (int node : mesh.loaded_end)
    loading.prescribed.add(node, 0, drive);
  for (int node : mesh.fixed_end)
    loading.prescribed.add(node, 0, 0.0);
  for (const auto& face : {mesh.loaded_end, mesh.fixed_end}) {
    for (const auto& [node, direction] : lateral_supports(mesh.nodes, face, solid.end_faces))
      loading.prescribed.add(node, direction, 0.0);
    // pinned: the face pivots about its centre (its x DOFs, prescribed above, plus a rotation)
    if (solid.end_faces == model::SolidEndFaces::pinned && !face.empty()) {
      PivotingFace pivot{face, Eigen::Matrix2Xd(2, static_cast<Eigen::Index>(face.size()))};
      for (std::size_t i = 0; i < face.size(); ++i)
        pivot.positions.col(static_cast<Eigen::Index>(i)) = mesh.nodes.col(face[i]).tail<2>();
      loading.pivoting_faces.push_back(std::move(pivot));
    }
  }
  for (int node : mesh.symmetry_plane)
    loading.prescribed.add(node, 0, 0.0);
  loading.history = [protocol](double t) { return protocol.at(t); };

  // the lateral damping acts on y and z only: the axial loading is not slowed by it
  SolidExplicit<SolidBody> solver(
      body, loading,
      {settings.stable_step_safety, 0.0, settings.lateral_damping, {false, true, true}});
  run.lateral_damping = settings.lateral_damping;
  run.time_step = solver.time_step();
  run.nodes = body.node_count();
  run.elements = body.element_count();
  const auto record = [&](int point) {
    SolidBraceRecord r;
    r.point = point;
    r.steps = solver.steps();
    r.time = solver.time();
    // the driven face's translation, drive x history(t), over drive (1 or 1/2: exact); read
    // from the history since a pivoting face's nodes also carry its rotation
    r.deformation = loading.history(solver.time());
    for (int node : mesh.loaded_end)
      r.force += solver.internal_force()[3 * node];
    const SolidExplicitEnergy& e = solver.energy();
    r.kinetic = e.kinetic;
    r.internal = e.internal;
    r.hourglass = e.hourglass;
    r.contact_stored = e.interaction;
    r.friction = e.friction;
    r.damping = e.damping;
    r.external = e.external;
    r.energy_error = e.relative_error();
    run.records.push_back(r);
    if (observer)
      observer(SolidBraceState{body, mesh, solver.displacement(), run.records.back()});
  };
  record(0);
  for (std::size_t i = 0; i + 1 < protocol.point_times.size(); ++i) {
    const double segment_start = protocol.point_times[i];
    const double segment_duration = protocol.point_times[i + 1] - segment_start;
    for (int k = 1; k <= settings.outputs_per_segment; ++k) {
      const double t = k == settings.outputs_per_segment
                           ? protocol.point_times[i + 1]
                           : segment_start + segment_duration * k / settings.outputs_per_segment;
      if (!solver.run_to(t, run.failure)) {
        run.steps = solver.steps();
        return run;
      }
      record(static_cast<int>(i) + 1);
    }
  }
  run.steps = solver.steps();
  run.completed = true;
  return run;
}

} // namespace brb::solid
