// A body of several solid parts and interactions (see solid_body.hpp).
#include "brb/solid/solid_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace brb::solid {

SolidBody::SolidBody(Eigen::Matrix3Xd reference_nodes)
    : reference_nodes_(std::move(reference_nodes)) {
  if (!reference_nodes_.allFinite())
    throw std::invalid_argument("solid body: the reference coordinates must be finite");
}

void SolidBody::check_node_map(const std::string& name, const Eigen::Matrix3Xd& local_nodes,
                               const std::vector<int>& global_nodes) const {
  if (static_cast<Eigen::Index>(global_nodes.size()) != local_nodes.cols())
    throw std::invalid_argument("solid body: part \"" + name + "\" maps " +
                                std::to_string(global_nodes.size()) + " nodes but its mesh has " +
                                std::to_string(local_nodes.cols()));
  const double size =
      reference_nodes_.cols() > 0
          ? (reference_nodes_.rowwise().maxCoeff() - reference_nodes_.rowwise().minCoeff()).norm()
          : 0.0;
  const double tolerance = 1e-9 * std::max(size, 1.0);
  std::vector<char> used(static_cast<std::size_t>(node_count()), 0);
  for (std::size_t n = 0; n < global_nodes.size(); ++n) {
    const int global = global_nodes[n];
    if (global < 0 || global >= node_count())
      throw std::invalid_argument("solid body: part \"" + name + "\" maps local node " +
                                  std::to_string(n) + " to global node " + std::to_string(global) +
                                  ", outside 0.." + std::to_string(node_count() - 1));
    if (used[global])
      throw std::invalid_argument("solid body: part \"" + name + "\" maps two local nodes to " +
                                  "global node " + std::to_string(global));
    used[global] = 1;
    if ((local_nodes.col(static_cast<Eigen::Index>(n)) - reference_nodes_.col(global)).norm() >
        tolerance)
      throw std::invalid_argument("solid body: part \"" + name + "\": local node " +
                                  std::to_string(n) + " is not at its global node " +
                                  std::to_string(global) + "'s coordinates");
  }
}

SolidInteraction& SolidBody::add_interaction(std::unique_ptr<SolidInteraction> interaction) {
  if (!interaction)
    throw std::invalid_argument("solid body: null interaction");
  interactions_.push_back(std::move(interaction));
  return *interactions_.back();
}

int SolidBody::element_count() const {
  int count = 0;
  for (const auto& part : parts_)
    count += part->element_count();
  return count;
}

bool SolidBody::evaluate(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                         std::string& reason) {
  force.setZero(dof_count());
  for (const auto& part : parts_)
    if (!part->add_force(displacement, force, reason))
      return false;
  for (std::size_t i = 0; i < interactions_.size(); ++i) {
    if (!interactions_[i]->add_force(displacement, force, reason)) {
      reason = "interaction " + std::to_string(i) + ": " + reason;
      return false;
    }
  }
  return true;
}

void SolidBody::commit() {
  for (const auto& part : parts_)
    part->commit();
  for (const auto& interaction : interactions_)
    interaction->commit();
}

Eigen::VectorXd SolidBody::lumped_mass() const {
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(dof_count());
  for (const auto& part : parts_)
    part->add_lumped_mass(mass);
  return mass;
}

double SolidBody::element_frequency() const {
  double frequency = 0.0;
  for (const auto& part : parts_)
    frequency = std::max(frequency, part->max_frequency());
  return frequency;
}

double SolidBody::interaction_frequency_squared() const {
  if (interactions_.empty())
    return 0.0;
  const Eigen::VectorXd mass = lumped_mass();
  double squared = 0.0;
  for (const auto& interaction : interactions_)
    squared += interaction->frequency_bound_squared(mass);
  return squared;
}

double SolidBody::stable_time_step(double safety) const {
  const double element = element_frequency();
  const double interactions = interaction_frequency_squared();
  // without interactions exactly SolidModel's safety x min_e 2 / w_e (= 2 / max_e w_e)
  const double frequency =
      interactions > 0.0 ? std::sqrt(element * element + interactions) : element;
  if (!(frequency > 0.0))
    return std::numeric_limits<double>::infinity();
  return safety * (2.0 / frequency);
}

SolidEnergy SolidBody::energy() const {
  SolidEnergy total;
  for (const auto& part : parts_) {
    const SolidEnergy energy = part->energy();
    total.internal += energy.internal;
    total.hourglass += energy.hourglass;
  }
  for (const auto& interaction : interactions_) {
    total.interaction += interaction->stored_energy();
    total.friction += interaction->dissipated_energy();
  }
  return total;
}

void SolidBody::set_threads(int threads) {
  if (threads < 1)
    throw std::invalid_argument("solid body: threads must be >= 1 (got " + std::to_string(threads) +
                                ")");
  threads_ = threads;
  for (const auto& part : parts_)
    part->set_threads(threads);
}

} // namespace brb::solid
