// Straight beam models for verification tests.
#pragma once

#include "brb/element/corot_beam_3d.hpp"
#include "brb/model/model.hpp"
#include "brb/section/elastic_section.hpp"

#include <memory>
#include <vector>

namespace brb::test {

using ElasticBeam = element::CorotBeam3D<section::ElasticSection>;

/// Nodes 0..n along the global x axis from `start`, n elastic co-rotational elements
/// (Gauss-Lobatto, 3 points). Local z of the elements along global z.
inline std::vector<ElasticBeam*>
add_elastic_beam(model::Model& model, const element::Vector3& start, double length, int elements,
                 const section::ElasticSectionProperties& properties, int first_node = -1) {
  std::vector<ElasticBeam*> beams;
  int previous = first_node >= 0 ? first_node : model.add_node(start);
  const auto integration =
      element::BeamIntegration::make(element::IntegrationRule::gauss_lobatto, 3);
  for (int e = 1; e <= elements; ++e) {
    const element::Vector3 position = start + element::Vector3(length * e / elements, 0.0, 0.0);
    const int node = model.add_node(position);
    std::vector<section::ElasticSection> sections(integration.weights.size(),
                                                  section::ElasticSection(properties));
    beams.push_back(&model.add_element(std::make_unique<ElasticBeam>(
        std::array<int, 2>{previous, node}, model.coordinates(previous), position,
        element::Vector3(0.0, 0.0, 1.0), integration, std::move(sections))));
    previous = node;
  }
  return beams;
}

} // namespace brb::test
