#include "brb/design/check.hpp"

#include "brb/model/brace_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace brb::design {

DriftDemand drift_demand(const CheckSpec& check, double story_drift) {
  DriftDemand demand;
  demand.story_drift = story_drift;
  // AISC341_NOTES.md: for Delta_bm the design story drift is not taken less than 0.01 h.
  demand.minimum_drift = check.edition.minimum_drift_ratio * check.story.story_height;
  demand.used_story_drift = std::max(story_drift, demand.minimum_drift);
  demand.small_displacement_deformation =
      brace_deformation_small(check.story, demand.used_story_drift);
  demand.design_deformation = demand.small_displacement_deformation;
  demand.kinematics = "small-displacement formula Delta cos(theta), " +
                      to_string(check.story.configuration) + " brace";
  if (check.frame_brace) {
    demand.frame_deformation =
        design_deformation_in_frame(*check.frame_brace, demand.used_story_drift);
    demand.design_deformation = *demand.frame_deformation;
    demand.kinematics = "frame geometry: story " + check.frame_brace->story +
                        " top level translated rigidly by the drift, exact change of the "
                        "brace's length (larger of the two directions)";
  }
  return demand;
}

YieldForces yield_forces(const CheckSpec& check, double core_area) {
  YieldForces forces;
  forces.core_area = core_area;
  if (check.fysc_measured) {
    forces.tested = core_area * *check.fysc_measured;
    forces.tested_basis = "Asc x measured Fysc";
  } else {
    forces.tested = core_area * check.Ry * *check.fysc_specified;
    forces.tested_basis = "Asc x Ry x specified Fysc";
  }
  forces.design = core_area * check.fysc_specified.value_or(check.fysc_measured.value_or(0.0));
  return forces;
}

QualificationResult qualify(const CheckSpec& check, double design_deformation) {
  model::BraceModel brace = model::build_brace_model(check.brace);
  QualificationInput input;
  input.design_deformation = design_deformation;
  input.tested_yield_force = yield_forces(check, brace.core_area).tested;
  input.edition = check.edition;
  input.beta_limit = check.beta_limit();
  input.max_step = check.max_step * brace.yield_deformation;
  return run_qualification(brace, input);
}

CheckResult run_check(const CheckSpec& check) {
  CheckResult result;
  {
    const model::BraceModel brace = model::build_brace_model(check.brace);
    result.yield_deformation = brace.yield_deformation;
    result.yield_force = brace.yield_force;
    result.forces = yield_forces(check, brace.core_area);
    result.warnings = brace.warnings;
  }
  result.demand = drift_demand(check, check.design_story_drift());
  result.qualification = qualify(check, result.demand.design_deformation);
  // F4.2a: tension omega Ry Pysc, compression beta omega Ry Pysc.
  result.adjusted_tension = result.qualification.omega * check.Ry * result.forces.design;
  result.adjusted_compression = result.qualification.beta * result.adjusted_tension;
  if (check.drift_capacity) {
    const double design_ratio = result.demand.used_story_drift / check.story.story_height;
    result.drift_capacity =
        find_drift_capacity(check, *check.drift_capacity, design_ratio, result.qualification.passed,
                            failed_criteria(result.qualification));
  }
  return result;
}

DriftCapacity find_drift_capacity(const CheckSpec& check, const DriftCapacitySpec& spec,
                                  double design_ratio, bool passed_at_design,
                                  const std::string& failed_at_design) {
  DriftCapacity capacity;
  capacity.resolution = spec.resolution;
  capacity.upper = spec.upper;
  const double height = check.story.story_height;
  const auto trial = [&](double ratio) {
    const double dbm = drift_demand(check, ratio * height).design_deformation;
    const QualificationResult result = qualify(check, dbm);
    capacity.trials.push_back({ratio, dbm, result.passed, failed_criteria(result)});
    return capacity.trials.back();
  };
  const double minimum = check.edition.minimum_drift_ratio;
  double low = 0.0;
  double high = 0.0;
  std::string failed_high;
  if (passed_at_design) {
    low = design_ratio;
    if (design_ratio >= spec.upper) {
      capacity.drift_ratio = design_ratio;
      capacity.upper_passed = true;
      return capacity;
    }
    const DriftTrial top = trial(spec.upper);
    if (top.passed) {
      capacity.drift_ratio = spec.upper;
      capacity.upper_passed = true;
      return capacity;
    }
    high = spec.upper;
    failed_high = top.failed;
  } else {
    high = design_ratio;
    failed_high = failed_at_design;
    if (design_ratio <= minimum) {
      capacity.limited_by = failed_high;
      return capacity; // fails at the minimum drift: no capacity
    }
    const DriftTrial bottom = trial(minimum);
    if (!bottom.passed) {
      capacity.limited_by = bottom.failed;
      return capacity;
    }
    low = minimum;
  }
  // Bisection: `low` passes, `high` fails.
  while (high - low > spec.resolution) {
    const double middle = 0.5 * (low + high);
    const DriftTrial middle_trial = trial(middle);
    if (middle_trial.passed) {
      low = middle;
    } else {
      high = middle;
      failed_high = middle_trial.failed;
    }
  }
  capacity.drift_ratio = low;
  capacity.bracket = high - low;
  capacity.limited_by = failed_high;
  return capacity;
}

} // namespace brb::design
