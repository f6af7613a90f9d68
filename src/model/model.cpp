#include "brb/model/model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace brb::model {

int Model::add_node(const Vector3& coordinates, const Matrix3& axes) {
  coordinates_.push_back(coordinates);
  axes_.push_back(axes);
  fixed_.push_back({false, false, false, false, false, false});
  masses_.push_back({0.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  return node_count() - 1;
}

void Model::add_mass(int node, const NodalMass& mass) {
  NodalMass& total = masses_.at(node);
  for (int k = 0; k < kDofPerNode; ++k) {
    if (!(mass[k] >= 0.0) || !std::isfinite(mass[k]))
      throw std::invalid_argument("node " + std::to_string(node) +
                                  ": a mass must be finite and >= 0");
    total[k] += mass[k];
  }
}

bool Model::has_mass() const {
  for (const NodalMass& mass : masses_) {
    for (const double m : mass) {
      if (m > 0.0)
        return true;
    }
  }
  return false;
}

void Model::add_equal_dof(EqualDofConstraint constraint) {
  check_node(constraint.master, "equal_dof master");
  check_node(constraint.slave, "equal_dof slave");
  if (constraint.master == constraint.slave)
    throw std::invalid_argument("equal_dof: a node cannot be its own master");
  if (constraint.dofs.empty())
    throw std::invalid_argument("equal_dof: no DOF listed");
  equal_dofs_.push_back(std::move(constraint));
}

void Model::add_rigid_diaphragm(RigidDiaphragmConstraint constraint) {
  check_node(constraint.master, "rigid_diaphragm master");
  for (const int slave : constraint.slaves) {
    check_node(slave, "rigid_diaphragm node");
    if (slave == constraint.master)
      throw std::invalid_argument("rigid_diaphragm: the master cannot be one of its nodes");
  }
  diaphragms_.push_back(std::move(constraint));
}

void Model::check_node(int node, const std::string& what) const {
  if (node < 0 || node >= node_count())
    throw std::out_of_range(what + " refers to node " + std::to_string(node) +
                            " but the model has " + std::to_string(node_count()) + " nodes");
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
