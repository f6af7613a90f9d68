// The penalty tie of two node sets' mean axial displacements (see axial_tie.hpp).
#include "brb/solid/axial_tie.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace brb::solid {

AxialTie::AxialTie(std::vector<int> set_a, std::vector<int> set_b, double stiffness)
    : set_a_(std::move(set_a)), set_b_(std::move(set_b)), stiffness_(stiffness) {
  if (set_a_.empty() || set_b_.empty())
    throw std::invalid_argument("axial tie: both node sets must be non-empty");
  for (const auto* set : {&set_a_, &set_b_})
    for (int node : *set)
      if (node < 0)
        throw std::invalid_argument("axial tie: negative node index " + std::to_string(node));
  if (!(stiffness_ > 0.0) || !std::isfinite(stiffness_))
    throw std::invalid_argument("axial tie: stiffness must be finite and > 0 N/mm");
}

bool AxialTie::add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                         std::string& reason) {
  double mean_a = 0.0, mean_b = 0.0;
  for (int node : set_a_)
    mean_a += displacement[3 * node];
  for (int node : set_b_)
    mean_b += displacement[3 * node];
  const double n_a = static_cast<double>(set_a_.size()), n_b = static_cast<double>(set_b_.size());
  trial_elongation_ = mean_a / n_a - mean_b / n_b;
  const double f = stiffness_ * trial_elongation_;
  if (!std::isfinite(f)) {
    reason = "axial tie: the force is not finite";
    return false;
  }
  for (int node : set_a_)
    force[3 * node] += f / n_a;
  for (int node : set_b_)
    force[3 * node] -= f / n_b;
  return true;
}

double AxialTie::frequency_bound_squared(const Eigen::VectorXd& lumped_mass) const {
  const double n_a = static_cast<double>(set_a_.size()), n_b = static_cast<double>(set_b_.size());
  double sum = 0.0;
  for (int node : set_a_)
    sum += 1.0 / (n_a * n_a * lumped_mass[3 * node]);
  for (int node : set_b_)
    sum += 1.0 / (n_b * n_b * lumped_mass[3 * node]);
  return stiffness_ * sum;
}

} // namespace brb::solid
