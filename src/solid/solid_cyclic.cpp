// A virtual cyclic test of the 3D continuum brace (see solid_cyclic.hpp).
#include "brb/solid/solid_cyclic.hpp"

#include "brb/analysis/brace_indicators.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/solid/node_to_surface_contact.hpp"
#include "brb/solid/solid_body.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <set>

namespace brb::solid {

namespace {

using Steel = material::SteelDamagePlasticity3D;
using Mortar = material::MortarDamage3D;

const SolidPartOf<Steel>* steel_part(const SolidBody& body, const std::string& name) {
  for (const auto& part : body.parts())
    if (part->name() == name)
      return dynamic_cast<const SolidPartOf<Steel>*>(part.get());
  return nullptr;
}

const SolidPartOf<Mortar>* mortar_part(const SolidBody& body) {
  for (const auto& part : body.parts())
    if (part->name() == "mortar")
      return dynamic_cast<const SolidPartOf<Mortar>*>(part.get());
  return nullptr;
}

/// Local indices of the mortar elements that have a face among the casing's contact faces.
std::vector<int> bearing_elements(const BraceMesh& mesh) {
  std::set<std::array<int, 4>> faces;
  for (const QuadFace& face : mesh.casing_faces) {
    std::array<int, 4> sorted{face[0], face[1], face[2], face[3]};
    std::sort(sorted.begin(), sorted.end());
    faces.insert(sorted);
  }
  // the six faces of a hexahedron in the order of hex_mesh.hpp
  static constexpr std::array<std::array<int, 4>, 6> kHexFaces{
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  std::vector<int> bearing;
  const HexMesh& mortar = mesh.mortar.mesh;
  for (int e = 0; e < mortar.element_count(); ++e) {
    for (const auto& local_face : kHexFaces) {
      std::array<int, 4> global{};
      for (int k = 0; k < 4; ++k)
        global[k] = mesh.mortar.global_nodes[mortar.elements[e][local_face[k]]];
      std::sort(global.begin(), global.end());
      if (faces.contains(global)) {
        bearing.push_back(e);
        break;
      }
    }
  }
  return bearing;
}

/// Normal penalty per unit area: E_c over the mortar element's thickness across the ring.
double contact_penalty(const model::BraceSpec& brace, const model::SolidMeshSpec& solid,
                       double factor) {
  const model::CasingSpec& casing = *brace.casing;
  const auto [thickness_y, thickness_z] = casing.mortar_thickness(brace.core_section);
  const double element = std::min(thickness_y, thickness_z) / solid.elements_through_mortar;
  return factor * casing.mortar.youngs_modulus / element;
}

/// The indicators of a state (solid_cyclic.hpp), folded into the running ones.
class SolidIndicatorTracker {
public:
  SolidIndicatorTracker(const model::BraceSpec& brace, const BraceMesh& mesh, double yield_force,
                        double yield_deformation)
      : yield_force_(yield_force), yield_deformation_(yield_deformation) {
    if (brace.casing) {
      const double clearance = std::max(brace.casing->gap_y, brace.casing->gap_z);
      bow_limit_ = brace.yielding_length / analysis::kGlobalBucklingRatio + clearance;
      bearing_ = bearing_elements(mesh);
    }
    std::vector<char> core_node(static_cast<std::size_t>(mesh.nodes.cols()), 0);
    for (int node : mesh.core.global_nodes)
      core_node[static_cast<std::size_t>(node)] = 1;
    for (int node = 0; node < static_cast<int>(mesh.nodes.cols()); ++node)
      (core_node[static_cast<std::size_t>(node)] ? core_nodes_ : casing_nodes_).push_back(node);
  }

  /// Largest lateral motion of any node (mm).
  double observe(const SolidBraceState& state) {
    BraceIndicators& ind = indicators_;
    const auto lateral = [&](const std::vector<int>& nodes) {
      double largest = 0.0;
      for (int node : nodes)
        largest = std::max(largest, state.displacement.segment<2>(3 * node + 1).norm());
      return largest;
    };
    const double core_lateral = lateral(core_nodes_);
    const double casing_lateral = lateral(casing_nodes_);
    ind.max_core_lateral_displacement = std::max(ind.max_core_lateral_displacement, core_lateral);
    ind.max_casing_lateral_displacement =
        std::max(ind.max_casing_lateral_displacement, casing_lateral);
    if (bow_limit_ > 0.0 && casing_lateral > bow_limit_)
      ind.global_buckling = true;
    if (const auto* core = steel_part(state.body, "core"))
      for (const auto& element : core->model().states())
        ind.max_steel_damage = std::max(ind.max_steel_damage, element.damage);
    if (ind.max_steel_damage >= analysis::kFractureDamage)
      ind.core_fracture = true;
    if (const auto* mortar = mortar_part(state.body)) {
      const auto& states = mortar->model().states();
      const auto& laws = mortar->model().laws(); // one per element: its own lc
      for (std::size_t e = 0; e < states.size(); ++e) {
        ind.max_mortar_damage = std::max(ind.max_mortar_damage, states[e].damage);
        ind.min_fill_residual_strength =
            std::min(ind.min_fill_residual_strength, laws[e].residual_strength(states[e]));
      }
      for (int e : bearing_) {
        const auto element = static_cast<std::size_t>(e);
        ind.max_bearing_damage = std::max(ind.max_bearing_damage, states[element].damage);
        ind.min_bearing_residual_strength = std::min(
            ind.min_bearing_residual_strength, laws[element].residual_strength(states[element]));
      }
      // as the reduced model's rule (BraceIndicators): the mortar bounding the core cracked or
      // crushed through
      if (ind.min_bearing_residual_strength <= analysis::kCrushedResidualStrength)
        ind.casing_failure = true;
    }
    if (has_previous_)
      ind.cumulative_inelastic_deformation += analysis::inelastic_deformation_increment(
          state.record.deformation - previous_deformation_, state.record.force - previous_force_,
          yield_force_, yield_deformation_);
    has_previous_ = true;
    previous_deformation_ = state.record.deformation;
    previous_force_ = state.record.force;
    return std::max(core_lateral, casing_lateral);
  }

  const analysis::BraceIndicators& indicators() const { return indicators_; }

private:
  using BraceIndicators = analysis::BraceIndicators;
  double yield_force_, yield_deformation_;
  double bow_limit_ = 0.0;
  std::vector<int> bearing_;
  std::vector<int> core_nodes_, casing_nodes_;
  BraceIndicators indicators_;
  bool has_previous_ = false;
  double previous_deformation_ = 0.0, previous_force_ = 0.0;
};

} // namespace

SolidCyclicResult run_solid_cyclic(const model::BraceSpec& brace,
                                   std::span<const double> deformation, std::span<const int> cycle,
                                   std::span<const double> cycle_amplitude, double yield_force,
                                   double yield_deformation, const SolidCyclicSettings& settings,
                                   const SolidBraceObserver& observer) {
  if (deformation.size() < 2 || cycle.size() != deformation.size())
    throw std::invalid_argument("solid cyclic test: the protocol needs at least one point after "
                                "the initial 0 and one cycle number per point");
  if (!(settings.contact_penalty_factor > 0.0))
    throw std::invalid_argument("solid cyclic test: the contact penalty factor must be > 0");
  const model::SolidMeshSpec solid = brace.solid.value_or(model::SolidMeshSpec{});

  SolidCyclicResult result;
  result.quasi_static_floor = kQuasiStaticFloorFraction * 0.5 * yield_force * yield_deformation;
  ContactFactory contact = nullptr;
  if (brace.casing) {
    NodeToSurfaceContactSettings contact_settings;
    contact_settings.normal_penalty =
        contact_penalty(brace, solid, settings.contact_penalty_factor);
    contact_settings.tangential_stiffness_ratio = 1.0;
    contact_settings.friction_coefficient = brace.casing->friction_coefficient;
    const auto [core_y, core_z] = model::core_extent(brace.core_section);
    contact_settings.search_distance = std::max(brace.casing->gap_y, brace.casing->gap_z) +
                                       std::min(core_y, core_z) / solid.elements_across_core;
    contact_settings.two_pass = true;
    result.contact_penalty = contact_settings.normal_penalty;
    const int threads = solid.threads;
    contact = [contact_settings, threads](const std::vector<QuadFace>& core_faces,
                                          const std::vector<QuadFace>& casing_faces,
                                          const Eigen::Matrix3Xd& coordinates) {
      // the core is the master surface (BRB_SOURCE_FACTS section 4)
      auto pair = std::make_unique<NodeToSurfaceContact>(coordinates, casing_faces, core_faces,
                                                         contact_settings);
      pair->set_threads(threads);
      return pair;
    };
  }

  analysis::CyclicTestResult& cyclic = result.cyclic;
  cyclic.steps.push_back({0, cycle[0], 0.0, 0.0, 0.0, 0});
  analysis::HysteresisAccumulator hysteresis(cyclic);
  std::optional<SolidIndicatorTracker> tracker;
  long previous_steps = 0;
  const int outputs = settings.run.outputs_per_segment;
  const auto record = [&](const SolidBraceState& state) {
    if (!tracker)
      tracker.emplace(brace, state.mesh, yield_force, yield_deformation);
    const double lateral = tracker->observe(state);
    const SolidBraceRecord& r = state.record;
    // Ratios are judged once the internal energy is a measurable part of the brace's: at the
    // start of a smooth ramp u ~ t^3, so KE / IE ~ (3 / t)^2 m / k grows without bound as
    // t -> 0 however slow the loading (see quasi_static_floor in the header).
    if (r.internal > result.quasi_static_floor) {
      result.max_kinetic_ratio = std::max(result.max_kinetic_ratio, r.kinetic / r.internal);
      // |.|: a negative hourglass work would be energy the control made, as bad as a large one
      result.max_hourglass_ratio =
          std::max(result.max_hourglass_ratio, std::abs(r.hourglass) / r.internal);
    }
    result.max_energy_error = std::max(result.max_energy_error, r.energy_error);
    if (r.point > 0) {
      const int step = static_cast<int>(cyclic.steps.size());
      const int point_cycle = cycle[static_cast<std::size_t>(r.point)];
      // the last output of the segment ends the cycle when the next point is in another one
      const bool segment_ends = (step - 1) % outputs == outputs - 1;
      const bool cycle_ends =
          segment_ends && (static_cast<std::size_t>(r.point) + 1 == deformation.size() ||
                           cycle[static_cast<std::size_t>(r.point) + 1] != point_cycle);
      hysteresis.append({step, point_cycle, r.deformation, r.force, lateral,
                         static_cast<int>(r.steps - previous_steps)},
                        cycle_ends, cycle_amplitude);
      // The element history of brb cyclic --histories: the core strain as the brace's
      // deformation over the yielding length (the 3D mesh has no yielding-zone chord; the end
      // zones' elastic share is neglected), the dissipation as in the energy balance below.
      cyclic.history.push_back({step, r.deformation / brace.yielding_length,
                                r.internal + r.friction, tracker->indicators()});
    }
    previous_steps = r.steps;
    if (observer)
      observer(state);
  };
  result.run =
      run_solid_brace(brace, std::vector<double>(deformation.begin() + 1, deformation.end()),
                      settings.run, contact, record);
  cyclic.completed = result.run.completed;
  cyclic.stop_reason = result.run.completed ? "" : result.run.failure;
  cyclic.substeps = static_cast<int>(std::min<long>(result.run.steps, 2147483647L));
  if (tracker)
    cyclic.indicators = tracker->indicators();
  // The energy balance in the reduced model's terms: external work, stored (kinetic, elastic
  // and hourglass; contact springs), dissipated (the rest of the internal work, friction) and
  // released in jumps: what the lateral damping took, the energy of the snaps it calms (the
  // reduced model's regularisation absorbs the same; a little of it is the viscous work of the
  // slow lateral motions).
  if (!result.run.records.empty()) {
    const SolidBraceRecord& last = result.run.records.back();
    cyclic.energy_balance.external_work = last.external;
    cyclic.energy_balance.stored = last.kinetic + last.hourglass + last.contact_stored;
    cyclic.energy_balance.dissipated = last.internal + last.friction;
    cyclic.energy_balance.released_in_jumps = last.damping;
    // gross work over the outputs: the scale of the balance, as the reduced test's sum of
    // |work of a step| (a cyclic run's net work after elastic cycles is close to zero)
    double previous_external = 0.0;
    for (const SolidBraceRecord& r : result.run.records) {
      cyclic.energy_balance.gross_work += std::abs(r.external - previous_external);
      previous_external = r.external;
    }
  }
  return result;
}

SolidElementFields element_fields(const SolidBody& body) {
  SolidElementFields fields;
  for (std::size_t p = 0; p < body.parts().size(); ++p) {
    const SolidPart& part = *body.parts()[p];
    if (const auto* steel = dynamic_cast<const SolidPartOf<Steel>*>(&part)) {
      for (const auto& state : steel->model().states()) {
        fields.steel_damage.push_back(state.damage);
        fields.mortar_damage.push_back(0.0);
        fields.plastic_strain.push_back(state.equivalent_plastic_strain);
        fields.part.push_back(static_cast<double>(p));
      }
    } else if (const auto* mortar = dynamic_cast<const SolidPartOf<Mortar>*>(&part)) {
      for (const auto& state : mortar->model().states()) {
        fields.steel_damage.push_back(0.0);
        fields.mortar_damage.push_back(state.damage);
        fields.plastic_strain.push_back(0.0);
        fields.part.push_back(static_cast<double>(p));
      }
    } else {
      for (int e = 0; e < part.element_count(); ++e) {
        fields.steel_damage.push_back(0.0);
        fields.mortar_damage.push_back(0.0);
        fields.plastic_strain.push_back(0.0);
        fields.part.push_back(static_cast<double>(p));
      }
    }
  }
  return fields;
}

std::vector<double> contact_pressure(const SolidBody& body) {
  std::vector<double> pressure(static_cast<std::size_t>(body.node_count()), 0.0);
  for (const auto& interaction : body.interactions()) {
    const auto* contact = dynamic_cast<const NodeToSurfaceContact*>(interaction.get());
    if (contact == nullptr)
      continue;
    const double penalty = contact->settings().normal_penalty;
    for (int pass = 0; pass < contact->pass_count(); ++pass) {
      const std::vector<int>& nodes = contact->slave_nodes(pass);
      const std::vector<double>& stiffness = contact->normal_stiffness(pass);
      const std::vector<NodeContactState>& states = contact->states(pass);
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        // k_N = penalty x area / passes: in two-pass mode each pass carries about half of
        // the contact, so the pressure is the pass's force x passes over the area
        const double passes = contact->pass_count();
        const double area = stiffness[i] / penalty * passes;
        if (!(area > 0.0))
          continue;
        // a node in a concave corner presses on each of its faces: the largest pressure
        double& p = pressure[static_cast<std::size_t>(nodes[i])];
        for (int k = 0; k < states[i].contact_count; ++k)
          p = std::max(p, states[i].contact(k).normal_force * passes / area);
      }
    }
  }
  return pressure;
}

} // namespace brb::solid
