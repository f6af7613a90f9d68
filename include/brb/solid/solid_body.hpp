// SolidBody: the 3D continuum model of a whole brace, made of parts (the steel core, the
// mortar fill, the steel tube), each a SolidModel<Law> of its own law over its own HexMesh,
// whose local nodes map to global nodes (parts that are bonded, such as the mortar and the
// tube, share global nodes), plus any number of SolidInteraction objects (contact, ties).
// It offers the explicit solver (solid_explicit.hpp) what a single SolidModel offers, over
// the global DOFs (node-major, 3 n + i): internal forces, commit, lumped mass, stable step,
// energies and threads.
//
// Hot loop: a part is evaluated by one virtual call (SolidPart::add_force), inside which
// SolidModel<Law> runs its homogeneous element loop; no virtual call per element.
//
// Stable step (stated bound). With K = sum_parts K_e + sum_interactions K_i and the lumped
// mass M = sum_e M_e (a node shared by parts gets the sum of its elements' shares):
// - Irons' element eigenvalue theorem: lambda_max(K_el, M) <= max_e lambda_max(K_e, M_e), so
//   w_el^2 = (max over every element of every part of hex8_max_frequency)^2 bounds the
//   elements with their own shares of the mass (the summed mass of a shared node included);
// - Weyl's inequality for the symmetric M^-1/2 K M^-1/2: lambda_max(K_el + K_i) <= lambda_max(
//   K_el) + lambda_max(K_i), so w^2 <= w_el^2 + sum_i w_i^2 with w_i^2 the interactions' own
//   frequency_bound_squared(lumped mass);
// and the step is safety x 2 / w (central differences are stable for w dt <= 2).
#pragma once

#include "brb/solid/solid_interaction.hpp"
#include "brb/solid/solid_model.hpp"

#include <Eigen/Core>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace brb::solid {

/// One part of a body, behind one virtual call per evaluation.
class SolidPart {
public:
  virtual ~SolidPart() = default;
  virtual const std::string& name() const = 0;
  /// The part's global node of each local node.
  virtual const std::vector<int>& global_nodes() const = 0;
  /// The part's mesh (local node numbers).
  virtual const HexMesh& mesh() const = 0;
  /// Gathers the part's displacements from the global vector, evaluates its elements and adds
  /// their internal forces to the global `force`. False, with `reason`, when an element
  /// inverts or its stress is not finite.
  virtual bool add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                         std::string& reason) = 0;
  virtual void commit() = 0;
  /// Adds the part's lumped mass to the global per-DOF mass.
  virtual void add_lumped_mass(Eigen::VectorXd& mass) const = 0;
  /// Largest element frequency bound of the part (rad/s).
  virtual double max_frequency() const = 0;
  /// Energies of the committed state (internal, hourglass).
  virtual SolidEnergy energy() const = 0;
  virtual void set_threads(int threads) = 0;
  virtual int element_count() const = 0;
};

/// A SolidModel<Law> and its map to global nodes.
template <class Law> class SolidPartOf final : public SolidPart {
public:
  SolidPartOf(std::string name, SolidModel<Law> model, std::vector<int> global_nodes)
      : name_(std::move(name)), model_(std::move(model)), global_nodes_(std::move(global_nodes)),
        local_displacement_(Eigen::VectorXd::Zero(model_.dof_count())),
        local_force_(Eigen::VectorXd::Zero(model_.dof_count())) {
    if (static_cast<int>(global_nodes_.size()) != model_.node_count())
      throw std::invalid_argument("solid body: part \"" + name_ + "\" maps " +
                                  std::to_string(global_nodes_.size()) +
                                  " nodes but its mesh has " + std::to_string(model_.node_count()));
  }

  const std::string& name() const override { return name_; }
  const std::vector<int>& global_nodes() const override { return global_nodes_; }
  const HexMesh& mesh() const override { return model_.mesh(); }
  SolidModel<Law>& model() { return model_; }
  const SolidModel<Law>& model() const { return model_; }

  bool add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                 std::string& reason) override {
    for (std::size_t n = 0; n < global_nodes_.size(); ++n)
      local_displacement_.segment<3>(3 * n) = displacement.segment<3>(3 * global_nodes_[n]);
    if (!model_.evaluate(local_displacement_, local_force_, reason)) {
      reason = "part " + name_ + ": " + reason;
      return false;
    }
    for (std::size_t n = 0; n < global_nodes_.size(); ++n)
      force.segment<3>(3 * global_nodes_[n]) += local_force_.segment<3>(3 * n);
    return true;
  }
  void commit() override { model_.commit(); }
  void add_lumped_mass(Eigen::VectorXd& mass) const override {
    const Eigen::VectorXd local = model_.lumped_mass();
    for (std::size_t n = 0; n < global_nodes_.size(); ++n)
      mass.segment<3>(3 * global_nodes_[n]) += local.segment<3>(3 * n);
  }
  double max_frequency() const override { return model_.max_frequency(); }
  SolidEnergy energy() const override { return model_.energy(); }
  void set_threads(int threads) override { model_.set_threads(threads); }
  int element_count() const override { return model_.element_count(); }

private:
  std::string name_;
  SolidModel<Law> model_;
  std::vector<int> global_nodes_;
  Eigen::VectorXd local_displacement_, local_force_;
};

class SolidBody {
public:
  /// reference_nodes: the global nodes' reference coordinates (mm), one column per node.
  explicit SolidBody(Eigen::Matrix3Xd reference_nodes);

  /// Adds a part whose local node n is global node global_nodes[n]. Throws
  /// std::invalid_argument when a global index is out of range, a part maps two local nodes
  /// to one global node, or a local node's coordinates are not its global node's (1e-9 of
  /// the body's size): bonded parts must share nodes where they meet.
  template <class Law>
  SolidPartOf<Law>& add_part(std::string name, SolidModel<Law> model,
                             std::vector<int> global_nodes) {
    check_node_map(name, model.mesh().nodes, global_nodes);
    auto part = std::make_unique<SolidPartOf<Law>>(std::move(name), std::move(model),
                                                   std::move(global_nodes));
    SolidPartOf<Law>& reference = *part;
    reference.set_threads(threads_);
    parts_.push_back(std::move(part));
    return reference;
  }
  /// Adds an interaction (owned); its force joins the elements' from the next evaluate().
  SolidInteraction& add_interaction(std::unique_ptr<SolidInteraction> interaction);

  int node_count() const { return static_cast<int>(reference_nodes_.cols()); }
  int dof_count() const { return 3 * node_count(); }
  const Eigen::Matrix3Xd& reference_nodes() const { return reference_nodes_; }
  const std::vector<std::unique_ptr<SolidPart>>& parts() const { return parts_; }
  const std::vector<std::unique_ptr<SolidInteraction>>& interactions() const {
    return interactions_;
  }
  int element_count() const;

  /// Trial internal forces at global displacements u: every part's elements plus every
  /// interaction. False, with `reason`, when a part or an interaction fails.
  bool evaluate(const Eigen::VectorXd& displacement, Eigen::VectorXd& force, std::string& reason);
  /// Accepts the last evaluate() in every part and interaction.
  void commit();

  /// Lumped mass per global DOF (tonne): the sum of the parts' row-sum masses.
  Eigen::VectorXd lumped_mass() const;
  /// The largest element frequency over all parts (rad/s).
  double element_frequency() const;
  /// sum over interactions of frequency_bound_squared(lumped mass) (rad^2/s^2).
  double interaction_frequency_squared() const;
  /// safety x 2 / sqrt(w_el^2 + sum_i w_i^2) (the bound of the header).
  double stable_time_step(double safety) const;

  /// Energies of the committed state: the parts' internal and hourglass energies, the
  /// interactions' stored energy and friction dissipation.
  SolidEnergy energy() const;

  /// Threads of every part's element loop (>= 1).
  void set_threads(int threads);

private:
  void check_node_map(const std::string& name, const Eigen::Matrix3Xd& local_nodes,
                      const std::vector<int>& global_nodes) const;

  Eigen::Matrix3Xd reference_nodes_;
  std::vector<std::unique_ptr<SolidPart>> parts_;
  std::vector<std::unique_ptr<SolidInteraction>> interactions_;
  int threads_ = 1;
};

} // namespace brb::solid
