#include "brb/frame/frame_builder.hpp"

#include <variant>

#include "brb/element/frame_element_specs.hpp"
#include "brb/io/input_error.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/model/brace_fidelity.hpp"
#include "brb/model/brace_model.hpp"

#include <memory>
#include <unordered_map>

namespace brb::frame {

namespace {

using model::Dof;
using model::kDofPerNode;

class Builder {
public:
  Builder(const model::FrameSpec& spec, const std::string& source, BraceOverride braces,
          const model::WorkSkips& skips)
      : spec_(spec), source_(source), braces_(braces), skips_(skips) {}

  FrameModel build() {
    frame_.title = spec_.title;
    frame_.dimension = static_cast<int>(spec_.dimension);
    model::Model& model = *frame_.model;
    for (const model::FrameNodeSpec& node : spec_.nodes) {
      index_[node.id] = model.add_node(node.coordinates);
      frame_.node_ids.push_back(node.id);
    }
    for (const model::SupportSpec& support : spec_.supports) {
      for (int dof = 0; dof < kDofPerNode; ++dof) {
        if (support.fixed[dof])
          model.fix(node(support.node), static_cast<Dof>(dof));
      }
    }
    for (const model::NodalMassSpec& mass : spec_.masses)
      model.add_mass(node(mass.node), mass.mass);
    for (const model::EqualDofConstraint& constraint : spec_.equal_dofs)
      model.add_equal_dof({node(constraint.master), node(constraint.slave), constraint.dofs});
    for (const model::RigidDiaphragmConstraint& diaphragm : spec_.rigid_diaphragms) {
      model::RigidDiaphragmConstraint translated{node(diaphragm.master), {}};
      for (const int slave : diaphragm.slaves)
        translated.slaves.push_back(node(slave));
      model.add_rigid_diaphragm(std::move(translated));
    }
    for (std::size_t e = 0; e < spec_.elements.size(); ++e) {
      const model::FrameElementSpec& element = spec_.elements[e];
      try {
        std::visit([&](const auto& kind) { add(element, kind); }, element.kind);
      } catch (const ParameterError& error) {
        throw io::InputError(source_, "/elements/" + std::to_string(e),
                             "element " + std::to_string(element.id) + ": " + error.field() + ": " +
                                 error.what());
      }
    }
    for (int n = 0; n < model.node_count(); ++n) {
      if (model.is_fixed(n, model::ux) || model.is_fixed(n, model::uy) ||
          model.is_fixed(n, model::uz))
        frame_.support_nodes.push_back(n);
    }
    gravity();
    for (const model::StorySpec& story : spec_.stories) {
      const int bottom = node(story.bottom), top = node(story.top);
      frame_.stories.push_back(
          {story.name, bottom, top, model.coordinates(top).z() - model.coordinates(bottom).z()});
    }
    for (const model::FloorSpec& floor : spec_.floors)
      frame_.floors.push_back({floor.name, node(floor.node)});
    return std::move(frame_);
  }

private:
  int node(int id) const { return index_.at(id); }

  std::array<int, 2> nodes(const model::FrameElementSpec& element) const {
    return {node(element.nodes[0]), node(element.nodes[1])};
  }

  template <class ElementType>
  void place(const model::FrameElementSpec& element, std::unique_ptr<ElementType> built,
             bool damped) {
    frame_.model->add_element(std::move(built));
    frame_.element_ids.push_back(element.id);
    frame_.in_stiffness_damping.push_back(damped);
  }

  const element::Vector3& position(int index) const { return frame_.model->coordinates(index); }

  void add(const model::FrameElementSpec& element, const model::ElasticBeamSpec& beam) {
    element::ElasticBeamColumnSpec built;
    built.nodes = nodes(element);
    built.section = beam.section;
    built.orientation = beam.orientation;
    built.geometry = beam.geometry;
    place(element,
          element::make_elastic_beam_column(built, position(built.nodes[0]),
                                            position(built.nodes[1])),
          true);
  }

  void add(const model::FrameElementSpec& element, const model::TrussSpec& truss) {
    element::TrussSpec built;
    built.nodes = nodes(element);
    built.area = truss.area;
    built.material = truss.material.law;
    place(element, element::make_truss(built, position(built.nodes[0]), position(built.nodes[1])),
          true);
  }

  void add(const model::FrameElementSpec& element, const model::SpringSpec& spring) {
    element::UniaxialSpringSpec built;
    built.nodes = nodes(element);
    for (int dof = 0; dof < kDofPerNode; ++dof) {
      if (spring.dofs[dof])
        built.dofs[dof] = element::SpringDofSpec{spring.dofs[dof]->law, 1.0, 1.0};
    }
    place(element,
          element::make_uniaxial_spring(built, position(built.nodes[0]), position(built.nodes[1])),
          true);
  }

  void add(const model::FrameElementSpec& element, const model::FiberBeamSpec& beam) {
    // A chain of `subdivisions` co-rotational fiber beams (the brace core's element type),
    // through new nodes on the straight member.
    const auto [first, last] = nodes(element);
    const element::Vector3 start = position(first), end = position(last);
    const element::Vector3 orientation =
        beam.orientation.value_or(element::default_orientation(start, end));
    const auto integration =
        element::BeamIntegration::make(beam.integration_rule, beam.integration_points);
    beam.steel.validate();
    const section::FiberLayout layout = beam.section.mesh();
    const double shear = beam.steel.youngs_modulus / (2.0 * (1.0 + beam.steel.poissons_ratio));
    const double element_length = (end - start).norm() / beam.subdivisions;
    int previous = first;
    for (int k = 1; k <= beam.subdivisions; ++k) {
      const int next =
          k == beam.subdivisions
              ? last
              : frame_.model->add_node(start + (end - start) *
                                                   (static_cast<double>(k) / beam.subdivisions));
      if (k < beam.subdivisions)
        frame_.node_ids.push_back(-element.id); // an internal node of element `id`
      std::vector<model::CoreSection> sections;
      for (const double weight : integration.weights) {
        material::SteelUniaxial law(beam.steel, weight * element_length);
        law.set_elastic_fast_path(skips_.elastic_fast_path);
        sections.emplace_back(layout, law, shear);
      }
      place(element,
            std::make_unique<model::CoreBeam>(std::array<int, 2>{previous, next},
                                              position(previous), position(next), orientation,
                                              integration, std::move(sections)),
            true);
      previous = next;
    }
  }

  void add(const model::FrameElementSpec& element, const model::BraceElementSpec& brace) {
    BraceReference reference;
    reference.id = element.id;
    model::Fidelity fidelity = model::Fidelity::full;
    model::BraceFidelity asked = brace.fidelity;
    switch (braces_) {
    case BraceOverride::none:
      break;
    case BraceOverride::elastic:
      add_elastic_brace(element, brace);
      return;
    case BraceOverride::truss:
      asked = model::BraceFidelity::truss;
      break;
    case BraceOverride::full:
      asked = model::BraceFidelity::full;
      break;
    case BraceOverride::automatic:
      asked = model::BraceFidelity::automatic;
      break;
    }
    switch (asked) {
    case model::BraceFidelity::truss:
      fidelity = model::Fidelity::truss;
      break;
    case model::BraceFidelity::full:
      break;
    case model::BraceFidelity::automatic: {
      if (!skips_.auto_fidelity) {
        // WorkSkips::auto_fidelity off: no brace is let off as a truss
        reference.fidelity_reason = "auto: full (the auto skip is switched off)";
        break;
      }
      const model::FidelityChoice choice = model::choose_auto_fidelity(brace.brace);
      fidelity = choice.fidelity;
      reference.fidelity_reason = "auto: " + choice.reason;
      break;
    }
    }
    const auto [start, end] = nodes(element);
    const element::BraceTrussParameters truss = model::truss_parameters(brace.brace);
    reference.yield_force = brace.brace.steel.yield_stress * truss.core_area;
    if (fidelity == model::Fidelity::truss) {
      auto built =
          std::make_unique<element::BraceTruss>(std::array<int, 2>{start, end}, position(start),
                                                position(end), truss, skips_.elastic_fast_path);
      reference.truss = built.get();
      reference.yield_deformation = reference.yield_force / built->elastic_stiffness();
      reference.fidelity = "truss";
      place(element, std::move(built), false);
    } else {
      if (brace.mode == model::ElementMode::expanded)
        throw ParameterError("mode", "an expanded brace is not available in frames yet: use "
                                     "\"mode\": \"condensed\"");
      auto built = std::make_unique<analysis::BRBElement>(
          std::array<int, 2>{start, end}, position(start), position(end), brace.brace,
          brace.orientation, analysis::NewtonSettings{}, skips_);
      reference.full = built.get();
      reference.yield_deformation = built->internal_brace().yield_deformation;
      reference.fidelity = "full";
      place(element, std::move(built), false);
    }
    reference.element = static_cast<int>(frame_.model->elements().size()) - 1;
    frame_.braces.push_back(reference);
  }

  /// An elastic truss of the brace's series axial stiffness K = 1 / sum L_i / (E A_i).
  void add_elastic_brace(const model::FrameElementSpec& element,
                         const model::BraceElementSpec& brace) {
    const auto [start, end] = nodes(element);
    const element::BraceTrussParameters truss = model::truss_parameters(brace.brace);
    const element::BraceTruss reference({start, end}, position(start), position(end), truss);
    element::TrussSpec built;
    built.nodes = {start, end};
    built.area = truss.core_area;
    built.material = element::ElasticLawParameters{
        reference.elastic_stiffness() * (position(end) - position(start)).norm() / truss.core_area};
    place(element, element::make_truss(built, position(start), position(end)), true);
  }

  void gravity() {
    frame_.gravity_load = Eigen::VectorXd::Zero(frame_.model->dof_count());
    if (!spec_.gravity)
      return;
    frame_.gravity_steps = spec_.gravity->steps;
    for (const model::NodalLoadSpec& load : spec_.gravity->loads) {
      for (int dof = 0; dof < kDofPerNode; ++dof)
        frame_.gravity_load[kDofPerNode * node(load.node) + dof] += load.force[dof];
    }
    if (spec_.gravity->from_masses) {
      for (int n = 0; n < frame_.model->node_count(); ++n)
        frame_.gravity_load[kDofPerNode * n + model::uz] -=
            frame_.model->mass(n)[model::uz] * model::kStandardGravity;
    }
  }

  const model::FrameSpec& spec_;
  const std::string& source_;
  BraceOverride braces_;
  model::WorkSkips skips_;
  FrameModel frame_;
  std::unordered_map<int, int> index_;
};

} // namespace

FrameRunOptions run_options_of(const model::FrameSpec& spec) {
  FrameRunOptions options;
  switch (spec.analysis.integrator) {
  case model::Integrator::newmark:
    options.integrator = Integrator::newmark;
    break;
  case model::Integrator::hht:
    options.integrator = Integrator::hht;
    break;
  case model::Integrator::explicit_central_difference:
    options.integrator = Integrator::explicit_central_difference;
    break;
  }
  options.hht_alpha = spec.analysis.alpha;
  options.dt = spec.analysis.dt.value_or(0.0);
  options.free_vibration = spec.analysis.free_vibration;
  options.drift_limit = spec.analysis.drift_limit;
  if (!spec.damping) {
    options.damping.kind = DampingOptions::Kind::none;
  } else if (const auto* rayleigh = std::get_if<model::RayleighDampingSpec>(&*spec.damping)) {
    options.damping.kind = DampingOptions::Kind::rayleigh;
    options.damping.mode_i = rayleigh->modes[0];
    options.damping.mode_j = rayleigh->modes[1];
    options.damping.ratio_i = rayleigh->ratios[0];
    options.damping.ratio_j = rayleigh->ratios[1];
    options.damping.exclude_braces = rayleigh->exclude_braces;
  } else {
    const auto& modal = std::get<model::ModalDampingSpec>(*spec.damping);
    options.damping.kind = DampingOptions::Kind::modal;
    options.damping.modal_ratio = modal.ratio;
    options.damping.modal_modes = modal.modes;
  }
  options.recorders.drifts = spec.recorders.drifts;
  options.recorders.floor_accelerations = spec.recorders.floor_accelerations;
  options.recorders.base_shear = spec.recorders.base_shear;
  options.recorders.energy = spec.recorders.energy;
  options.recorders.braces = spec.recorders.brace_ids;
  options.directions.clear();
  for (const model::GroundDirection direction : spec.ground_directions)
    options.directions.push_back(direction == model::GroundDirection::x ? Eigen::Vector3d::UnitX()
                                 : direction == model::GroundDirection::y
                                     ? Eigen::Vector3d::UnitY()
                                     : Eigen::Vector3d::UnitZ());
  return options;
}

std::optional<BraceOverride> brace_override_named(std::string_view text) {
  for (const BraceOverride braces : {BraceOverride::elastic, BraceOverride::truss,
                                     BraceOverride::full, BraceOverride::automatic}) {
    if (brace_override_name(braces) == text)
      return braces;
  }
  return std::nullopt;
}

std::string_view brace_override_name(BraceOverride braces) {
  switch (braces) {
  case BraceOverride::none:
    return "none";
  case BraceOverride::elastic:
    return "elastic";
  case BraceOverride::truss:
    return "truss";
  case BraceOverride::full:
    return "full";
  case BraceOverride::automatic:
    return "auto";
  }
  return "none";
}

FrameModel build_frame(const model::FrameSpec& spec, const std::string& source,
                       BraceOverride braces, const model::WorkSkips& skips) {
  return Builder(spec, source, braces, skips).build();
}

} // namespace brb::frame
