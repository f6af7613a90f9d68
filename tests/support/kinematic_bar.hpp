// Independent reference for tests: the axial force of a straight bar under uniform strain
// delta / L through the closed-form uniaxial law of linear kinematic hardening (elastic
// predictor, radial return onto |sigma - alpha| = fy, d(alpha) = H d(eps_p)). The steel laws
// of the library collapse to it for H_iso = 0, no Chaboche terms and no damage.
#pragma once

#include <cmath>
#include <vector>

namespace brb::testing {

struct KinematicBar {
  double youngs_modulus = 0.0; ///< MPa
  double yield_stress = 0.0;   ///< MPa
  double hardening = 0.0;      ///< H_kin (MPa)
  double length = 0.0;         ///< mm
  double area = 0.0;           ///< mm^2

  /// Force (N) at each deformation (mm) of a history that starts from the virgin state.
  std::vector<double> forces(const std::vector<double>& deformations) const {
    std::vector<double> result;
    double plastic_strain = 0.0;
    double back_stress = 0.0;
    for (const double deformation : deformations) {
      const double strain = deformation / length;
      double stress = youngs_modulus * (strain - plastic_strain);
      const double overstress = std::abs(stress - back_stress) - yield_stress;
      if (overstress > 0.0) {
        const double direction = stress > back_stress ? 1.0 : -1.0;
        const double plastic_increment = overstress / (youngs_modulus + hardening);
        plastic_strain += direction * plastic_increment;
        back_stress += direction * hardening * plastic_increment;
        stress = youngs_modulus * (strain - plastic_strain);
      }
      result.push_back(stress * area);
    }
    return result;
  }
};

} // namespace brb::testing
