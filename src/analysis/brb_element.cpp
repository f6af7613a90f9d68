#include "brb/analysis/brb_element.hpp"

#include "brb/element/rotation.hpp"
#include "brb/material/parameter_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace brb::analysis {
namespace {

/// The nested solver's settings: one polishing Newton correction once within tolerance
/// (NewtonSettings::polish_corrections), so that the outer forces are accurate to round-off,
/// not to the inner tolerance summed over the internal nodes. Without it, a warm start within
/// tolerance was returned as it was and the outer Newton of brbf9 with 16-element braces took
/// minutes per time step in the elastic range (thousands of evaluations, no inner iteration).
NewtonSettings nested_settings(NewtonSettings settings) {
  settings.polish_corrections = std::max(settings.polish_corrections, 1);
  return settings;
}

bool same_configuration(std::span<const element::NodeConfiguration> configuration,
                        const std::array<element::NodeConfiguration, 2>& last) {
  for (std::size_t k = 0; k < 2; ++k) {
    if (configuration[k].position != last[k].position ||
        configuration[k].rotation != last[k].rotation)
      return false;
  }
  return true;
}

} // namespace

using element::Matrix3;
using element::NodeConfiguration;
using element::Vector3;

BRBElement::BRBElement(std::array<int, 2> nodes, const Vector3& start, const Vector3& end,
                       const model::BraceSpec& spec, std::optional<Vector3> section_z,
                       NewtonSettings settings, const model::WorkSkips& skips)
    : nodes_(nodes), placement_(model::BracePlacement::between(start, end, section_z)),
      length_((end - start).norm()), work_(model::build_brace_model(spec, skips)),
      committed_model_(model::build_brace_model(spec, skips)),
      analysis_(work_.model, nested_settings(settings)), tracker_(work_, work_.model),
      reuse_tangents_(skips.reuse_tangents) {
  const double total = spec.total_length();
  if (std::abs(length_ - total) > 1e-9 * total) {
    throw ParameterError("element/nodes", "the outer nodes must be the brace's length apart (" +
                                              std::to_string(total) + " mm; got " +
                                              std::to_string(length_) + " mm)");
  }
  analysis_.use_prescribed_motion({work_.start_node, work_.end_node});
  committed_path_ = analysis_.path_state();
}

void BRBElement::restore_committed_internal_state() {
  if (work_is_committed_)
    return;
  work_.model.copy_element_states_from(committed_model_.model);
  analysis_.restore_path_state(committed_path_);
  work_is_committed_ = true;
}

bool BRBElement::evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                          Eigen::MatrixXd& tangent, std::string& failure) {
  if (reuse_tangents_ && last_.valid && same_configuration(configuration, last_.configuration)) {
    force = last_.force;
    tangent = last_.tangent;
    trial_ = last_.outputs;
    ++reused_evaluations_;
    return true;
  }
  last_.valid = false;
  const Matrix3& axes = placement_.axes;
  std::array<NodeConfiguration, 2> local;
  for (std::size_t k = 0; k < 2; ++k) {
    local[k].position = axes.transpose() * (configuration[k].position - placement_.origin);
    local[k].rotation = axes.transpose() * configuration[k].rotation * axes;
  }
  restore_committed_internal_state();
  analysis_.set_motion_target(local);
  work_is_committed_ = false;
  // Between the iterations of a global step, retrace the internal path of the last solve
  // (StaticAnalysis::retrace_last_path: smooth in the target, so the global Newton sees a
  // smooth brace); the first evaluation of a step, a target far from the last one, or a
  // retrace that fails solves adaptively from the committed state.
  StepReport report = analysis_.retrace_last_path();
  if (!report.converged) {
    if (report.substeps > 0) { // substeps before the failing one were committed
      restore_committed_internal_state();
      analysis_.set_motion_target(local);
      work_is_committed_ = false;
    }
    report = analysis_.step_to(1.0);
  }
  if (!report.converged) {
    failure = "BRB element (condensed): the internal solve failed: " + report.failure;
    return false;
  }
  Eigen::MatrixXd condensed;
  try {
    condensed = analysis_.condensed_tangent();
  } catch (const std::runtime_error& error) {
    failure = std::string("BRB element (condensed): ") + error.what();
    return false;
  }
  // back to global axes: f = Q f_l per 3-block, K = T K_l T^T
  const Eigen::VectorXd& internal = analysis_.internal_force();
  force.resize(12);
  tangent.resize(12, 12);
  const std::array<int, 2> inner = {work_.start_node, work_.end_node};
  for (int k = 0; k < 2; ++k) {
    for (int part = 0; part < 2; ++part) {
      force.segment<3>(6 * k + 3 * part) =
          axes * internal.segment<3>(model::kDofPerNode * inner[k] + 3 * part);
    }
  }
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b)
      tangent.block<3, 3>(3 * a, 3 * b) =
          axes * condensed.block<3, 3>(3 * a, 3 * b) * axes.transpose();
  }
  trial_ = outputs_of_internal_state();
  if (reuse_tangents_) {
    last_.valid = true;
    last_.configuration = {configuration[0], configuration[1]};
    last_.force = force;
    last_.tangent = tangent;
    last_.outputs = trial_;
  }
  return true;
}

BRBElement::Outputs BRBElement::outputs_of_internal_state() const {
  Outputs outputs;
  const Vector3 chord =
      analysis_.node(work_.end_node).position - analysis_.node(work_.start_node).position;
  const double length = chord.norm();
  outputs.deformation = length - length_;
  const Vector3 end_force =
      analysis_.internal_force().segment<3>(model::kDofPerNode * work_.end_node);
  outputs.axial_force = end_force.dot(chord / length);
  double initial = 0.0, current = 0.0;
  for (std::size_t e = 0; e < work_.beams.size(); ++e) {
    if (!work_.in_yielding_zone[e])
      continue;
    initial += work_.beams[e]->frame().initial_length();
    current += work_.beams[e]->frame().current_length();
  }
  outputs.core_strain = (current - initial) / initial;
  const EnergyBalance& energy = analysis_.energy();
  // The released energy is dissipated (by the laws' measure); the internal solver's misfit
  // is its elements' less what its jumps' own measure moved into the released energy, so
  // that the outer balance sums as the inner one does.
  outputs.energy = {energy.stored, energy.dissipated + energy.released_by_laws,
                    energy.integration_misfit + energy.released_in_jumps - energy.released_by_laws};
  return outputs;
}

void BRBElement::commit() {
  // A committed step that dissipated (plastic flow, damage, slip, a jump) changed the history
  // the last evaluation started from: it cannot be reused any more.
  if (trial_.energy.dissipated != committed_.energy.dissipated)
    last_.valid = false;
  if (!work_is_committed_) {
    committed_model_.model.copy_element_states_from(work_.model);
    committed_path_ = analysis_.path_state();
    work_is_committed_ = true;
  }
  committed_ = trial_;
  tracker_.observe([this](int node) -> const Vector3& { return analysis_.node(node).position; },
                   committed_.deformation, committed_.axial_force);
}

void BRBElement::revert_to_committed() {
  trial_ = committed_;
}

void BRBElement::copy_state_from(const Element& other) {
  const auto& twin = dynamic_cast<const BRBElement&>(other);
  work_.model.copy_element_states_from(twin.work_.model);
  committed_model_.model.copy_element_states_from(twin.committed_model_.model);
  analysis_.restore_path_state(twin.analysis_.path_state());
  committed_path_ = twin.committed_path_;
  work_is_committed_ = twin.work_is_committed_;
  tracker_ = twin.tracker_; // its history; then point it at this element's internal model
  tracker_.rebind(work_, work_.model);
  trial_ = twin.trial_;
  committed_ = twin.committed_;
  last_ = twin.last_;
}

} // namespace brb::analysis
