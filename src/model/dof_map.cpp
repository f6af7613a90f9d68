#include "brb/model/dof_map.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace brb::model {

namespace {

const char* dof_name(int dof) {
  static constexpr const char* names[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  return names[dof];
}

std::string describe(int full_dof) {
  return "node " + std::to_string(full_dof / kDofPerNode) + " " + dof_name(full_dof % kDofPerNode);
}

/// A constrained DOF's definition in terms of other full DOF.
struct SlaveDefinition {
  std::vector<std::pair<int, double>> masters; // (full DOF, factor)
};

} // namespace

DofMap DofMap::build(const Model& model, int dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("the model dimension must be 2 (planar X-Z) or 3");
  const int full = model.dof_count();
  DofMap map;
  map.dimension_ = dimension;

  std::vector<bool> removed(full, false);
  if (dimension == 2) {
    for (int node = 0; node < model.node_count(); ++node) {
      for (const Dof dof : {uy, rx, rz})
        removed[Model::global_dof(node, dof)] = true;
    }
  }

  std::map<int, SlaveDefinition> slaves;
  const auto define = [&](int slave_dof, SlaveDefinition definition) {
    if (removed[slave_dof])
      return; // out of the plane of a planar model: zero anyway
    if (model.is_fixed(slave_dof / kDofPerNode, static_cast<Dof>(slave_dof % kDofPerNode)))
      throw std::invalid_argument(describe(slave_dof) +
                                  " is both restrained and constrained to another node");
    if (!slaves.emplace(slave_dof, std::move(definition)).second)
      throw std::invalid_argument(describe(slave_dof) + " is constrained twice");
  };
  for (const EqualDofConstraint& constraint : model.equal_dofs()) {
    for (const Dof dof : constraint.dofs) {
      define(Model::global_dof(constraint.slave, dof),
             {{{Model::global_dof(constraint.master, dof), 1.0}}});
    }
  }
  for (const RigidDiaphragmConstraint& diaphragm : model.rigid_diaphragms()) {
    if (dimension == 2)
      throw std::invalid_argument("a rigid diaphragm needs a 3D model (its plane is X-Y)");
    const Vector3& centre = model.coordinates(diaphragm.master);
    const int master_ux = Model::global_dof(diaphragm.master, ux);
    const int master_uy = Model::global_dof(diaphragm.master, uy);
    const int master_rz = Model::global_dof(diaphragm.master, rz);
    for (const int slave : diaphragm.slaves) {
      const Vector3 arm = model.coordinates(slave) - centre;
      // rigid in-plane motion: u = u_m + rz_m e_z x arm
      define(Model::global_dof(slave, ux), {{{master_ux, 1.0}, {master_rz, -arm.y()}}});
      define(Model::global_dof(slave, uy), {{{master_uy, 1.0}, {master_rz, arm.x()}}});
      define(Model::global_dof(slave, rz), {{{master_rz, 1.0}}});
    }
  }

  map.independent_.assign(full, -1);
  for (int dof = 0; dof < full; ++dof) {
    const bool fixed = model.is_fixed(dof / kDofPerNode, static_cast<Dof>(dof % kDofPerNode));
    if (!removed[dof] && !fixed && !slaves.contains(dof))
      map.independent_[dof] = map.equation_count_++;
  }

  // Each DOF's expression in the equations, resolving chains of constraints depth first.
  std::vector<std::vector<DofTerm>> expression(full);
  std::vector<int> state(full, 0); // 0 unvisited, 1 in progress, 2 done
  const auto resolve = [&](auto&& self, int dof) -> const std::vector<DofTerm>& {
    if (state[dof] == 2)
      return expression[dof];
    if (state[dof] == 1)
      throw std::invalid_argument("the constraints form a cycle through " + describe(dof));
    state[dof] = 1;
    std::map<int, double> sum;
    if (map.independent_[dof] >= 0) {
      sum[map.independent_[dof]] = 1.0;
    } else if (const auto slave = slaves.find(dof); slave != slaves.end()) {
      for (const auto& [master, factor] : slave->second.masters) {
        for (const DofTerm& term : self(self, master))
          sum[term.equation] += factor * term.factor;
      }
    }
    for (const auto& [equation, factor] : sum) {
      if (factor != 0.0)
        expression[dof].push_back({equation, factor});
    }
    state[dof] = 2;
    return expression[dof];
  };

  map.offsets_.assign(full + 1, 0);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int dof = 0; dof < full; ++dof) {
    const std::vector<DofTerm>& terms = resolve(resolve, dof);
    map.offsets_[dof] = static_cast<int>(map.terms_.size());
    for (const DofTerm& term : terms) {
      map.terms_.push_back(term);
      triplets.emplace_back(dof, term.equation, term.factor);
    }
  }
  map.offsets_[full] = static_cast<int>(map.terms_.size());
  map.transformation_.resize(full, map.equation_count_);
  map.transformation_.setFromTriplets(triplets.begin(), triplets.end());
  return map;
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& equations) const {
  return transformation_ * equations;
}

Eigen::VectorXd DofMap::reduce(const Eigen::VectorXd& full) const {
  return transformation_.transpose() * full;
}

Eigen::SparseMatrix<double> DofMap::reduced_mass(const Model& model) const {
  Eigen::SparseMatrix<double> lumped(full_dof_count(), full_dof_count());
  std::vector<Eigen::Triplet<double>> triplets;
  for (int node = 0; node < model.node_count(); ++node) {
    for (int k = 0; k < kDofPerNode; ++k) {
      if (model.mass(node)[k] > 0.0)
        triplets.emplace_back(kDofPerNode * node + k, kDofPerNode * node + k, model.mass(node)[k]);
    }
  }
  lumped.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> transposed = transformation_.transpose();
  Eigen::SparseMatrix<double> mass = transposed * lumped * transformation_;
  mass.prune(0.0);
  return mass;
}

Eigen::VectorXd DofMap::ground_influence(const Eigen::Vector3d& direction) const {
  Eigen::VectorXd influence = Eigen::VectorXd::Zero(equation_count_);
  for (int dof = 0; dof < full_dof_count(); ++dof) {
    const int equation = independent_[dof];
    const int component = dof % kDofPerNode;
    if (equation >= 0 && component < 3)
      influence[equation] = direction[component];
  }
  return influence;
}

} // namespace brb::model
