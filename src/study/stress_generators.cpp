#include "brb/study/stress_generators.hpp"

#include "brb/io/protocol.hpp"
#include "brb/model/brace_fidelity.hpp"
#include "brb/model/brace_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace brb::study {

double unit_uniform(std::mt19937_64& engine) {
  // 53 random bits over 2^53: uniform on [0, 1) with the double's full precision, the same
  // on every platform (the engine's sequence is fixed by the standard).
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

std::vector<double> random_turning_points(std::uint64_t seed, int reversals, double max_amplitude) {
  if (reversals < 1)
    throw std::invalid_argument("a random history needs at least one reversal");
  if (!(max_amplitude > 0.0) || !std::isfinite(max_amplitude))
    throw std::invalid_argument("the amplitude limit of a random history must be > 0");
  std::mt19937_64 engine(seed);
  bool going_up = unit_uniform(engine) < 0.5;
  std::vector<double> points;
  double previous = 0.0;
  for (int k = 0; k <= reversals; ++k) {
    const double u = unit_uniform(engine);
    const double next = going_up ? previous + u * (max_amplitude - previous)
                                 : previous - u * (max_amplitude + previous);
    points.push_back(next);
    previous = next;
    going_up = !going_up;
  }
  points.push_back(0.0);
  return points;
}

std::vector<double> history_points(const std::vector<double>& turning_points, double max_step) {
  return io::history_protocol("stress history", turning_points, max_step).deformation;
}

BraceYield brace_yield(const model::BraceSpec& spec) {
  const element::BraceTrussParameters truss = model::truss_parameters(spec);
  BraceYield yield;
  yield.force = spec.steel.yield_stress * truss.core_area;
  yield.yielding_length = truss.yielding_length;
  const double core_deformation =
      yield.force * truss.yielding_length / (truss.core_area * spec.steel.youngs_modulus);
  yield.end_zone_deformation = yield.force * truss.end_flexibility;
  yield.deformation = core_deformation + yield.end_zone_deformation;
  return yield;
}

double compression_target(const BraceYield& yield, double core_strain) {
  return -(core_strain * yield.yielding_length + 1.5 * yield.end_zone_deformation);
}

model::BraceSpec brace_variant(model::BraceSpec brace, model::Fidelity fidelity,
                               int core_elements) {
  brace.element.fidelity = fidelity;
  brace.core_elements = core_elements;
  return brace;
}

namespace {

model::CasingSpec& casing_of(model::BraceSpec& brace) {
  if (!brace.casing)
    throw std::invalid_argument("the near-singular stress cases need a brace with a casing");
  return *brace.casing;
}

/// The tube's outer size and wall times `scale`.
model::SectionSpec scaled_tube(model::SectionSpec tube, double scale) {
  tube.width *= scale;
  tube.depth *= scale;
  tube.diameter *= scale;
  tube.wall *= scale;
  return tube;
}

/// Whether the scaled tube leaves room for mortar around the core's opening.
bool tube_fits(const model::BraceSpec& brace, const model::SectionSpec& tube) {
  const auto [extent_y, extent_z] = model::core_extent(brace.core_section);
  const model::CasingSpec& casing = *brace.casing;
  if (tube.shape == model::SectionShape::circular_tube)
    return tube.diameter - 2.0 * tube.wall > extent_y + 2.0 * casing.gap_y;
  return tube.width - 2.0 * tube.wall > extent_y + 2.0 * casing.gap_y &&
         tube.depth - 2.0 * tube.wall > extent_z + 2.0 * casing.gap_z;
}

} // namespace

model::BraceSpec with_gap(model::BraceSpec brace, double gap) {
  casing_of(brace).gap_y = gap;
  casing_of(brace).gap_z = gap;
  return brace;
}

model::BraceSpec with_friction(model::BraceSpec brace, double friction) {
  casing_of(brace).friction_coefficient = friction;
  return brace;
}

double casing_euler_ratio(const model::BraceSpec& brace) {
  const double yield_force = brace.steel.yield_stress * brace.core_section.mesh().total_area();
  return std::pow(std::numbers::pi / brace.yielding_length, 2) *
         model::casing_assembly_flexural_rigidity(brace) / yield_force;
}

model::BraceSpec with_casing_euler_ratio(model::BraceSpec brace, double euler_ratio) {
  model::CasingSpec& casing = casing_of(brace);
  if (!casing.steel_tube)
    throw std::invalid_argument("scaling the casing to an Euler load needs a steel tube");
  const model::SectionSpec original = casing.tube;
  const auto ratio_at = [&](double scale) {
    casing.tube = scaled_tube(original, scale);
    return casing_euler_ratio(brace);
  };
  // Bracket: the smallest scale that leaves mortar around the opening, and a scale large
  // enough. The Euler load grows with the scale (tube and fill both grow).
  double low = 1.0;
  while (tube_fits(brace, scaled_tube(original, low * 0.99)) && low > 1e-3)
    low *= 0.99;
  double high = 1.0;
  while (ratio_at(high) < euler_ratio && high < 1e3)
    high *= 2.0;
  if (ratio_at(low) > euler_ratio || ratio_at(high) < euler_ratio) {
    throw std::invalid_argument("no tube size gives a casing Euler load of " +
                                std::to_string(euler_ratio) + " P_y");
  }
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double middle = 0.5 * (low + high);
    const double ratio = ratio_at(middle);
    if (std::abs(ratio - euler_ratio) <= 1e-6 * euler_ratio)
      break;
    (ratio < euler_ratio ? low : high) = middle;
  }
  return brace;
}

FrameStress frame_stress(const model::FrameSpec& frame, const std::string& source,
                         frame::BraceOverride braces, const io::GroundMotion& motion, double scale,
                         double duration) {
  FrameStress stress;
  stress.frame = frame;
  stress.source = source;
  stress.braces = braces;
  stress.record = motion.name;
  stress.scale = scale;
  stress.dt = motion.dt;
  stress.acceleration = motion.acceleration;
  if (duration > 0.0) {
    const auto samples = static_cast<std::size_t>(std::floor(duration / motion.dt + 1e-9)) + 1;
    if (samples < stress.acceleration.size())
      stress.acceleration.resize(samples);
  }
  for (double& value : stress.acceleration)
    value *= scale;
  return stress;
}

} // namespace brb::study
