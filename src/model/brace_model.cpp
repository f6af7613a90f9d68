#include "brb/model/brace_model.hpp"

#include "brb/analysis/static_analysis.hpp"
#include "brb/material/parameter_error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace brb::model {
namespace {

/// A mortar-only casing whose walls split (CasingSplitting) comes apart into two halves that
/// bend each about its own centroid (FiberSection::split_halves). After each commit, each
/// casing beam takes as its split fractions (phi_y, phi_z) the mean of its two end links'
/// wall damage per direction (the y faces' split frees the halves y > 0 and y < 0). The
/// damage is monotone, so are the fractions. Elements by index: a twin model gets the rule too.
void add_casing_split_coupling(Model& model, std::vector<std::size_t> beam_index,
                               std::vector<std::size_t> contact_index) {
  model.add_commit_coupling([beams = std::move(beam_index), links = std::move(contact_index)](
                                std::span<const std::unique_ptr<element::Element>> elements) {
    bool changed = false;
    for (std::size_t n = 0; n < beams.size(); ++n) {
      // the indices were taken as these elements were added (build_brace_model)
      const auto& start = static_cast<const element::CasingContact&>(*elements[links[n]]);
      const auto& end = static_cast<const element::CasingContact&>(*elements[links[n + 1]]);
      auto& beam = static_cast<CasingBeam&>(*elements[beams[n]]);
      const std::array<double, 2> present = beam.local_beam().sections().front().split_fractions();
      std::array<double, 2> fractions{};
      for (int direction = 0; direction < 2; ++direction) {
        const double damage =
            0.5 * (start.split_damage()[direction] + end.split_damage()[direction]);
        fractions[direction] = std::clamp(damage, present[direction], 1.0);
      }
      if (fractions != present) {
        beam.split_sections(fractions);
        changed = true;
      }
    }
    return changed;
  });
}

struct Zone {
  double length;
  const SectionSpec* section;
  int elements;
  bool yielding;
  bool inside_casing; ///< the yielding zone and the transition overlap (CasingSpec::overlap)
};

/// Zones from start to end. A casing overlap splits each transition zone in two: the part
/// inside the casing (next to the yielding core, with elements about as long as the core's)
/// and the rest (the transition's own element count). The split does not depend on whether
/// the casing is built, so the bare core of a spec has the same nodes as the spec.
std::vector<Zone> zones_of(const BraceSpec& spec) {
  const double overlap = spec.casing && spec.transition ? spec.casing->overlap : 0.0;
  std::vector<Zone> transition_outward; // from the yielding core outward
  if (spec.transition) {
    const ZoneSpec& transition = *spec.transition;
    if (overlap > 0.0) {
      const double core_element_length = spec.yielding_length / spec.core_elements;
      const int overlap_elements =
          std::max(1, static_cast<int>(std::lround(overlap / core_element_length)));
      transition_outward.push_back({overlap, &transition.section, overlap_elements, false, true});
    }
    if (transition.length - overlap > 0.0) {
      transition_outward.push_back(
          {transition.length - overlap, &transition.section, transition.elements, false, false});
    }
  }
  std::vector<Zone> zones;
  if (spec.connection) {
    zones.push_back({spec.connection->length, &spec.connection->section, spec.connection->elements,
                     false, false});
  }
  zones.insert(zones.end(), transition_outward.rbegin(), transition_outward.rend());
  zones.push_back({spec.yielding_length, &spec.core_section, spec.core_elements, true, true});
  zones.insert(zones.end(), transition_outward.begin(), transition_outward.end());
  if (spec.connection) {
    zones.push_back({spec.connection->length, &spec.connection->section, spec.connection->elements,
                     false, false});
  }
  return zones;
}

void check(bool condition, const std::string& field, const std::string& expected) {
  if (!condition)
    throw ParameterError(field, expected);
}

/// The sub-element waves of a station (element::HighModeWaves): they form in the core's
/// weaker bending direction (the smaller radius of gyration of its fiber mesh, the one the
/// beams bend with), across that direction's clearance.
element::HighModeWaves high_mode_waves(const SectionSpec& section,
                                       const material::SteelParameters& steel,
                                       const CasingSpec& casing, double tributary,
                                       double resolved_half_wave) {
  const section::FiberLayout layout = section.mesh();
  const double area = layout.total_area();
  const double radius_along_z = std::sqrt(layout.second_moment_y() / area); // motion along z
  const double radius_along_y = std::sqrt(layout.second_moment_z() / area); // motion along y
  const auto [extent_y, extent_z] = core_extent(section);
  element::HighModeWaves waves;
  waves.steel = steel;
  waves.area = area;
  const bool along_z = radius_along_z <= radius_along_y;
  waves.gyration_radius = along_z ? radius_along_z : radius_along_y;
  waves.thickness = along_z ? extent_z : extent_y;
  waves.gap = along_z ? casing.gap_z : casing.gap_y;
  waves.tributary_length = tributary;
  waves.resolved_half_wave = resolved_half_wave;
  waves.crest_factor = *casing.high_mode_waves;
  return waves;
}

/// Adds the casing around the yielding zone and the transition overlaps (see
/// brace_model.hpp). Stations: the core nodes of the elements inside the casing (per element:
/// `inside_casing`, and its section in `element_sections`); each gets a casing node on the
/// straight brace axis.
CasingModel add_casing(Model& model, BraceHandles& brace, const BraceSpec& spec,
                       const element::BeamIntegration& integration,
                       const std::vector<bool>& inside_casing,
                       const std::vector<const SectionSpec*>& element_sections,
                       const WorkSkips& skips) {
  const CasingSpec& casing = *spec.casing;
  check(casing.tube.shape == SectionShape::rectangular_tube ||
            casing.tube.shape == SectionShape::circular_tube,
        "casing/tube/shape", "must be rectangular_tube or circular_tube");
  check(casing.friction_coefficient >= 0.0, "casing/friction", "must be >= 0");
  check(casing.core_expansion >= 0.0 && casing.core_expansion <= 0.5, "casing/core_expansion",
        "must be in [0, 0.5] (lateral over axial strain of the core)");
  check(casing.tangential_stiffness_ratio > 0.0, "casing/tangential_stiffness_ratio",
        "must be > 0");
  check(casing.stopper_stiffness_ratio > 0.0, "casing/stopper_stiffness_ratio", "must be > 0");
  check(casing.stopper_position >= 0.0 && casing.stopper_position <= 1.0, "casing/stopper/position",
        "must be in [0, 1] (a fraction of the casing's length)");
  if (casing.steel_tube)
    casing.tube_steel.validate();
  casing.mortar.validate();
  const double transition_length = spec.transition ? spec.transition->length : 0.0;
  check(casing.overlap >= 0.0 && casing.overlap <= transition_length, "casing/overlap",
        "must be in [0, transition length] (" + std::to_string(transition_length) + " mm)");
  const element::Matrix3& axes = brace.axes;
  const element::Vector3 axis = axes.col(0);

  // stations: core nodes of the elements inside the casing, from start to end; the section
  // the mortar bears on at each (a station between a transition and a core element: the core)
  CasingModel result;
  result.steel_tube = casing.steel_tube;
  std::vector<const SectionSpec*> station_sections;
  std::vector<const SectionSpec*> segment_sections; // casing element n: stations n, n + 1
  for (std::size_t e = 0; e < brace.beams.size(); ++e) {
    if (!inside_casing[e])
      continue;
    if (result.core_nodes.empty()) {
      result.core_nodes.push_back(brace.nodes[e]);
      station_sections.push_back(element_sections[e]);
    } else if (brace.in_yielding_zone[e]) {
      station_sections.back() = &spec.core_section;
    }
    result.core_nodes.push_back(brace.nodes[e + 1]);
    station_sections.push_back(brace.in_yielding_zone[e] ? &spec.core_section
                                                         : element_sections[e]);
    segment_sections.push_back(element_sections[e]);
  }
  const std::size_t stations = result.core_nodes.size();
  std::vector<double> station_x;
  for (const int core : result.core_nodes) {
    station_x.push_back(axis.dot(model.coordinates(core) - brace.origin));
    result.nodes.push_back(model.add_node(brace.origin + station_x.back() * axis, brace.axes));
  }

  // casing beams: tube steel + mortar fill fibers, characteristic length w_k L per point
  // (a mortar-only casing has no steel fibers: an empty layout)
  const section::FiberLayout tube_layout =
      casing.steel_tube ? casing.tube.mesh() : section::FiberLayout{};
  // Without a tube the steel part of the section has no fibers; the core's steel stands in
  // for its (unused) law so that the section type stays the same.
  const material::SteelParameters& tube_steel = casing.steel_tube ? casing.tube_steel : spec.steel;
  const double tube_shear = tube_steel.youngs_modulus / (2.0 * (1.0 + tube_steel.poissons_ratio));
  const double mortar_shear =
      casing.mortar.youngs_modulus / (2.0 * (1.0 + casing.mortar.poissons_ratio));
  std::vector<std::size_t> casing_beam_index; // for the split coupling below
  for (std::size_t n = 0; n + 1 < stations; ++n) {
    const int first = result.nodes[n], second = result.nodes[n + 1];
    const double length = station_x[n + 1] - station_x[n];
    // the fill around the core, or around the transition in the overlaps
    const section::FiberLayout fill_layout = casing.fill_mesh(*segment_sections[n]);
    std::vector<CasingSection> sections;
    sections.reserve(integration.weights.size());
    for (const double weight : integration.weights) {
      material::SteelUniaxial tube_law(tube_steel, weight * length);
      tube_law.set_elastic_fast_path(skips.elastic_fast_path);
      sections.emplace_back(
          section::FiberSection<material::SteelUniaxial>(tube_layout, tube_law, tube_shear),
          section::FiberSection<material::MortarUniaxial>(
              fill_layout, material::MortarUniaxial(casing.mortar, weight * length), mortar_shear));
    }
    casing_beam_index.push_back(model.elements().size());
    result.beams.push_back(&model.add_element(std::make_unique<CasingBeam>(
        std::array<int, 2>{first, second}, model.coordinates(first), model.coordinates(second),
        axes.col(2), integration, std::move(sections))));
  }

  // contact links. A y face (normal to y) bears over the tributary length times the core's
  // extent along z; the penetration turns into strain over the mortar's thickness in that
  // direction (a plate core in a square tube has a thin and a thick side).
  const auto [core_extent_y, core_extent_z] = core_extent(spec.core_section);
  const auto [core_thickness_y, core_thickness_z] = casing.mortar_thickness(spec.core_section);
  const double layer_per_length = casing.layer_stiffness.value_or(
      CasingSpec::kDefaultLayerRatio * casing.mortar.youngs_modulus *
      std::min(core_extent_y / core_thickness_y, core_extent_z / core_thickness_z));
  check(layer_per_length >= 0.0, "casing/layer_stiffness", "must be >= 0 N/mm per mm");
  std::vector<std::size_t> contact_index;
  for (std::size_t n = 0; n < stations; ++n) {
    const auto [extent_y, extent_z] = core_extent(*station_sections[n]);
    const auto [thickness_y, thickness_z] = casing.mortar_thickness(*station_sections[n]);
    const double before = n > 0 ? station_x[n] - station_x[n - 1] : 0.0;
    const double after = n + 1 < stations ? station_x[n + 1] - station_x[n] : 0.0;
    const double tributary = 0.5 * (before + after);
    result.tributary_length.push_back(tributary);
    element::CasingContactParameters link;
    link.axes = axes;
    link.gap_y = casing.gap_y;
    link.gap_z = casing.gap_z;
    link.bearing_area_y = tributary * extent_z;
    link.bearing_area_z = tributary * extent_y;
    link.bearing_depth_y = thickness_y;
    link.bearing_depth_z = thickness_z;
    link.mortar = casing.mortar;
    link.layer_stiffness = layer_per_length * tributary;
    link.friction_coefficient = casing.friction_coefficient;
    // The stiffer face's bearing stiffness, E max(A_y / t_y, A_z / t_z), written so that it
    // rounds exactly as E max(A_y, A_z) / t when both depths are equal (the restrained core's
    // path through its mode jumps is sensitive to the last bit of this penalty; see the
    // note in tests/slow/restrained_core_test.cpp).
    const double bearing_stiffness =
        casing.mortar.youngs_modulus *
        std::max(link.bearing_area_y, link.bearing_area_z * (thickness_y / thickness_z)) /
        thickness_y;
    link.tangential_stiffness = casing.tangential_stiffness_ratio * bearing_stiffness;
    if (!casing.steel_tube && casing.splitting) {
      // the walls beside the opening (outline minus core and clearances) hold the two halves
      // that a direction's faces bear on; they stretch over the outline's extent
      const auto [outline_y, outline_z] = core_extent(casing.tube);
      element::CasingSplitting split;
      split.wall_area_y = (outline_z - extent_z - 2.0 * casing.gap_z) * tributary;
      split.wall_area_z = (outline_y - extent_y - 2.0 * casing.gap_y) * tributary;
      split.wall_length_y = outline_y;
      split.wall_length_z = outline_z;
      link.splitting = split;
    }
    const int core = result.core_nodes[n], shell = result.nodes[n];
    // The core's expansion from the chord of its neighbour stations (at an end station the
    // station itself is one end); nu_c = 0 leaves the two-node link.
    std::optional<element::CoreExpansion> expansion;
    if ((casing.core_expansion > 0.0 || casing.high_mode_waves) && stations > 1) {
      expansion.emplace();
      expansion->previous_node = result.core_nodes[n > 0 ? n - 1 : n];
      expansion->next_node = result.core_nodes[n + 1 < stations ? n + 1 : n];
      expansion->previous_position = model.coordinates(expansion->previous_node);
      expansion->next_position = model.coordinates(expansion->next_node);
      expansion->extent_y = extent_y;
      expansion->extent_z = extent_z;
      expansion->ratio = casing.core_expansion;
    }
    std::optional<element::HighModeWaves> wave_links; // they need the chord
    if (casing.high_mode_waves && expansion)
      wave_links = high_mode_waves(*station_sections[n], spec.steel, casing, tributary,
                                   2.0 * std::max(before, after));
    contact_index.push_back(model.elements().size());
    result.contacts.push_back(&model.add_element(std::make_unique<element::CasingContact>(
        std::array<int, 2>{core, shell}, model.coordinates(core), model.coordinates(shell), link,
        skips.open_links, expansion, wave_links)));
    if (n == stations / 2)
      result.interior_link = link; // mid-length: a core station
  }
  if (!casing.steel_tube && casing.splitting)
    add_casing_split_coupling(model, casing_beam_index, contact_index);

  // stopper at the station nearest its position along the casing (default: mid-length)
  const double target =
      station_x.front() + casing.stopper_position * (station_x.back() - station_x.front());
  std::size_t nearest = 0;
  for (std::size_t n = 1; n < stations; ++n) {
    if (std::abs(station_x[n] - target) < std::abs(station_x[nearest] - target))
      nearest = n;
  }
  const section::FiberLayout core_layout = spec.core_section.mesh();
  const double core_shear = spec.steel.youngs_modulus / (2.0 * (1.0 + spec.steel.poissons_ratio));
  const double ratio = casing.stopper_stiffness_ratio / spec.yielding_length;
  result.stopper_stiffness = {ratio * spec.steel.youngs_modulus * core_layout.total_area(),
                              0.0,
                              0.0,
                              ratio * core_shear * core_layout.torsion_constant,
                              0.0,
                              0.0};
  result.stopper_station = nearest;
  const int core = result.core_nodes[nearest], shell = result.nodes[nearest];
  result.stopper = &model.add_element(std::make_unique<element::ZeroLengthSpring>(
      std::array<int, 2>{core, shell}, model.coordinates(core), model.coordinates(shell),
      result.stopper_stiffness, axes));
  return result;
}

/// Places the brace in `model` along `placement` with its core nodes at `offsets` (lateral
/// section y, z per node; empty: straight). The outer nodes are `ends` when given (existing
/// nodes at the ends of the brace's axis), else new nodes.
BraceHandles place(Model& model, const BraceSpec& spec,
                   const std::vector<std::pair<double, double>>& offsets,
                   const BracePlacement& placement, std::optional<std::array<int, 2>> ends,
                   const WorkSkips& skips, bool with_casing = true) {
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

  BraceHandles brace;
  brace.origin = placement.origin;
  brace.axes = placement.axes;
  const section::FiberLayout core_layout = spec.core_section.mesh();
  brace.core_area = core_layout.total_area();
  brace.yield_force = spec.steel.yield_stress * brace.core_area;

  double x = 0.0;
  const auto add_node = [&](double position, std::optional<int> existing) {
    const std::size_t index = brace.nodes.size();
    element::Vector3 point(position, 0.0, 0.0);
    if (!offsets.empty()) {
      point.y() = offsets[index].first;
      point.z() = offsets[index].second;
    }
    brace.nodes.push_back(
        existing ? *existing
                 : model.add_node(placement.origin + placement.axes * point, placement.axes));
  };
  std::vector<bool> inside_casing;                  // per element
  std::vector<const SectionSpec*> element_sections; // per element
  const std::size_t zone_count = zones_of(spec).size();
  std::size_t zone_index = 0;
  add_node(0.0, ends ? std::optional<int>(ends->front()) : std::nullopt);
  double flexibility = 0.0; // sum L / (E A)
  bool lowered_warning_given = false;
  for (const Zone& zone : zones_of(spec)) {
    const bool last_zone = ++zone_index == zone_count;
    const section::FiberLayout layout = zone.yielding ? core_layout : zone.section->mesh();
    flexibility += zone.length / (youngs * layout.total_area());
    const double element_length = zone.length / zone.elements;
    for (int e = 0; e < zone.elements; ++e) {
      x += element_length;
      const bool outer = last_zone && e + 1 == zone.elements;
      add_node(x, outer && ends ? std::optional<int>(ends->back()) : std::nullopt);
      const int first = brace.nodes[brace.nodes.size() - 2], second = brace.nodes.back();
      std::vector<CoreSection> sections;
      sections.reserve(integration.weights.size());
      for (const double weight : integration.weights) {
        // each fiber's characteristic length: its integration weight times the element length
        material::SteelUniaxial law(spec.steel, weight * element_length);
        law.set_elastic_fast_path(skips.elastic_fast_path);
        sections.emplace_back(layout, law, shear);
        const auto& softening = sections.back().law().softening();
        if (softening && softening->strength_lowered() && !lowered_warning_given) {
          std::ostringstream warning;
          warning << "core steel: elements too long for the softening (lc = "
                  << weight * element_length
                  << " mm >= 2 Gf E / fu^2); damage onset lowered from fu = "
                  << spec.steel.damage->onset_stress << " to " << softening->onset_stress()
                  << " MPa where needed (same Gf / lc); use more core elements to avoid it";
          brace.warnings.push_back(warning.str());
          lowered_warning_given = true;
        }
      }
      brace.beams.push_back(&model.add_element(std::make_unique<CoreBeam>(
          std::array<int, 2>{first, second}, model.coordinates(first), model.coordinates(second),
          placement.axes.col(2), integration, std::move(sections))));
      brace.in_yielding_zone.push_back(zone.yielding);
      inside_casing.push_back(zone.inside_casing);
      element_sections.push_back(zone.section);
    }
  }
  brace.yield_deformation = brace.yield_force * flexibility;
  brace.start_node = brace.nodes.front();
  brace.end_node = brace.nodes.back();
  if (spec.casing && with_casing)
    brace.casing =
        add_casing(model, brace, spec, integration, inside_casing, element_sections, skips);
  return brace;
}

/// The stand-alone brace model along global x: the test set-up of `brb cyclic` (start node
/// held, end node driven along x; pinned or fixed ends).
BraceModel build(const BraceSpec& spec, const std::vector<std::pair<double, double>>& offsets,
                 const WorkSkips& skips, bool with_casing = true) {
  BraceModel brace;
  static_cast<BraceHandles&>(brace) =
      place(brace.model, spec, offsets, BracePlacement{}, {}, skips, with_casing);
  hold_stand_alone_ends(brace.model, brace.start_node, brace.end_node, spec.ends);
  return brace;
}

/// Lateral offsets (section y, z) of the core nodes from the imperfection.
std::vector<std::pair<double, double>> imperfection_offsets(const BraceSpec& spec) {
  const double total = spec.total_length();
  check(spec.imperfection.amplitude >= 0.0 && spec.imperfection.amplitude < total,
        "imperfection/amplitude",
        "must be >= 0 and shorter than the brace (" + std::to_string(total) + " mm)");
  // node x positions of a straight model, for the offsets
  BraceModel straight = build(spec, {}, WorkSkips{}, /*with_casing=*/false);
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
  return offsets;
}

} // namespace

BracePlacement BracePlacement::between(const Vector3& start, const Vector3& end,
                                       std::optional<Vector3> section_z) {
  const Vector3 chord = end - start;
  check(chord.norm() > 0.0, "element/nodes", "the outer nodes of a brace must not coincide");
  const Vector3 axis = chord.normalized();
  Vector3 z = section_z.value_or(Vector3::UnitZ());
  if (!section_z && axis.cross(z).norm() < 1e-3)
    z = Vector3::UnitY(); // a brace along global Z: its section z defaults to global Y
  z -= z.dot(axis) * axis;
  check(z.norm() > 1e-9 * std::max(1.0, section_z ? section_z->norm() : 1.0), "element/orientation",
        "the section's z direction must not be parallel to the brace axis");
  z.normalize();
  BracePlacement placement;
  placement.origin = start;
  placement.axes.col(0) = axis;
  placement.axes.col(1) = z.cross(axis);
  placement.axes.col(2) = z;
  return placement;
}

void hold_stand_alone_ends(Model& model, int start_node, int end_node, EndCondition ends) {
  for (const Dof dof : {ux, uy, uz, rx})
    model.fix(start_node, dof);
  for (const Dof dof : {uy, uz})
    model.fix(end_node, dof);
  if (ends == EndCondition::fixed) {
    for (const Dof dof : {ry, rz})
      model.fix(start_node, dof);
    for (const Dof dof : {rx, ry, rz})
      model.fix(end_node, dof);
  }
}

BraceModel build_brace_model(const BraceSpec& spec, const WorkSkips& skips) {
  return build(spec, imperfection_offsets(spec), skips);
}

element::BraceTrussParameters truss_parameters(const BraceSpec& spec) {
  check(spec.yielding_length > 0.0, "core/yielding_length", "must be > 0 mm");
  element::BraceTrussParameters parameters;
  parameters.steel = spec.steel;
  parameters.core_area = spec.core_section.mesh().total_area();
  parameters.yielding_length = spec.yielding_length;
  for (const auto* zone : {&spec.transition, &spec.connection}) {
    if (*zone) {
      parameters.end_flexibility +=
          2.0 * (*zone)->length /
          (spec.steel.youngs_modulus * (*zone)->section.mesh().total_area());
    }
  }
  return parameters;
}

BraceModel build_brace_truss_model(const BraceSpec& spec, const WorkSkips& skips) {
  const element::BraceTrussParameters parameters = truss_parameters(spec);
  BraceModel brace;
  Model& model = brace.model;
  brace.start_node = model.add_node(Vector3::Zero());
  brace.end_node = model.add_node(Vector3(spec.total_length(), 0.0, 0.0));
  brace.nodes = {brace.start_node, brace.end_node};
  brace.truss = &model.add_element(std::make_unique<element::BraceTruss>(
      std::array<int, 2>{brace.start_node, brace.end_node}, model.coordinates(brace.start_node),
      model.coordinates(brace.end_node), parameters, skips.elastic_fast_path));
  brace.core_area = parameters.core_area;
  brace.yield_force = spec.steel.yield_stress * parameters.core_area;
  brace.yield_deformation = brace.yield_force / brace.truss->elastic_stiffness();
  const auto& softening = brace.truss->law().softening();
  if (softening && softening->strength_lowered()) {
    brace.warnings.push_back("core steel: the truss's one material point spans the yielding "
                             "length, too long for the softening; damage onset lowered to " +
                             std::to_string(softening->onset_stress()) + " MPa (same Gf / lc)");
  }
  for (const Dof dof : {ux, uy, uz, rx, ry, rz})
    model.fix(brace.start_node, dof);
  for (const Dof dof : {uy, uz, rx, ry, rz})
    model.fix(brace.end_node, dof);
  return brace;
}

BraceHandles add_brace_to_model(Model& model, const BraceSpec& spec, int start_node, int end_node,
                                std::optional<Vector3> section_z, const WorkSkips& skips) {
  check(start_node >= 0 && start_node < model.node_count() && end_node >= 0 &&
            end_node < model.node_count() && start_node != end_node,
        "element/nodes", "two distinct nodes of the model");
  const BracePlacement placement = BracePlacement::between(model.coordinates(start_node),
                                                           model.coordinates(end_node), section_z);
  const double distance = (model.coordinates(end_node) - model.coordinates(start_node)).norm();
  const double total = spec.total_length();
  check(std::abs(distance - total) <= 1e-9 * total, "element/nodes",
        "the outer nodes must be the brace's length apart (" + std::to_string(total) + " mm; got " +
            std::to_string(distance) + " mm)");
  return place(model, spec, imperfection_offsets(spec), placement,
               std::array<int, 2>{start_node, end_node}, skips);
}

std::vector<std::pair<double, double>> first_buckling_mode(const BraceSpec& spec) {
  // Linearised buckling of the perfect brace: K0 phi = lambda (K0 - K1) phi, with K1 the
  // tangent under a small elastic shortening; the geometric stiffness is linear in the
  // axial force for such a small step. The first mode has the largest 1/lambda.
  BraceModel brace = build(spec, {}, WorkSkips{}, /*with_casing=*/false);
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
