#include "brb/element/elastic_beam_column.hpp"

#include "brb/element/rotation.hpp"
#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::element {
namespace {

void require_positive(double value, const char* field, const char* meaning) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw ParameterError(field, std::string(meaning) + " must be > 0 and finite");
}

/// Rotation vectors of the nodal triads, with J^-1 (d theta = J^-1 dw).
struct NodalRotation {
  Vector3 vector;
  Matrix3 jacobian_inverse;
};

NodalRotation nodal_rotation(const Matrix3& triad) {
  const Vector3 theta = vector_from_rotation(triad);
  return {theta, inverse_left_jacobian(theta)};
}

} // namespace

void ElasticBeamProperties::validate() const {
  require_positive(youngs_modulus, "E", "Young's modulus E (MPa)");
  require_positive(shear_modulus, "G", "shear modulus G (MPa)");
  require_positive(area, "A", "area A (mm^2)");
  require_positive(inertia_y, "Iy", "second moment of area Iy (mm^4)");
  require_positive(inertia_z, "Iz", "second moment of area Iz (mm^4)");
  require_positive(torsion_constant, "J", "torsion constant J (mm^4)");
}

ElasticBeamColumn::ElasticBeamColumn(std::array<int, 2> nodes, const Vector3& position_i,
                                     const Vector3& position_j,
                                     const ElasticBeamProperties& properties,
                                     const Vector3& orientation, BeamGeometry geometry)
    : nodes_(nodes), reference_position_{position_i, position_j},
      properties_((properties.validate(), properties)), geometry_(geometry),
      frame_(position_i, position_j, orientation) {
  // L = blockdiag(T^T, T^T, T^T, T^T) maps global to local components.
  Matrix12 transformation = Matrix12::Zero();
  for (int block = 0; block < 4; ++block)
    transformation.block<3, 3>(3 * block, 3 * block) = local_axes().transpose();
  global_stiffness_ = transformation.transpose() * local_stiffness() * transformation;

  // co-rotational local beam on d_l = [u_bar, theta_i (3), theta_j (3)]
  const double length = frame_.initial_length();
  const double torsion = properties_.shear_modulus * properties_.torsion_constant / length;
  const double bending_y = properties_.youngs_modulus * properties_.inertia_y / length;
  const double bending_z = properties_.youngs_modulus * properties_.inertia_z / length;
  LocalMatrix& k = corotational_local_;
  k.setZero();
  k(0, 0) = properties_.youngs_modulus * properties_.area / length;
  k(1, 1) = k(4, 4) = torsion;
  k(1, 4) = k(4, 1) = -torsion;
  k(2, 2) = k(5, 5) = 4.0 * bending_y;
  k(2, 5) = k(5, 2) = 2.0 * bending_y;
  k(3, 3) = k(6, 6) = 4.0 * bending_z;
  k(3, 6) = k(6, 3) = 2.0 * bending_z;
}

Matrix12 ElasticBeamColumn::local_stiffness() const {
  // DOF order [u_i (0-2), theta_i (3-5), u_j (6-8), theta_j (9-11)] in local axes.
  const double length = frame_.initial_length();
  const double axial = properties_.youngs_modulus * properties_.area / length;
  const double torsion = properties_.shear_modulus * properties_.torsion_constant / length;
  Matrix12 k = Matrix12::Zero();
  k(0, 0) = k(6, 6) = axial;
  k(0, 6) = -axial;
  k(3, 3) = k(9, 9) = torsion;
  k(3, 9) = -torsion;
  // Bending in the x-y plane: deflection v (1, 7), rotation theta_z (5, 11), v' = theta_z.
  const double c = properties_.youngs_modulus * properties_.inertia_z / (length * length * length);
  k(1, 1) = k(7, 7) = 12.0 * c;
  k(1, 7) = -12.0 * c;
  k(1, 5) = k(1, 11) = 6.0 * length * c;
  k(5, 7) = k(7, 11) = -6.0 * length * c;
  k(5, 5) = k(11, 11) = 4.0 * length * length * c;
  k(5, 11) = 2.0 * length * length * c;
  // Bending in the x-z plane: deflection w (2, 8), rotation theta_y (4, 10), w' = -theta_y.
  const double b = properties_.youngs_modulus * properties_.inertia_y / (length * length * length);
  k(2, 2) = k(8, 8) = 12.0 * b;
  k(2, 8) = -12.0 * b;
  k(2, 4) = k(2, 10) = -6.0 * length * b;
  k(4, 8) = k(8, 10) = 6.0 * length * b;
  k(4, 4) = k(10, 10) = 4.0 * length * length * b;
  k(4, 10) = 2.0 * length * length * b;
  return k.selfadjointView<Eigen::Upper>();
}

bool ElasticBeamColumn::evaluate(std::span<const NodeConfiguration> configuration,
                                 Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                                 std::string& failure) {
  if (geometry_ == BeamGeometry::corotational)
    return evaluate_corotational(configuration, force, tangent, failure);
  evaluate_small_displacement(configuration, force, tangent);
  return true;
}

void ElasticBeamColumn::evaluate_small_displacement(
    std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
    Eigen::MatrixXd& tangent) {
  const NodalRotation rotation_i = nodal_rotation(configuration[0].rotation);
  const NodalRotation rotation_j = nodal_rotation(configuration[1].rotation);
  Vector12 displacement;
  displacement << configuration[0].position - reference_position_[0], rotation_i.vector,
      configuration[1].position - reference_position_[1], rotation_j.vector;
  const Vector12 generalised_force = global_stiffness_ * displacement; // q = K d = dV/dd
  stored_energy_ = 0.5 * displacement.dot(generalised_force);

  // Spins: d d = D dw with D = blockdiag(I, J_i^-1, I, J_j^-1); f = D^T q and
  // K_t = D^T K D + blockdiag(0, H_i J_i^-1, 0, H_j J_j^-1), H = d(J^-T q_theta)/d theta.
  Matrix12 spin_map = Matrix12::Identity();
  spin_map.block<3, 3>(3, 3) = rotation_i.jacobian_inverse;
  spin_map.block<3, 3>(9, 9) = rotation_j.jacobian_inverse;
  Vector12 nodal_force = spin_map.transpose() * generalised_force;
  Matrix12 nodal_tangent = spin_map.transpose() * global_stiffness_ * spin_map;
  nodal_tangent.block<3, 3>(3, 3) += inverse_left_jacobian_transpose_derivative(
                                         rotation_i.vector, generalised_force.segment<3>(3)) *
                                     rotation_i.jacobian_inverse;
  nodal_tangent.block<3, 3>(9, 9) += inverse_left_jacobian_transpose_derivative(
                                         rotation_j.vector, generalised_force.segment<3>(9)) *
                                     rotation_j.jacobian_inverse;

  const Vector3 axis = local_axes().col(0);
  const Vector3 relative = displacement.segment<3>(6) - displacement.segment<3>(0);
  const double axial_stiffness = properties_.youngs_modulus * properties_.area / length();
  axial_force_ = axial_stiffness * axis.dot(relative);

  if (geometry_ == BeamGeometry::pdelta) {
    // P-Delta of the chord: f_j += N a / L, f_i -= N a / L, a = (I - x x^T)(u_j - u_i).
    const Matrix3 transverse = Matrix3::Identity() - axis * axis.transpose();
    const Vector3 offset = transverse * relative;
    const double inverse_length = 1.0 / length();
    nodal_force.segment<3>(0) -= axial_force_ * inverse_length * offset;
    nodal_force.segment<3>(6) += axial_force_ * inverse_length * offset;
    // d(N a / L)/d u_j = N / L (I - x x^T) + a (E A / L^2) x^T (and minus for u_i)
    const Matrix3 block = axial_force_ * inverse_length * transverse +
                          axial_stiffness * inverse_length * offset * axis.transpose();
    nodal_tangent.block<3, 3>(0, 0) += block;
    nodal_tangent.block<3, 3>(0, 6) -= block;
    nodal_tangent.block<3, 3>(6, 0) -= block;
    nodal_tangent.block<3, 3>(6, 6) += block;
    stored_energy_ += 0.5 * axial_force_ * inverse_length * offset.squaredNorm();
  }
  force = nodal_force;
  tangent = nodal_tangent;
}

bool ElasticBeamColumn::evaluate_corotational(std::span<const NodeConfiguration> configuration,
                                              Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                                              std::string& failure) {
  if (!frame_.update(configuration[0], configuration[1])) {
    failure = "elastic beam-column (corotational) degenerated: zero length or its y director "
              "along the chord";
    return false;
  }
  const LocalVector& deformation = frame_.local_deformation();
  const LocalVector local_force = corotational_local_ * deformation;
  axial_force_ = local_force[0];
  stored_energy_ = 0.5 * deformation.dot(local_force);
  GlobalVector global_force;
  GlobalMatrix global_tangent;
  frame_.global_response(local_force, corotational_local_, global_force, global_tangent);
  force = global_force;
  tangent = global_tangent;
  return true;
}

} // namespace brb::element
