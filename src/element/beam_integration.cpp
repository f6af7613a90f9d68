#include "brb/element/beam_integration.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::element {

BeamIntegration BeamIntegration::make(IntegrationRule rule, int points) {
  // Abscissae and weights on [-1, 1] (Abramowitz & Stegun 25.4.29-30), mapped to [0, 1].
  std::vector<double> x, w;
  if (rule == IntegrationRule::gauss_legendre) {
    switch (points) {
    case 1:
      x = {0.0};
      w = {2.0};
      break;
    case 2:
      x = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
      w = {1.0, 1.0};
      break;
    case 3:
      x = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
      w = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
      break;
    case 4: {
      const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
      const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
      const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
      x = {-b, -a, a, b};
      w = {wb, wa, wa, wb};
      break;
    }
    case 5: {
      const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
      const double b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
      const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
      const double wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
      x = {-b, -a, 0.0, a, b};
      w = {wb, wa, 128.0 / 225.0, wa, wb};
      break;
    }
    default:
      throw ParameterError("integration_points", "Gauss-Legendre needs 1 to 5 points (got " +
                                                     std::to_string(points) + ")");
    }
  } else {
    switch (points) {
    case 2:
      x = {-1.0, 1.0};
      w = {1.0, 1.0};
      break;
    case 3:
      x = {-1.0, 0.0, 1.0};
      w = {1.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0};
      break;
    case 4: {
      const double a = 1.0 / std::sqrt(5.0);
      x = {-1.0, -a, a, 1.0};
      w = {1.0 / 6.0, 5.0 / 6.0, 5.0 / 6.0, 1.0 / 6.0};
      break;
    }
    case 5: {
      const double a = std::sqrt(3.0 / 7.0);
      x = {-1.0, -a, 0.0, a, 1.0};
      w = {0.1, 49.0 / 90.0, 32.0 / 45.0, 49.0 / 90.0, 0.1};
      break;
    }
    case 6: {
      const double a = std::sqrt(1.0 / 3.0 - 2.0 * std::sqrt(7.0) / 21.0);
      const double b = std::sqrt(1.0 / 3.0 + 2.0 * std::sqrt(7.0) / 21.0);
      const double wa = (14.0 + std::sqrt(7.0)) / 30.0, wb = (14.0 - std::sqrt(7.0)) / 30.0;
      x = {-1.0, -b, -a, a, b, 1.0};
      w = {1.0 / 15.0, wb, wa, wa, wb, 1.0 / 15.0};
      break;
    }
    default:
      throw ParameterError("integration_points", "Gauss-Lobatto needs 2 to 6 points (got " +
                                                     std::to_string(points) + ")");
    }
  }
  BeamIntegration integration;
  for (std::size_t i = 0; i < x.size(); ++i) {
    integration.locations.push_back(0.5 * (x[i] + 1.0));
    integration.weights.push_back(0.5 * w[i]);
  }
  return integration;
}

} // namespace brb::element
