#include "brb/validation/steel_calibration.hpp"

#include "brb/material/steel_uniaxial.hpp"
#include "brb/validation/record_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace brb::validation {

AxialBraceIdealisation AxialBraceIdealisation::of(const model::BraceSpec& brace) {
  AxialBraceIdealisation result;
  result.youngs_modulus = brace.steel.youngs_modulus;
  result.core_area = brace.core_section.mesh().total_area();
  result.yielding_length = brace.yielding_length;
  for (const auto* zone : {&brace.transition, &brace.connection}) {
    if (*zone) {
      const double area = (*zone)->section.mesh().total_area();
      result.end_zone_flexibility += 2.0 * (*zone)->length / (result.youngs_modulus * area);
    }
  }
  return result;
}

double AxialBraceIdealisation::yield_deformation(double yield_stress) const {
  return yield_stress * core_area *
         (yielding_length / (youngs_modulus * core_area) + end_zone_flexibility);
}

std::vector<double> fast_brace_forces(const material::SteelParameters& steel,
                                      const AxialBraceIdealisation& brace,
                                      std::span<const double> deformation) {
  material::SteelParameters law_parameters = steel;
  law_parameters.damage.reset();
  const material::SteelUniaxial law(law_parameters, 1.0);
  material::SteelStateUniaxial committed = law.initial_state();

  const double length = brace.yielding_length;
  const double area = brace.core_area;
  const double flexibility = brace.end_zone_flexibility;
  // Residual r(eps) = eps L_y + A sigma(eps) f_e - delta, increasing in eps (tangent >= 0
  // for this law without damage), so a bracket [low, high] with r(low) <= 0 <= r(high)
  // always exists: the core strain lies between 0-force and all-in-the-core limits.
  std::vector<double> forces;
  forces.reserve(deformation.size());
  double strain = 0.0;
  double force = 0.0;
  for (const double delta : deformation) {
    const double tolerance =
        1e-12 * (std::abs(delta) + length * steel.yield_stress / steel.youngs_modulus);
    // Bracket: with the force at the previous point, the end zones take N f_e; the core
    // strain lies between the strains for zero force and for "all deformation in the core".
    double low = std::min(delta / length, (delta - force * flexibility) / length);
    double high = std::max(delta / length, (delta - force * flexibility) / length);
    const auto residual_at = [&](double eps, material::SteelUniaxial::Response& response) {
      response = law.evaluate(committed, eps);
      return eps * length + area * response.stress * flexibility - delta;
    };
    material::SteelUniaxial::Response response;
    // Widen the bracket until it holds the root (the law's stress is bounded by its
    // saturation or grows slowly, so a few doublings suffice).
    double width = std::max(high - low, 1e-6);
    for (int i = 0; residual_at(low, response) > 0.0; ++i) {
      low -= width;
      width *= 2.0;
      if (i > 60)
        throw std::runtime_error("fast_brace_forces: no bracket for the core strain");
    }
    width = std::max(high - low, 1e-6);
    for (int i = 0; residual_at(high, response) < 0.0; ++i) {
      high += width;
      width *= 2.0;
      if (i > 60)
        throw std::runtime_error("fast_brace_forces: no bracket for the core strain");
    }
    double eps = std::clamp(strain + (delta - (strain * length + force * flexibility)) /
                                         (length + area * steel.youngs_modulus * flexibility),
                            low, high);
    bool converged = false;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double r = residual_at(eps, response);
      if (std::abs(r) <= tolerance) {
        converged = true;
        break;
      }
      (r > 0.0 ? high : low) = eps;
      const double slope = length + area * response.tangent * flexibility;
      double next = eps - r / slope;
      if (!(next > low && next < high))
        next = 0.5 * (low + high); // Newton left the bracket: bisect
      if (high - low <= 1e-15 * std::max(1.0, std::abs(eps))) {
        converged = true;
        break;
      }
      eps = next;
    }
    if (!converged)
      throw std::runtime_error("fast_brace_forces: the core strain did not converge");
    residual_at(eps, response);
    committed = response.state;
    strain = eps;
    force = area * response.stress;
    forces.push_back(force);
  }
  return forces;
}

CalibrationBounds CalibrationBounds::for_start(const material::SteelParameters& start) {
  CalibrationBounds bounds{};
  const double fy = start.yield_stress;
  const double lower[kCount] = {0.7 * fy, 100.0, 1.0, 10.0, 0.1, 0.1, 0.1};
  const double upper[kCount] = {1.5 * fy, 2e5, 2000.0, 2e4, 200.0, 400.0, 100.0};
  for (int i = 0; i < kCount; ++i) {
    bounds.lower[i] = lower[i];
    bounds.upper[i] = upper[i];
    bounds.logarithmic[i] = i > 0;
  }
  return bounds;
}

namespace {

double logistic(double u) {
  return 1.0 / (1.0 + std::exp(-u));
}

double logit(double s) {
  return std::log(s / (1.0 - s));
}

/// Bounds by transformation: parameter = lower + (upper - lower) s(u) (or the same on
/// log(parameter)), s the logistic function, so every real u is a parameter within bounds and
/// the simplex moves freely in u.
double to_parameter(const CalibrationBounds& bounds, int i, double u) {
  const double s = logistic(u);
  if (bounds.logarithmic[i]) {
    return std::exp(std::log(bounds.lower[i]) +
                    s * (std::log(bounds.upper[i]) - std::log(bounds.lower[i])));
  }
  return bounds.lower[i] + s * (bounds.upper[i] - bounds.lower[i]);
}

double to_unbounded(const CalibrationBounds& bounds, int i, double parameter) {
  double s = bounds.logarithmic[i]
                 ? (std::log(parameter) - std::log(bounds.lower[i])) /
                       (std::log(bounds.upper[i]) - std::log(bounds.lower[i]))
                 : (parameter - bounds.lower[i]) / (bounds.upper[i] - bounds.lower[i]);
  s = std::clamp(s, 1e-6, 1.0 - 1e-6);
  return logit(s);
}

material::SteelParameters with_values(material::SteelParameters steel, const double values[7]) {
  steel.yield_stress = values[0];
  steel.chaboche = {{values[1], values[2]}, {values[3], values[4]}};
  steel.voce_saturation = values[5];
  steel.voce_rate = values[6];
  return steel;
}

/// normalised RMS error over the points selected by `mask`.
double masked_error(std::span<const double> model, std::span<const double> test,
                    const std::vector<bool>& mask) {
  std::vector<double> m, t;
  for (std::size_t i = 0; i < test.size(); ++i) {
    if (mask[i]) {
      m.push_back(model[i]);
      t.push_back(test[i]);
    }
  }
  return normalised_rms_force_error(m, t);
}

} // namespace

CalibrationResult
calibrate_steel(const material::SteelParameters& start, const AxialBraceIdealisation& brace,
                std::span<const double> deformation, std::span<const double> test_force,
                const std::vector<bool>& compared, const CalibrationOptions& options) {
  if (deformation.size() != test_force.size() || compared.size() != test_force.size())
    throw std::invalid_argument("calibrate_steel: the series differ in length");
  std::vector<bool> all = compared;
  std::vector<bool> tension = compared;
  for (std::size_t i = 0; i < test_force.size(); ++i)
    tension[i] = compared[i] && test_force[i] >= 0.0;
  const std::vector<bool>& objective_mask =
      options.side == CalibrationSide::tension ? tension : all;

  const CalibrationBounds bounds = CalibrationBounds::for_start(start);
  // Deterministic start: the given fy; back-stresses saturating at 60 MPa (fast, gamma 100)
  // and 100 MPa (slow, gamma 10); a Voce term of 40 MPa at rate 5. Mid-range values of
  // structural mild steel fits (order of magnitude), not tuned to any record.
  const double initial[CalibrationBounds::kCount] = {
      std::clamp(start.yield_stress, bounds.lower[0] * 1.0001, bounds.upper[0] * 0.9999),
      6000.0,
      100.0,
      1000.0,
      10.0,
      40.0,
      5.0};
  std::vector<double> u(CalibrationBounds::kCount);
  for (int i = 0; i < CalibrationBounds::kCount; ++i)
    u[i] = to_unbounded(bounds, i, initial[i]);

  const auto parameters_of = [&](const std::vector<double>& point) {
    double values[CalibrationBounds::kCount];
    for (int i = 0; i < CalibrationBounds::kCount; ++i)
      values[i] = to_parameter(bounds, i, point[i]);
    return with_values(start, values);
  };
  const auto objective = [&](const std::vector<double>& point) {
    try {
      const std::vector<double> model = fast_brace_forces(parameters_of(point), brace, deformation);
      return masked_error(model, test_force, objective_mask);
    } catch (const std::runtime_error&) {
      return std::numeric_limits<double>::infinity();
    }
  };

  CalibrationResult result;
  if (options.max_evaluations > 0) {
    result.start_objective = objective(u);
    const SimplexMinimum minimum =
        nelder_mead(objective, u, 1.0, 1e-7, options.max_evaluations, options.restarts);
    result.steel = parameters_of(minimum.point);
    result.evaluations = 1 + minimum.evaluations;
  } else {
    result.steel = start; // evaluate the given parameters as they are
  }
  result.model_force = fast_brace_forces(result.steel, brace, deformation);
  result.error_all = masked_error(result.model_force, test_force, all);
  result.error_tension = masked_error(result.model_force, test_force, tension);
  result.objective =
      options.side == CalibrationSide::tension ? result.error_tension : result.error_all;
  if (options.max_evaluations == 0) {
    result.start_objective = result.objective;
    result.evaluations = 1;
  }
  return result;
}

SimplexMinimum nelder_mead(const std::function<double(const std::vector<double>&)>& objective,
                           std::vector<double> start, double step, double value_tolerance,
                           int max_evaluations, int restarts) {
  const std::size_t n = start.size();
  SimplexMinimum best{start, objective(start), 1};
  for (int round = 0; round <= restarts && best.evaluations < max_evaluations; ++round) {
    // Simplex: the best point so far and one vertex per coordinate direction.
    std::vector<std::vector<double>> vertex(n + 1, best.point);
    std::vector<double> value(n + 1, best.value);
    for (std::size_t i = 0; i < n; ++i) {
      vertex[i + 1][i] += step;
      value[i + 1] = objective(vertex[i + 1]);
      ++best.evaluations;
    }
    std::vector<std::size_t> order(n + 1);
    const auto point_along = [&](const std::vector<double>& centroid,
                                 const std::vector<double>& worst, double coefficient) {
      std::vector<double> point(n);
      for (std::size_t j = 0; j < n; ++j)
        point[j] = centroid[j] + coefficient * (worst[j] - centroid[j]);
      return point;
    };
    while (best.evaluations < max_evaluations) {
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(),
                [&](std::size_t a, std::size_t b) { return value[a] < value[b]; });
      const std::size_t lowest = order.front();
      const std::size_t worst = order.back();
      const std::size_t second_worst = order[n - 1];
      if (value[worst] - value[lowest] <= value_tolerance)
        break;
      std::vector<double> centroid(n, 0.0);
      for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t j = 0; j < n; ++j)
          centroid[j] += vertex[order[k]][j] / static_cast<double>(n);
      }
      const std::vector<double> reflected = point_along(centroid, vertex[worst], -1.0);
      const double reflected_value = objective(reflected);
      ++best.evaluations;
      if (reflected_value < value[lowest]) {
        const std::vector<double> expanded = point_along(centroid, vertex[worst], -2.0);
        const double expanded_value = objective(expanded);
        ++best.evaluations;
        if (expanded_value < reflected_value) {
          vertex[worst] = expanded;
          value[worst] = expanded_value;
        } else {
          vertex[worst] = reflected;
          value[worst] = reflected_value;
        }
        continue;
      }
      if (reflected_value < value[second_worst]) {
        vertex[worst] = reflected;
        value[worst] = reflected_value;
        continue;
      }
      // Contraction: outside when the reflected point is better than the worst, else inside.
      const bool outside = reflected_value < value[worst];
      const std::vector<double> contracted =
          point_along(centroid, vertex[worst], outside ? -0.5 : 0.5);
      const double contracted_value = objective(contracted);
      ++best.evaluations;
      if (contracted_value < (outside ? reflected_value : value[worst])) {
        vertex[worst] = contracted;
        value[worst] = contracted_value;
        continue;
      }
      // Shrink towards the best vertex.
      for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t index = order[k];
        for (std::size_t j = 0; j < n; ++j)
          vertex[index][j] = vertex[lowest][j] + 0.5 * (vertex[index][j] - vertex[lowest][j]);
        value[index] = objective(vertex[index]);
        ++best.evaluations;
      }
    }
    const auto lowest =
        static_cast<std::size_t>(std::min_element(value.begin(), value.end()) - value.begin());
    const bool improved = value[lowest] < best.value - value_tolerance;
    if (value[lowest] < best.value) {
      best.point = vertex[lowest];
      best.value = value[lowest];
    }
    if (!improved && round > 0)
      break; // a restart that finds nothing better: converged
  }
  return best;
}

} // namespace brb::validation
