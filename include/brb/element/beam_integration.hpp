// Integration rules along a beam, on xi in [0, 1] with weights summing to 1.
#pragma once

#include <string>
#include <vector>

namespace brb::element {

enum class IntegrationRule { gauss_legendre, gauss_lobatto };

struct BeamIntegration {
  std::vector<double> locations; ///< xi in [0, 1]
  std::vector<double> weights;   ///< sum to 1

  /// Gauss-Legendre with 1..5 points or Gauss-Lobatto with 2..6 points (ends included);
  /// throws ParameterError("integration_points") otherwise.
  static BeamIntegration make(IntegrationRule rule, int points);
};

} // namespace brb::element
