#include "brb/element/casing_contact.hpp"

#include "brb/material/parameter_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace brb::element {
namespace {

void require(bool condition, const char* field, const std::string& expected) {
  if (!condition)
    throw ParameterError(field, expected);
}

/// The lateral direction a face bears in (faces 0, 1: +y, -y; 2, 3: +z, -z): 0 y, 1 z.
constexpr std::size_t face_lateral(int face) {
  return face < 2 ? 0 : 1;
}

} // namespace

void CasingContactParameters::validate() const {
  require(gap_y >= 0.0 && std::isfinite(gap_y), "gap_y", "clearance must be >= 0 mm");
  require(gap_z >= 0.0 && std::isfinite(gap_z), "gap_z", "clearance must be >= 0 mm");
  require(bearing_area_y > 0.0, "bearing_area_y", "must be > 0 mm^2");
  require(bearing_area_z > 0.0, "bearing_area_z", "must be > 0 mm^2");
  require(bearing_depth_y > 0.0, "bearing_depth_y", "must be > 0 mm");
  require(bearing_depth_z > 0.0, "bearing_depth_z", "must be > 0 mm");
  require(layer_stiffness >= 0.0, "layer_stiffness", "must be >= 0 N/mm");
  require(friction_coefficient >= 0.0, "friction", "must be >= 0");
  require(tangential_stiffness > 0.0, "tangential_stiffness", "must be > 0 N/mm");
  require((axes.transpose() * axes - Matrix3::Identity()).norm() < 1e-9, "axes",
          "must be orthonormal");
  if (splitting)
    splitting->validate();
}

void CasingSplitting::validate() const {
  require(wall_area_y > 0.0 && std::isfinite(wall_area_y), "wall_area_y",
          "must be > 0 mm^2 (mortar beside the core's opening)");
  require(wall_area_z > 0.0 && std::isfinite(wall_area_z), "wall_area_z",
          "must be > 0 mm^2 (mortar beside the core's opening)");
  require(wall_length_y > 0.0 && std::isfinite(wall_length_y), "wall_length_y", "must be > 0 mm");
  require(wall_length_z > 0.0 && std::isfinite(wall_length_z), "wall_length_z", "must be > 0 mm");
}

void CoreExpansion::validate() const {
  require(previous_node >= 0 && next_node >= 0 && previous_node != next_node, "expansion_nodes",
          "two distinct core nodes around the station");
  require((next_position - previous_position).norm() > 0.0, "expansion_nodes",
          "core nodes at distinct positions (a chord of length > 0)");
  require(extent_y > 0.0 && std::isfinite(extent_y), "extent_y", "must be > 0 mm");
  require(extent_z > 0.0 && std::isfinite(extent_z), "extent_z", "must be > 0 mm");
  require(ratio >= 0.0 && ratio <= 0.5, "core_expansion",
          "lateral over axial strain nu_c in [0, 0.5]");
}

void HighModeWaves::validate() const {
  require(area > 0.0 && std::isfinite(area), "area", "core area must be > 0 mm^2");
  require(gyration_radius > 0.0 && std::isfinite(gyration_radius), "gyration_radius",
          "must be > 0 mm");
  require(thickness > 0.0 && std::isfinite(thickness), "thickness", "must be > 0 mm");
  require(gap >= 0.0 && std::isfinite(gap), "gap", "clearance must be >= 0 mm");
  require(tributary_length > 0.0 && std::isfinite(tributary_length), "tributary_length",
          "must be > 0 mm");
  require(resolved_half_wave > 0.0 && std::isfinite(resolved_half_wave), "resolved_half_wave",
          "must be > 0 mm");
  require(crest_factor >= 0.0 && std::isfinite(crest_factor), "crest_factor", "must be >= 0");
}

double HighModeWaves::normal_force(double stress, double tangent_modulus) const {
  if (!(stress < 0.0))
    return 0.0;
  const double compression = -stress * area; // P (N)
  // 1 / l^2 = sigma / (pi^2 r^2 E_t), capped at 1 / thickness^2 (also when E_t <= 0: a
  // softening core forms the shortest waves)
  const double shortest = 1.0 / (thickness * thickness);
  const double pi_r = std::numbers::pi * gyration_radius;
  const double inverse_square = tangent_modulus > 0.0
                                    ? std::min(-stress / (pi_r * pi_r * tangent_modulus), shortest)
                                    : shortest;
  const double unresolved =
      inverse_square - 1.0 / (resolved_half_wave * resolved_half_wave); // 1/l^2 - 1/l_mesh^2
  if (!(unresolved > 0.0))
    return 0.0;
  return crest_factor * gap * compression * tributary_length * unresolved;
}

namespace {

/// nodes_ of a link: core, casing, then the expansion's chord ends not already listed.
std::vector<int> link_nodes(std::array<int, 2> nodes,
                            const std::optional<CoreExpansion>& expansion) {
  std::vector<int> all(nodes.begin(), nodes.end());
  if (expansion) {
    expansion->validate();
    for (const int node : {expansion->previous_node, expansion->next_node}) {
      if (std::find(all.begin(), all.end(), node) == all.end())
        all.push_back(node);
    }
  }
  return all;
}

int index_of(const std::vector<int>& nodes, int node) {
  return static_cast<int>(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
}

} // namespace

CasingContact::CasingContact(std::array<int, 2> nodes, const Vector3& core_position,
                             const Vector3& casing_position,
                             const CasingContactParameters& parameters, bool skip_open_links,
                             const std::optional<CoreExpansion>& expansion,
                             const std::optional<HighModeWaves>& waves)
    : nodes_(link_nodes(nodes, expansion)), initial_offset_(core_position - casing_position),
      parameters_(parameters),
      waves_(waves), bearing_{material::MortarUniaxial((parameters.validate(), parameters.mortar),
                                                       parameters.bearing_depth_y),
                              material::MortarUniaxial(parameters.mortar,
                                                       parameters.bearing_depth_z)},
      friction_({1.0, parameters.tangential_stiffness, parameters.friction_coefficient}),
      skip_open_links_(skip_open_links) {
  if (parameters_.splitting) {
    walls_.emplace_back(parameters_.mortar, parameters_.splitting->wall_length_y);
    walls_.emplace_back(parameters_.mortar, parameters_.splitting->wall_length_z);
  }
  if (expansion) {
    chord_ends_ = {index_of(nodes_, expansion->previous_node),
                   index_of(nodes_, expansion->next_node)};
    chord_initial_length_ = (expansion->next_position - expansion->previous_position).norm();
    expansion_per_strain_ =
        -0.5 * expansion->ratio * Eigen::Vector2d(expansion->extent_y, expansion->extent_z);
  }
  if (waves_) {
    if (!expansion)
      throw ParameterError("expansion_nodes",
                           "the sub-element waves need the core chord around the station");
    waves_->validate();
    // characteristic length: the chord's, over which its strain is measured
    wave_steel_.emplace(waves_->steel, chord_initial_length_);
    committed_.wave_tangent = waves_->steel.youngs_modulus;
  }
  Eigen::VectorXd unused_force;
  scatter(Vector3::Zero(), open_local_tangent(), unused_force, open_tangent_);
  // the faces' penetrations in the initial configuration (no relative displacement, no expansion)
  for (int face = 0; face < 4; ++face)
    committed_.penetration[face] = penetration(face);
  trial_ = committed_;
}

CasingContact::Chord CasingContact::chord(std::span<const NodeConfiguration> configuration) const {
  const Vector3 span = configuration[static_cast<std::size_t>(chord_ends_[1])].position -
                       configuration[static_cast<std::size_t>(chord_ends_[0])].position;
  Chord result;
  result.length = span.norm();
  result.direction = span / result.length;
  result.strain = (result.length - chord_initial_length_) / chord_initial_length_;
  return result;
}

double CasingContact::penetration(int face) const {
  const int direction = 1 + face / 2;
  const double gap = parameters_.gap(face_lateral(face));
  const double motion = face % 2 == 0 ? trial_.relative[direction] : -trial_.relative[direction];
  return motion - gap + expansion_[direction - 1];
}

Matrix3 CasingContact::open_local_tangent() const {
  // The general path's sums with no face penetrated: 0 + k_layer on y and z, and friction's
  // zero tangent (F6 of penalty_friction.cpp) on the axis.
  Matrix3 local_tangent = Matrix3::Zero();
  local_tangent(1, 1) += parameters_.layer_stiffness;
  local_tangent(2, 2) += parameters_.layer_stiffness;
  return local_tangent;
}

void CasingContact::scatter(const Vector3& local_force, const Matrix3& local_tangent,
                            Eigen::VectorXd& force, Eigen::MatrixXd& tangent) const {
  const Matrix3& axes = parameters_.axes;
  const Vector3 global_force = axes * local_force;
  const Matrix3 global_tangent = axes * local_tangent * axes.transpose();
  const Eigen::Index dofs = 6 * static_cast<Eigen::Index>(nodes_.size());
  force = Eigen::VectorXd::Zero(dofs);
  tangent = Eigen::MatrixXd::Zero(dofs, dofs);
  force.segment<3>(0) = global_force;
  force.segment<3>(6) = -global_force;
  tangent.block<3, 3>(0, 0) = global_tangent;
  tangent.block<3, 3>(0, 6) = -global_tangent;
  tangent.block<3, 3>(6, 0) = -global_tangent;
  tangent.block<3, 3>(6, 6) = global_tangent;
}

bool CasingContact::evaluate(std::span<const NodeConfiguration> configuration,
                             Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                             std::string& failure) {
  const Matrix3& axes = parameters_.axes;
  trial_ = committed_;
  trial_.bearing_strain.fill(0.0);
  trial_.face_force.fill(0.0);
  trial_.wall_strain.fill(0.0);
  trial_.opening.fill(0.0);
  trial_.wall_force.fill(0.0);
  trial_.relative =
      axes.transpose() * (configuration[0].position - configuration[1].position - initial_offset_);
  const Vector3& relative = trial_.relative;
  Chord core_chord;
  if (has_expansion()) {
    core_chord = chord(configuration);
    expansion_ = expansion_per_strain_ * core_chord.strain;
  }
  if (waves_) {
    // N_w from the step's start (lagged, see HighModeWaves); the law follows the chord
    trial_.wave_normal_force =
        waves_->normal_force(committed_.wave_stress, committed_.wave_tangent);
    const auto steel = wave_steel_->evaluate(committed_.wave_steel, core_chord.strain);
    if (!std::isfinite(steel.stress)) {
      failure = "casing contact: non-finite core stress of the sub-element waves";
      return false;
    }
    trial_.wave_steel = steel.state;
    trial_.wave_stress = steel.stress;
    trial_.wave_tangent = steel.tangent;
  }

  if (skip_open_links_ && !(trial_.wave_normal_force > 0.0) && !(penetration(0) > 0.0) &&
      !(penetration(1) > 0.0) && !(penetration(2) > 0.0) && !(penetration(3) > 0.0)) {
    // Open link: the layer springs only. The state changes as the general path changes it:
    // faces as committed, the friction slip follows the axial motion (F6).
    ++open_evaluations_;
    trial_.friction.slip = Eigen::Vector2d(relative[0], 0.0);
    Vector3 local_force = Vector3::Zero();
    local_force[1] += parameters_.layer_stiffness * relative[1];
    local_force[2] += parameters_.layer_stiffness * relative[2];
    in_contact_ = false;
    trial_.link_force = local_force;
    force = Eigen::VectorXd::Zero(open_tangent_.rows());
    const Vector3 global_force = parameters_.axes * local_force;
    force.segment<3>(0) = global_force;
    force.segment<3>(6) = -global_force;
    tangent = open_tangent_;
    record_stress_work();
    return true;
  }

  // Bearing on each face: penetration p (see penetration()); the mortar is compressed at
  // strain -p / depth. Faces not penetrated cost nothing. Per direction the sums over its
  // two faces: bearing force S, stiffness K (dS/de) and signed stiffness K_r (dS/dr).
  // With CasingSplitting the faces bear at p - w / 2 (w: the direction's opening, solved so
  // that the walls' force is (F+ + F-) / 2), and the stiffnesses are condensed over w:
  // dw = (K+ dp+ + K- dp-) / (2 D), D = dT/dw + (K+ + K-) / 4, so with s = K+ + K- and
  // t = K+ - K-:  dS_r/dr = s - t^2 / (4 D),  dS_r/de = dS_e/dr = t (1 - s / (4 D)),
  // dS_e/de = s (1 - s / (4 D))  (S_r = F+ - F-, S_e = F+ + F-).
  Vector3 local_force = Vector3::Zero(); // resisting force on the core (axis, y, z)
  Matrix3 local_tangent = Matrix3::Zero();
  double normal_force = 0.0;
  Eigen::RowVector3d normal_rate = Eigen::RowVector3d::Zero();   // dN/d(relative)
  Eigen::Vector2d direction_force = Eigen::Vector2d::Zero();     // S per direction
  Eigen::Vector2d direction_stiffness = Eigen::Vector2d::Zero(); // K per direction
  bool penetrated = false;
  in_contact_ = false;
  for (int direction = 1; direction <= 2; ++direction) {
    const int first_face = 2 * (direction - 1);
    const std::array<double, 2> kinematic{penetration(first_face), penetration(first_face + 1)};
    const bool split = !walls_.empty() && (kinematic[0] > 0.0 || kinematic[1] > 0.0);
    std::array<FaceBearing, 2> faces;
    WallResponse walls;
    double opening = path_opening_[static_cast<std::size_t>(direction - 1)];
    if (split) {
      if (!solve_split(direction, kinematic, faces, walls, opening, failure))
        return false;
    } else {
      for (int side = 0; side < 2; ++side) {
        faces[static_cast<std::size_t>(side)] = bear(first_face + side, kinematic[side], failure);
        if (!std::isfinite(faces[static_cast<std::size_t>(side)].force))
          return false;
      }
    }
    for (int side = 0; side < 2; ++side) {
      const int face = first_face + side;
      const FaceBearing& bearing = faces[static_cast<std::size_t>(side)];
      if (!bearing.loaded)
        continue;
      penetrated = true;
      trial_.faces[face] = bearing.state;
      trial_.bearing_strain[face] = bearing.strain;
      const double sign = side == 0 ? 1.0 : -1.0; // dp/dr
      local_force[direction] += sign * bearing.force;
      normal_force += bearing.force;
      direction_force[direction - 1] += bearing.force;
      trial_.face_force[face] = bearing.force;
      in_contact_ = in_contact_ || bearing.force > 0.0;
      if (!split) {
        local_tangent(direction, direction) += bearing.stiffness;
        normal_rate[direction] += sign * bearing.stiffness;
        direction_stiffness[direction - 1] += bearing.stiffness;
      }
    }
    if (split) {
      const std::size_t d = static_cast<std::size_t>(direction - 1);
      trial_.walls[d] = walls.state;
      trial_.wall_strain[d] = walls.strain;
      trial_.opening[d] = opening;
      trial_.wall_force[d] = walls.force;
      const double sum = faces[0].stiffness + faces[1].stiffness;
      const double difference = faces[0].stiffness - faces[1].stiffness;
      const double opening_stiffness = walls.stiffness + 0.25 * sum; // D
      if (!(std::abs(opening_stiffness) > 0.0)) {
        failure = "casing contact: the casing's split has no stiffness (walls and faces softened)";
        return false;
      }
      const double kept = 1.0 - 0.25 * sum / opening_stiffness;
      local_tangent(direction, direction) +=
          sum - 0.25 * difference * difference / opening_stiffness;
      normal_rate[direction] += difference * kept;
      direction_stiffness[direction - 1] += sum * kept;
    }
    // unbonding layer: always active
    local_force[direction] += parameters_.layer_stiffness * relative[direction];
    local_tangent(direction, direction) += parameters_.layer_stiffness;
  }

  // Coulomb friction along the axis with the total bearing force (and the sub-element
  // waves' N_w, constant in the step) as normal force. Called with dN/dg = 1 so that the
  // tangent's first column is dT/dN.
  normal_force += trial_.wave_normal_force;
  const auto friction = friction_.evaluate_with_normal(committed_.friction, normal_force, 1.0,
                                                       Eigen::Vector2d(relative[0], 0.0));
  trial_.friction = friction.state;
  local_force[0] = friction.tangential_force[0];
  local_tangent(0, 0) = friction.tangent(1, 1);
  local_tangent.row(0) += friction.tangent(1, 0) * normal_rate;
  trial_.link_force = local_force;
  record_stress_work();
  scatter(local_force, local_tangent, force, tangent);
  if (has_expansion() && penetrated)
    add_expansion_terms(core_chord, direction_force, direction_stiffness, normal_rate,
                        friction.tangent(1, 0), force, tangent);
  return true;
}

CasingContact::FaceBearing CasingContact::bear(int face, double face_penetration,
                                               std::string& failure) const {
  FaceBearing result;
  if (!(face_penetration > 0.0))
    return result;
  const std::size_t lateral = face_lateral(face);
  const double area = parameters_.bearing_area(lateral);
  const double depth = parameters_.bearing_depth(lateral);
  result.loaded = true;
  result.strain = -face_penetration / depth;
  const auto response = bearing_[lateral].evaluate(committed_.faces[face], result.strain);
  result.state = response.state;
  result.force = -area * response.stress; // >= 0, pushes the core back
  result.stiffness = area * response.tangent / depth;
  if (!std::isfinite(result.force) || !std::isfinite(result.stiffness)) {
    failure = "casing contact: non-finite bearing stress";
    result.force = std::numeric_limits<double>::quiet_NaN();
  }
  return result;
}

CasingContact::WallResponse CasingContact::stretch_walls(int direction, double opening) const {
  const CasingSplitting& splitting = *parameters_.splitting;
  const std::size_t d = static_cast<std::size_t>(direction - 1);
  const double area = splitting.wall_area(d);
  const double length = splitting.wall_length(d);
  WallResponse result;
  result.strain = opening / length;
  const auto response = walls_[d].evaluate(committed_.walls[d], result.strain);
  result.state = response.state;
  result.force = area * response.stress;
  result.stiffness = area * response.tangent / length;
  return result;
}

bool CasingContact::solve_split(int direction, const std::array<double, 2>& kinematic,
                                std::array<FaceBearing, 2>& faces, WallResponse& walls,
                                double& opening, std::string& failure) const {
  // g(w) = T(w) - (F+(w) + F-(w)) / 2: g(0) < 0 (a face bears, the walls are unstretched),
  // g(w_open) = T >= 0 (both faces open), so a root lies in between; Newton on
  // dg/dw = dT/dw + (K+ + K-) / 4, bisection when a step leaves the bracket.
  double lower = 0.0;
  double upper = 2.0 * std::max(kinematic[0], kinematic[1]);
  const int first_face = 2 * (direction - 1);
  double trial = std::clamp(opening, lower, upper);
  constexpr int kMaxIterations = 200;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    for (int side = 0; side < 2; ++side)
      faces[static_cast<std::size_t>(side)] =
          bear(first_face + side, kinematic[side] - 0.5 * trial, failure);
    walls = stretch_walls(direction, trial);
    const double face_mean = 0.5 * (faces[0].force + faces[1].force);
    const double residual = walls.force - face_mean;
    if (!std::isfinite(residual) || !std::isfinite(walls.stiffness)) {
      if (failure.empty())
        failure = "casing contact: non-finite force in the casing's split walls";
      return false;
    }
    opening = trial;
    // converged to rounding of the forces, or the bracket is a few ulp wide
    if (std::abs(residual) <= 1e-13 * (face_mean + std::abs(walls.force)) ||
        upper - lower <= 1e-15 * upper)
      return true;
    if (residual < 0.0)
      lower = trial;
    else
      upper = trial;
    const double slope = walls.stiffness + 0.25 * (faces[0].stiffness + faces[1].stiffness);
    double next = slope > 0.0 ? trial - residual / slope : 0.5 * (lower + upper);
    if (!(next > lower && next < upper))
      next = 0.5 * (lower + upper);
    trial = next;
  }
  failure = "casing contact: the casing's split opening did not converge";
  return false;
}

void CasingContact::add_expansion_terms(const Chord& core_chord,
                                        const Eigen::Vector2d& direction_force,
                                        const Eigen::Vector2d& direction_stiffness,
                                        const Eigen::RowVector3d& normal_rate,
                                        double friction_normal_rate, Eigen::VectorXd& force,
                                        Eigen::MatrixXd& tangent) const {
  // e_d = m_d eps with m_d = -nu_c h_d / 2 and eps = l / l0 - 1 (l: the chord's length):
  // deps/dx_next = n / l0 = -deps/dx_previous, d2eps/dx_next2 = (I - n n^T) / (l0 l).
  // Stored energy W = sum over faces W_f(p_f), dp_f/de_d = 1, so the chord's ends get
  // Q deps/dx with Q = dW/deps = sum_d m_d S_d, and the tangent is
  //   d2W = sum_f k_f dp_f dp_f^T + Q d2eps:
  //   relative-chord: m_d K_r,d (dr_d/dx)(deps/dx)^T and its transpose,
  //   chord-chord:    sum_d m_d^2 K_d (deps/dx)(deps/dx)^T + Q d2eps,
  // and friction's row gets dT/dN dN/deps deps/dx, dN/deps = sum_d m_d K_d.
  const Matrix3& axes = parameters_.axes;
  const Eigen::Vector2d& m = expansion_per_strain_;
  const double l0 = chord_initial_length_;
  const Vector3 strain_rate = core_chord.direction / l0; // deps/dx_next
  const double energy_rate = m.dot(direction_force);     // Q
  Vector3 bearing_coupling = Vector3::Zero();            // sum_d m_d K_r,d a_d (global): dQ/dx_core
  for (int d = 0; d < 2; ++d)
    bearing_coupling += m[d] * normal_rate[d + 1] * axes.col(d + 1);
  const Vector3 row_coupling =
      bearing_coupling + friction_normal_rate * m.dot(direction_stiffness) * axes.col(0);
  const double chord_stiffness = m.cwiseProduct(m).dot(direction_stiffness);
  const Matrix3 chord_curvature =
      (Matrix3::Identity() - core_chord.direction * core_chord.direction.transpose()) /
      (l0 * core_chord.length);
  const Matrix3 chord_block = chord_stiffness * strain_rate * strain_rate.transpose() +
                              energy_rate * chord_curvature;             // d2W/dx_next2
  const Matrix3 relative_block = row_coupling * strain_rate.transpose(); // rows core, cols next
  const Matrix3 transposed_block = strain_rate * bearing_coupling.transpose();

  const std::array<int, 2> ends{6 * chord_ends_[0], 6 * chord_ends_[1]};
  const std::array<double, 2> end_sign{-1.0, 1.0}; // deps/dx_end = sign strain_rate
  for (int a = 0; a < 2; ++a) {
    force.segment<3>(ends[a]) += end_sign[a] * energy_rate * strain_rate;
    tangent.block<3, 3>(0, ends[a]) += end_sign[a] * relative_block;
    tangent.block<3, 3>(6, ends[a]) -= end_sign[a] * relative_block;
    tangent.block<3, 3>(ends[a], 0) += end_sign[a] * transposed_block;
    tangent.block<3, 3>(ends[a], 6) -= end_sign[a] * transposed_block;
    for (int b = 0; b < 2; ++b)
      tangent.block<3, 3>(ends[a], ends[b]) += end_sign[a] * end_sign[b] * chord_block;
  }
}

void CasingContact::record_stress_work() {
  // Trapezoidal rule on each face's force and signed penetration (the kinematic measure,
  // also when open, so that a face opening inside a step is summed as the external work
  // is), on the friction force and the axial relative displacement, and on the layer springs
  // (linear: exact).
  double work = 0.0;
  for (int face = 0; face < 4; ++face) {
    trial_.penetration[face] = penetration(face);
    work += (committed_.face_force[face] + trial_.face_force[face]) *
            (trial_.penetration[face] - committed_.penetration[face]);
  }
  const Vector3& relative = trial_.relative;
  const Vector3& start = committed_.relative;
  work += (committed_.link_force[0] + trial_.link_force[0]) * (relative[0] - start[0]);
  for (int direction = 1; direction <= 2; ++direction) {
    work += parameters_.layer_stiffness * (start[direction] + relative[direction]) *
            (relative[direction] - start[direction]);
  }
  trial_.stress_work = committed_.stress_work + 0.5 * work;
}

void CasingContact::save_state(io::StateWriter& out) const {
  out(*this);
}

void CasingContact::load_state(io::StateReader& in) {
  in(*this);
  revert_to_committed();
}

ElementEnergy CasingContact::energy() const {
  ElementEnergy energy;
  const double layer = parameters_.layer_stiffness;
  const Vector3& relative = trial_.relative;
  energy.stored = 0.5 * layer * (relative[1] * relative[1] + relative[2] * relative[2]);
  for (int face = 0; face < 4; ++face) {
    const std::size_t lateral = face_lateral(face);
    const double volume = parameters_.bearing_area(lateral) * parameters_.bearing_depth(lateral);
    energy.stored +=
        volume * bearing_[lateral].free_energy(trial_.faces[face], trial_.bearing_strain[face]);
    energy.dissipated += volume * material::MortarUniaxial::dissipated_energy(trial_.faces[face]);
  }
  for (std::size_t d = 0; d < walls_.size(); ++d) {
    // the walls' volume: area x L_w
    const CasingSplitting& splitting = *parameters_.splitting;
    const double volume = splitting.wall_area(d) * splitting.wall_length(d);
    energy.stored += volume * walls_[d].free_energy(trial_.walls[d], trial_.wall_strain[d]);
    energy.dissipated += volume * material::MortarUniaxial::dissipated_energy(trial_.walls[d]);
  }
  // friction: the stick spring's energy is stored, the slip work dissipated
  const double stick = relative[0] - trial_.friction.slip[0];
  energy.stored += 0.5 * parameters_.tangential_stiffness * stick * stick;
  energy.dissipated += trial_.friction.dissipated_energy;
  energy.integration_misfit = trial_.stress_work - energy.stored - energy.dissipated;
  return energy;
}

void CasingContact::mark_path_point() {
  for (std::size_t face = 0; face < path_damage_.size(); ++face)
    path_damage_[face] = trial_.faces[face].damage;
  for (std::size_t d = 0; d < path_wall_damage_.size(); ++d)
    path_wall_damage_[d] = trial_.walls[d].damage;
  path_opening_ = trial_.opening;
}

bool CasingContact::jumped_past_peak() const {
  for (std::size_t face = 0; face < path_damage_.size(); ++face) {
    if (path_damage_[face] < kPathIntactDamage && trial_.faces[face].damage > kPathCrushedDamage)
      return true;
  }
  for (std::size_t d = 0; d < path_wall_damage_.size(); ++d) {
    if (path_wall_damage_[d] < kPathIntactDamage && trial_.walls[d].damage > kPathCrushedDamage)
      return true;
  }
  return false;
}

double CasingContact::max_mortar_damage() const {
  double worst = 0.0;
  for (const auto& face : trial_.faces)
    worst = std::max(worst, face.damage);
  for (const auto& wall : trial_.walls) // 0 without CasingSplitting
    worst = std::max(worst, wall.damage);
  return worst;
}

double CasingContact::min_residual_strength() const {
  double weakest = 1.0;
  for (int face = 0; face < 4; ++face) {
    weakest = std::min(weakest, bearing_[face_lateral(face)].residual_strength(trial_.faces[face]));
  }
  for (std::size_t d = 0; d < walls_.size(); ++d) // none without CasingSplitting
    weakest = std::min(weakest, walls_[d].residual_strength(trial_.walls[d]));
  return weakest;
}

} // namespace brb::element
