#include "brb/model/assembler.hpp"

#include "brb/element/rotation.hpp"

#include <algorithm>

namespace brb::model {

Assembler::Assembler(const Model& model, const DofMap& map, int threads)
    : model_(model), map_(map), evaluations_(threads) {
  full_force_ = Eigen::VectorXd::Zero(model.dof_count());
  reduced_force_ = Eigen::VectorXd::Zero(map.equation_count());
  tangent_.resize(map.equation_count(), map.equation_count());
  evaluated_.assign(model.elements().size(), false);
}

bool Assembler::assemble(std::span<const element::NodeConfiguration> nodes, bool with_tangent,
                         std::string& failure, const std::vector<bool>* include) {
  full_force_.setZero();
  force_scale_ = 0.0;
  if (with_tangent)
    triplets_.clear();
  if (!evaluations_.evaluate(model_, nodes, with_tangent, failure, include))
    return false;
  const auto elements = model_.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    evaluated_[e] = include == nullptr || (*include)[e];
    if (!evaluated_[e])
      continue;
    const auto element_node_ids = elements[e]->nodes();
    const Eigen::VectorXd& element_force = evaluations_.force(e);
    const Eigen::MatrixXd& element_tangent = evaluations_.tangent(e);
    force_scale_ = std::max(force_scale_, element_force.lpNorm<Eigen::Infinity>());
    const int element_dofs = static_cast<int>(element_node_ids.size()) * kDofPerNode;
    for (int a = 0; a < element_dofs; ++a) {
      const int row = kDofPerNode * element_node_ids[a / kDofPerNode] + a % kDofPerNode;
      full_force_[row] += element_force[a];
      if (!with_tangent)
        continue;
      const auto row_terms = map_.terms(row);
      if (row_terms.empty())
        continue;
      for (int b = 0; b < element_dofs; ++b) {
        const double value = element_tangent(a, b);
        if (value == 0.0)
          continue;
        const int column = kDofPerNode * element_node_ids[b / kDofPerNode] + b % kDofPerNode;
        for (const DofTerm& row_term : row_terms) {
          for (const DofTerm& column_term : map_.terms(column))
            triplets_.emplace_back(row_term.equation, column_term.equation,
                                   row_term.factor * value * column_term.factor);
        }
      }
    }
  }
  reduced_force_ = map_.reduce(full_force_);
  if (with_tangent)
    tangent_.setFromTriplets(triplets_.begin(), triplets_.end());
  return true;
}

element::ElementEnergy Assembler::energy() const {
  element::ElementEnergy total;
  const auto elements = model_.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (!evaluated_[e])
      continue;
    const element::ElementEnergy energy = elements[e]->energy();
    total.stored += energy.stored;
    total.dissipated += energy.dissipated;
    total.integration_misfit += energy.integration_misfit;
  }
  return total;
}

void apply_increment(const DofMap& map, std::span<element::NodeConfiguration> nodes,
                     const Eigen::VectorXd& increment, double scale) {
  const Eigen::VectorXd full = map.expand(increment);
  for (std::size_t node = 0; node < nodes.size(); ++node) {
    const auto base = static_cast<Eigen::Index>(kDofPerNode * node);
    nodes[node].position += scale * full.segment<3>(base);
    const element::Vector3 spin = scale * full.segment<3>(base + 3);
    if (spin.squaredNorm() > 0.0)
      nodes[node].rotation = element::rotation_from_vector(spin) * nodes[node].rotation;
  }
}

Eigen::VectorXd full_displacement(const Model& model,
                                  std::span<const element::NodeConfiguration> nodes) {
  Eigen::VectorXd displacement(model.dof_count());
  for (int node = 0; node < model.node_count(); ++node) {
    displacement.segment<3>(kDofPerNode * node) = nodes[node].position - model.coordinates(node);
    displacement.segment<3>(kDofPerNode * node + 3) =
        element::vector_from_rotation(nodes[node].rotation);
  }
  return displacement;
}

std::vector<element::NodeConfiguration> initial_configuration(const Model& model) {
  std::vector<element::NodeConfiguration> nodes(model.node_count());
  for (int node = 0; node < model.node_count(); ++node)
    nodes[node].position = model.coordinates(node);
  return nodes;
}

} // namespace brb::model
