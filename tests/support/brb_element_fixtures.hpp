// Helpers for driving a condensed BRBElement: outer-node configurations and a global model
// holding one element, set up like the stand-alone brace of build_brace_model.
#pragma once

#include "brb/analysis/brb_element.hpp"
#include "brb/analysis/static_analysis.hpp"
#include "brb/element/rotation.hpp"
#include "brb/model/model.hpp"

#include <array>
#include <memory>
#include <optional>

namespace brb::test {

/// A global model with the two outer nodes of a brace along x (start at the origin), held as
/// build_brace_model holds its ends (pinned: start ux uy uz rx, end uy uz), and one
/// condensed BRBElement between them.
struct CondensedBraceModel {
  model::Model model;
  int start_node = 0;
  int end_node = 0;
  analysis::BRBElement* element = nullptr;
};

inline std::unique_ptr<CondensedBraceModel>
condensed_brace_model(const model::BraceSpec& spec, analysis::NewtonSettings settings = {}) {
  auto result = std::make_unique<CondensedBraceModel>();
  model::Model& model = result->model;
  result->start_node = model.add_node(element::Vector3::Zero());
  result->end_node = model.add_node(element::Vector3(spec.total_length(), 0.0, 0.0));
  result->element = &model.add_element(std::make_unique<analysis::BRBElement>(
      std::array<int, 2>{result->start_node, result->end_node},
      model.coordinates(result->start_node), model.coordinates(result->end_node), spec,
      std::nullopt, settings));
  for (const model::Dof dof : {model::ux, model::uy, model::uz, model::rx})
    model.fix(result->start_node, dof);
  for (const model::Dof dof : {model::uy, model::uz})
    model.fix(result->end_node, dof);
  if (spec.ends == model::EndCondition::fixed) {
    for (const model::Dof dof : {model::ry, model::rz})
      model.fix(result->start_node, dof);
    for (const model::Dof dof : {model::rx, model::ry, model::rz})
      model.fix(result->end_node, dof);
  }
  return result;
}

/// Outer-node configurations of a brace from `start` along the axes `axes` (columns: axis,
/// section y, section z): the start node at rest, the end node moved by `end_motion` and
/// turned by `end_spin` (both in the brace's axes).
inline std::array<element::NodeConfiguration, 2>
outer_configuration(const element::Vector3& start, const element::Matrix3& axes, double length,
                    const element::Vector3& end_motion, const element::Vector3& end_spin) {
  std::array<element::NodeConfiguration, 2> nodes;
  nodes[0].position = start;
  nodes[1].position = start + axes * (element::Vector3(length, 0.0, 0.0) + end_motion);
  nodes[1].rotation = element::rotation_from_vector(axes * end_spin);
  return nodes;
}

} // namespace brb::test
