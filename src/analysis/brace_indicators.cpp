#include "brb/analysis/brace_indicators.hpp"

#include <algorithm>
#include <cmath>

namespace brb::analysis {
namespace {

// Global buckling needs, beside a bow beyond L_y / kGlobalBucklingRatio, that over a step that
// shortens the brace the bow grows by more than the shortening
// while the brace stiffens by less than this fraction of its elastic axial stiffness
// P_y / d_y: the shortening goes into the bow, not into the core
constexpr double kGlobalBucklingStiffnessRatio = 0.5;

} // namespace

BraceIndicatorTracker::BraceIndicatorTracker(const model::BraceHandles& brace,
                                             const model::Model& model)
    : brace_(&brace), model_(&model) {
  for (const int node : brace.nodes)
    initial_positions_.push_back(model.coordinates(node));
  for (std::size_t e = 0; e < brace.beams.size(); ++e) {
    if (brace.in_yielding_zone[e])
      yielding_length_ += brace.beams[e]->local_beam().length();
  }
  if (brace.truss)
    yielding_length_ = brace.truss->parameters().yielding_length;
}

double BraceIndicatorTracker::max_lateral_displacement(const Positions& position) const {
  double largest = 0.0;
  for (std::size_t n = 0; n < brace_->nodes.size(); ++n) {
    const element::Vector3 motion = position(brace_->nodes[n]) - initial_positions_[n];
    largest = std::max(
        largest, std::hypot(motion.dot(brace_->axes.col(1)), motion.dot(brace_->axes.col(2))));
  }
  return largest;
}

void BraceIndicatorTracker::observe(const Positions& position, double deformation, double force) {
  const model::BraceHandles& brace = *brace_;
  BraceIndicators& indicators = indicators_;
  int uniform_beams = 0;
  const auto count_uniform = [&uniform_beams](const auto& beam) {
    if (beam.local_beam().committed_axial_strain_field() == element::AxialStrainField::uniform)
      ++uniform_beams;
  };
  for (const auto* beam : brace.beams) {
    for (const auto& section : beam->local_beam().sections()) {
      indicators.max_steel_damage = std::max(indicators.max_steel_damage, section.max_damage());
    }
    count_uniform(*beam);
  }
  if (brace.truss)
    indicators.max_steel_damage = std::max(indicators.max_steel_damage, brace.truss->damage());
  // lateral motion: components along the section axes y and z
  const auto lateral_of = [&](int node, const element::Vector3& initial) {
    const element::Vector3 motion = position(node) - initial;
    return Eigen::Vector2d(motion.dot(brace.axes.col(1)), motion.dot(brace.axes.col(2)));
  };
  for (std::size_t n = 0; n < brace.nodes.size(); ++n) {
    indicators.max_core_lateral_displacement =
        std::max(indicators.max_core_lateral_displacement,
                 lateral_of(brace.nodes[n], initial_positions_[n]).norm());
  }
  // Global buckling is the brace bowing as a whole: lateral offsets from the current chord
  // of its outer nodes (so a brace that rotates or translates rigidly, as in a frame, does
  // not count), at the place each node had along the initial chord.
  const element::Vector3& start_initial = initial_positions_.front();
  const element::Vector3 initial_chord = initial_positions_.back() - start_initial;
  const element::Vector3& start_now = position(brace.start_node);
  const element::Vector3 chord_now = position(brace.end_node) - start_now;
  const auto bow_of = [&](int node) {
    const element::Vector3 initial = model_->coordinates(node);
    const double along = (initial - start_initial).dot(initial_chord) / initial_chord.squaredNorm();
    const element::Vector3 offset = position(node) - (start_now + along * chord_now) -
                                    (initial - (start_initial + along * initial_chord));
    return Eigen::Vector2d(offset.dot(brace.axes.col(1)), offset.dot(brace.axes.col(2)));
  };
  double global_bow = 0.0;
  // Lateral displacement of the yielding core's stations, relative to the casing if any.
  std::vector<Eigen::Vector2d> relative;
  double casing_lateral = 0.0;
  if (brace.casing) {
    const auto& casing = *brace.casing;
    for (const auto* contact : casing.contacts) {
      indicators.max_bearing_damage =
          std::max(indicators.max_bearing_damage, contact->max_mortar_damage());
      indicators.min_bearing_residual_strength =
          std::min(indicators.min_bearing_residual_strength, contact->min_residual_strength());
    }
    indicators.max_mortar_damage =
        std::max(indicators.max_mortar_damage, indicators.max_bearing_damage);
    for (const auto* beam : casing.beams) {
      for (const auto& section : beam->local_beam().sections()) {
        indicators.max_mortar_damage =
            std::max(indicators.max_mortar_damage, section.second().max_damage());
        indicators.min_fill_residual_strength = std::min(indicators.min_fill_residual_strength,
                                                         section.second().min_residual_strength());
      }
      count_uniform(*beam);
    }
    const auto& link = casing.interior_link;
    for (std::size_t s = 0; s < casing.nodes.size(); ++s) {
      const int casing_node = casing.nodes[s];
      const Eigen::Vector2d casing_motion =
          lateral_of(casing_node, model_->coordinates(casing_node));
      casing_lateral = std::max(casing_lateral, casing_motion.norm());
      // the casing may shift sideways by the clearance without the brace bowing
      const Eigen::Vector2d bow = bow_of(casing_node);
      global_bow = std::max(global_bow, std::hypot(std::max(0.0, std::abs(bow[0]) - link.gap_y),
                                                   std::max(0.0, std::abs(bow[1]) - link.gap_z)));
      const int core_node = casing.core_nodes[s];
      relative.push_back(lateral_of(core_node, model_->coordinates(core_node)) - casing_motion);
    }
    indicators.max_casing_lateral_displacement =
        std::max(indicators.max_casing_lateral_displacement, casing_lateral);
    // Casing failure: the mortar under a station crushed through (or, with casing/splitting,
    // its walls split through: min_bearing_residual_strength holds both); or, in a mortar-only
    // casing (the thesis's small BRB), the casing itself cracked or crushed through. In a
    // steel tube the fill cracks as soon as the casing bends, and the tube still holds.
    if (indicators.min_bearing_residual_strength <= kCrushedResidualStrength ||
        (!casing.steel_tube && indicators.min_fill_residual_strength <= kCrushedResidualStrength))
      indicators.casing_failure = true;
  } else {
    for (const int node : brace.nodes)
      global_bow = std::max(global_bow, bow_of(node).norm());
    for (std::size_t e = 0; e < brace.beams.size(); ++e) {
      if (!brace.in_yielding_zone[e])
        continue;
      if (relative.empty())
        relative.push_back(lateral_of(brace.nodes[e], initial_positions_[e]));
      relative.push_back(lateral_of(brace.nodes[e + 1], initial_positions_[e + 1]));
    }
  }
  // half-waves in the direction of the largest motion
  int direction = 0;
  double largest = 0.0;
  for (const auto& u : relative) {
    for (int k = 0; k < 2; ++k) {
      if (std::abs(u[k]) > largest) {
        largest = std::abs(u[k]);
        direction = k;
      }
    }
  }
  // buckling happens in compression: count the half-waves there only
  if (force < 0.0 && largest > 1e-3) {
    int half_waves = 0;
    double previous_sign = 0.0;
    for (const auto& u : relative) {
      if (std::abs(u[direction]) < 0.1 * largest)
        continue;
      const double sign = u[direction] > 0.0 ? 1.0 : -1.0;
      if (sign != previous_sign)
        ++half_waves;
      previous_sign = sign;
    }
    indicators.max_buckling_half_waves = std::max(indicators.max_buckling_half_waves, half_waves);
  }
  indicators.uniform_axial_strain_beams =
      std::max(indicators.uniform_axial_strain_beams, uniform_beams);
  if (indicators.max_steel_damage >= kFractureDamage)
    indicators.core_fracture = true;
  const double shortening = previous_deformation_ - deformation; // > 0: shorter
  if (yielding_length_ > 0.0 && global_bow > yielding_length_ / kGlobalBucklingRatio &&
      shortening > 0.0 && force < 0.0 && global_bow - previous_bow_ > shortening) {
    const double elastic_stiffness = brace.yield_force / brace.yield_deformation;
    const double step_stiffness = (previous_force_ - force) / shortening;
    if (step_stiffness < kGlobalBucklingStiffnessRatio * elastic_stiffness)
      indicators.global_buckling = true;
  }
  previous_bow_ = global_bow;

  indicators.cumulative_inelastic_deformation +=
      inelastic_deformation_increment(deformation - previous_deformation_, force - previous_force_,
                                      brace.yield_force, brace.yield_deformation);
  previous_deformation_ = deformation;
  previous_force_ = force;
}

double inelastic_deformation_increment(double d_deformation, double d_force, double yield_force,
                                       double yield_deformation) {
  const double elastic_stiffness = yield_force / yield_deformation;
  return std::abs(d_deformation - d_force / elastic_stiffness) / yield_deformation;
}

} // namespace brb::analysis
