// A frame ready to analyse: the Model built from a frame file (frame_builder.hpp), its
// dimension, and the references the analysis and its recorders need by the user's ids
// (stories, floors, supports, braces). Workflow layer: the frame runner and IDA use it.
#pragma once

#include "brb/analysis/brb_element.hpp"
#include "brb/element/brace_truss.hpp"
#include "brb/model/model.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace brb::frame {

struct StoryReference {
  std::string name;
  int bottom = -1; ///< model node index
  int top = -1;
  double height = 0.0; ///< mm, Z of top minus Z of bottom
};

struct FloorReference {
  std::string name;
  int node = -1;
};

/// A BRB of the frame at the fidelity it runs at: exactly one of `truss` and `full` is set.
struct BraceReference {
  int id = 0;       ///< the user's element id
  int element = -1; ///< index in Model::elements()
  element::BraceTruss* truss = nullptr;
  analysis::BRBElement* full = nullptr;
  double yield_force = 0.0;       ///< N
  double yield_deformation = 0.0; ///< mm, between the work points
  std::string fidelity;           ///< "truss" or "full" (after `auto` is resolved)
  std::string fidelity_reason;    ///< why `auto` chose it (empty when given)

  double axial_force() const { return truss ? truss->axial_force() : full->axial_force(); }
  double deformation() const { return truss ? truss->deformation() : full->deformation(); }
  double core_strain() const { return truss ? truss->core_strain() : full->core_strain(); }
};

struct FrameModel {
  std::string title;
  int dimension = 2;
  std::unique_ptr<model::Model> model = std::make_unique<model::Model>();
  std::vector<int> node_ids;    ///< model node index -> user id
  std::vector<int> element_ids; ///< model element index -> user id
  /// Per model element: whether it takes part in the stiffness-proportional damping.
  std::vector<bool> in_stiffness_damping;
  std::vector<BraceReference> braces;
  std::vector<int> support_nodes; ///< nodes with any restrained translation
  Eigen::VectorXd gravity_load;   ///< full DOF vector (N), applied before the dynamic run
  int gravity_steps = 10;
  std::vector<StoryReference> stories;
  std::vector<FloorReference> floors;
};

} // namespace brb::frame
