#include "brb/model/model.hpp"

#include <stdexcept>
#include <string>

namespace brb::model {

int Model::add_node(const Vector3& coordinates) {
  coordinates_.push_back(coordinates);
  fixed_.push_back({false, false, false, false, false, false});
  return node_count() - 1;
}

void Model::fix(int node, Dof dof) {
  fixed_.at(node)[dof] = true;
}

void Model::fix_all(int node) {
  fixed_.at(node).fill(true);
}

void Model::copy_element_states_from(const Model& other) {
  if (other.elements_.size() != elements_.size())
    throw std::invalid_argument("copy_element_states_from: the models are not twins");
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->copy_state_from(*other.elements_[e]);
}

void Model::check_element_nodes(const element::Element& element) const {
  for (const int node : element.nodes()) {
    if (node < 0 || node >= node_count()) {
      throw std::out_of_range("element refers to node " + std::to_string(node) +
                              " but the model has " + std::to_string(node_count()) + " nodes");
    }
  }
}

} // namespace brb::model
