#include "brb/element/brace_truss.hpp"

#include "brb/element/corot_truss.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::element {

void BraceTrussParameters::validate() const {
  if (!(core_area > 0.0) || !std::isfinite(core_area))
    throw ParameterError("core_area", "the core's area must be > 0 mm^2");
  if (!(yielding_length > 0.0) || !std::isfinite(yielding_length))
    throw ParameterError("yielding_length", "the yielding length must be > 0 mm");
  if (!(end_flexibility >= 0.0) || !std::isfinite(end_flexibility))
    throw ParameterError("end_flexibility", "the end zones' flexibility must be >= 0 mm/N");
  steel.validate();
}

BraceTruss::BraceTruss(std::array<int, 2> nodes, const Vector3& position_i,
                       const Vector3& position_j, const BraceTrussParameters& parameters,
                       bool elastic_fast_path)
    : nodes_(nodes), initial_length_((position_j - position_i).norm()), parameters_(parameters),
      // one material point over the yielding zone: its characteristic length is L_y
      law_((parameters.validate(), parameters.steel), parameters.yielding_length),
      committed_(law_.initial_state()), trial_(committed_) {
  if (!(parameters.yielding_length <= initial_length_ * (1.0 + 1e-12)))
    throw ParameterError("yielding_length", "the yielding length must not exceed the brace's "
                                            "length (the outer nodes' distance)");
  law_.set_elastic_fast_path(elastic_fast_path);
}

double BraceTruss::elastic_stiffness() const {
  return 1.0 /
         (parameters_.yielding_length / (parameters_.steel.youngs_modulus * parameters_.core_area) +
          parameters_.end_flexibility);
}

bool BraceTruss::evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                          Eigen::MatrixXd& tangent, std::string& failure) {
  const Vector3 chord = configuration[1].position - configuration[0].position;
  const double length = chord.norm();
  if (!(length > 0.0)) {
    failure = "brace truss of zero length";
    return false;
  }
  const Vector3 direction = chord / length;
  deformation_ = length - initial_length_;
  const double area = parameters_.core_area;
  const double yielding_length = parameters_.yielding_length;
  const double flexibility = parameters_.end_flexibility;

  // Scalar Newton on the series split g(eps) = eps L_y + f_e A sigma(eps) - Delta = 0, from
  // the committed strain. g' = L_y + f_e A E_t > 0 while the core does not soften faster
  // than the end zones can unload (a snap-back otherwise: reported as a failure).
  double strain = committed_strain_;
  material::SteelUniaxial::Response response = law_.evaluate(committed_, strain);
  double slope = 0.0;
  const double tolerance = 1e-12 * initial_length_;
  bool converged = false;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double residual =
        strain * yielding_length + flexibility * area * response.stress - deformation_;
    slope = yielding_length + flexibility * area * response.tangent;
    if (std::abs(residual) <= tolerance) {
      converged = true;
      break;
    }
    if (!(slope > 0.0)) {
      failure = "brace truss: the core softens faster than the end zones unload (snap-back)";
      return false;
    }
    strain -= residual / slope;
    response = law_.evaluate(committed_, strain);
  }
  if (!converged || !std::isfinite(response.stress)) {
    failure = "brace truss: the series split of the deformation did not converge";
    return false;
  }
  strain_ = strain;
  trial_ = response.state;
  axial_force_ = area * response.stress;
  // dN/dDelta = A E_t d eps/dDelta = A E_t / g'
  const double axial_stiffness = area * response.tangent / slope;

  chord_force_and_tangent(direction, length, axial_force_, axial_stiffness, force, tangent);
  return true;
}

void BraceTruss::commit() {
  committed_work_ = core_stress_work();
  committed_ = trial_;
  committed_strain_ = strain_;
  committed_force_ = axial_force_;
}

void BraceTruss::revert_to_committed() {
  trial_ = committed_;
  strain_ = committed_strain_;
  axial_force_ = committed_force_;
}

double BraceTruss::core_stress_work() const {
  return committed_work_ + 0.5 * (committed_force_ + axial_force_) * (strain_ - committed_strain_) *
                               parameters_.yielding_length;
}

ElementEnergy BraceTruss::energy() const {
  const double volume = parameters_.core_area * parameters_.yielding_length;
  // core: free energy of the law; end zones: N^2 f_e / 2 (elastic)
  const double core_stored = volume * law_.free_energy(trial_, strain_);
  ElementEnergy energy{core_stored +
                           0.5 * axial_force_ * axial_force_ * parameters_.end_flexibility,
                       volume * material::SteelUniaxial::dissipated_energy(trial_)};
  energy.integration_misfit = core_stress_work() - core_stored - energy.dissipated;
  return energy;
}

} // namespace brb::element
