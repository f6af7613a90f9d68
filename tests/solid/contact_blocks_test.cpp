// Node-to-surface contact between two elastic blocks of one SolidModel, driven by a small
// explicit loop of this test (central differences, lumped mass, mass-proportional damping to
// settle each state): SolidExplicit does not take interactions yet. Stable step from the
// elements' bound plus the contact's frequency_bound_squared (solid_interaction.hpp).
// References: equilibrium (the contact forces equal the supports' reactions), the series
// stiffness of two bars and a penalty layer, and Coulomb (a sliding block carries kappa N).
#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/solid/node_to_surface_contact.hpp"
#include "brb/solid/solid_explicit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace brb::solid {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kDensity = 7.85e-9; // MPa, -, tonne/mm^3
constexpr double kSide = 10.0;                                 // mm, each block a cube

using ElasticModel = SolidModel<material::IsotropicElastic3D>;

/// Two 10 mm cubes of 2 x 2 x 2 elements, the upper one on top of the lower (z in [0, 10]
/// and [10, 20]), with their own nodes on the common plane. Slave: the upper block's bottom
/// face (outward -z); master: the lower block's top face (outward +z).
struct TwoBlocks {
  StructuredPrismMesh prism{Eigen::Vector3d(kSide, kSide, kSide), {2, 2, 2}};
  int offset = prism.mesh().node_count(); // first node of the upper block
  HexMesh mesh;
  std::vector<QuadFace> slave, master;

  TwoBlocks() {
    const HexMesh& block = prism.mesh();
    mesh.nodes.resize(3, 2 * offset);
    mesh.nodes.leftCols(offset) = block.nodes;
    mesh.nodes.rightCols(offset) = block.nodes.colwise() + Eigen::Vector3d(0, 0, kSide);
    mesh.elements = block.elements;
    for (HexConnectivity element : block.elements) {
      for (int& n : element)
        n += offset;
      mesh.elements.push_back(element);
    }
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        master.push_back({prism.node_index(i, j, 2), prism.node_index(i + 1, j, 2),
                          prism.node_index(i + 1, j + 1, 2), prism.node_index(i, j + 1, 2)});
        slave.push_back({offset + prism.node_index(i, j, 0), offset + prism.node_index(i, j + 1, 0),
                         offset + prism.node_index(i + 1, j + 1, 0),
                         offset + prism.node_index(i + 1, j, 0)});
      }
  }
  std::vector<int> lower(PrismFace face) const { return prism.face_nodes(face); }
  std::vector<int> upper(PrismFace face) const {
    std::vector<int> nodes = prism.face_nodes(face);
    for (int& n : nodes)
      n += offset;
    return nodes;
  }
};

/// Central differences (velocity Verlet) of model + contact with prescribed DOFs
/// u_d = value_d x history_d(t) and damping force c M v (dynamic relaxation).
class ExplicitLoop {
public:
  ExplicitLoop(ElasticModel& model, NodeToSurfaceContact& contact, double damping)
      : model_(model), contact_(contact), damping_(damping), mass_(model.lumped_mass()),
        u_(Eigen::VectorXd::Zero(model.dof_count())), v_(u_), a_(u_), force_(u_),
        prescribed_(static_cast<std::size_t>(model.dof_count()), false) {
    const double element_frequency = 2.0 / model.stable_time_step(1.0);
    const double w2 =
        element_frequency * element_frequency + contact.frequency_bound_squared(mass_);
    dt_ = 0.9 * 2.0 / std::sqrt(w2);
  }

  void prescribe(int node, int direction, double value, std::function<double(double)> history) {
    const int dof = 3 * node + direction;
    prescribed_[static_cast<std::size_t>(dof)] = true;
    prescriptions_.push_back({dof, value, std::move(history)});
  }

  /// Steps to `time`; false with the reason when the model or the contact refuses a state.
  bool run_to(double time, std::string& failure) {
    while (time_ < time - 1e-15) {
      time_ += dt_;
      for (Eigen::Index d = 0; d < u_.size(); ++d)
        if (!prescribed_[static_cast<std::size_t>(d)]) {
          v_[d] += 0.5 * dt_ * a_[d];
          u_[d] += dt_ * v_[d];
          damping_work_ += damping_ * mass_[d] * v_[d] * v_[d] * dt_;
        }
      const Eigen::VectorXd previous_u = u_, previous_force = force_;
      for (const Prescription& p : prescriptions_)
        u_[p.dof] = p.value * p.history(time_);
      force_.setZero();
      if (!model_.evaluate(u_, force_, nullptr, failure))
        return false;
      if (!contact_.add_force(u_, force_, failure))
        return false;
      model_.commit();
      contact_.commit();
      for (const Prescription& p : prescriptions_) // trapezoidal work of the reactions
        external_work_ +=
            0.5 * (previous_force[p.dof] + force_[p.dof]) * (u_[p.dof] - previous_u[p.dof]);
      for (Eigen::Index d = 0; d < u_.size(); ++d)
        if (!prescribed_[static_cast<std::size_t>(d)]) {
          a_[d] = -force_[d] / mass_[d] - damping_ * v_[d];
          v_[d] += 0.5 * dt_ * a_[d];
        }
      ++steps_;
    }
    return true;
  }

  double time_step() const { return dt_; }
  long steps() const { return steps_; }
  /// Internal + contact force of the committed state: the reactions on the prescribed DOFs.
  const Eigen::VectorXd& force() const { return force_; }
  const Eigen::VectorXd& displacement() const { return u_; }
  double kinetic_energy() const { return 0.5 * v_.dot(mass_.cwiseProduct(v_)); }
  double external_work() const { return external_work_; }
  double damping_work() const { return damping_work_; }

private:
  struct Prescription {
    int dof;
    double value;
    std::function<double(double)> history;
  };
  ElasticModel& model_;
  NodeToSurfaceContact& contact_;
  double damping_;
  Eigen::VectorXd mass_, u_, v_, a_, force_;
  std::vector<bool> prescribed_;
  std::vector<Prescription> prescriptions_;
  double time_ = 0.0, dt_ = 0.0;
  double external_work_ = 0.0, damping_work_ = 0.0;
  long steps_ = 0;
};

double sum_over(const Eigen::VectorXd& force, const std::vector<int>& nodes, int direction) {
  double sum = 0.0;
  for (int n : nodes)
    sum += force[3 * n + direction];
  return sum;
}

/// First axial period of the two blocks between the plates (a 20 mm bar fixed at both ends):
/// T = 2 L / c.
double axial_period() {
  return 2.0 * 2.0 * kSide / std::sqrt(kE / kDensity);
}

TEST(ContactBlocks, ABlockPressedOnAnotherTransmitsTheForce) {
  // The upper block's top is pushed down by delta on rollers, the lower block's bottom rests
  // on rollers: uniaxial stress, so the two blocks and the penalty layer act in series,
  //   F = delta / (2 L / (E A) + 1 / (penalty A))   (A = 100 mm^2, L = 10 mm; the
  // tributary-area springs under a uniform pressure are a uniform layer of stiffness penalty
  // per unit area). Green-Lagrange strain 1e-4 changes F by ~1.5e-4. Checked after a ramp of
  // 20 periods and damped settling: the contact's normal forces sum to the top reaction and
  // to the bottom reaction (equilibrium, 1e-4) and F is the series value (1e-3).
  TwoBlocks blocks;
  ElasticModel model(
      blocks.mesh, [](double) { return material::IsotropicElastic3D(kE, kNu); }, kDensity);
  NodeToSurfaceContactSettings settings;
  settings.normal_penalty = 10.0 * kE / kSide; // ten times the block's own stiffness
  settings.search_distance = 0.5;
  NodeToSurfaceContact contact(blocks.mesh.nodes, blocks.slave, blocks.master, settings);

  const double period = axial_period();
  ExplicitLoop loop(model, contact, 2.0 * std::numbers::pi / period);
  const double delta = 2e-3, ramp = 20.0 * period;
  const auto history = [ramp](double t) { return smooth_ramp(t, ramp); };
  const auto held = [](double) { return 0.0; };
  for (int n : blocks.lower(PrismFace::z_min))
    loop.prescribe(n, 2, 0.0, held);
  for (int n : blocks.upper(PrismFace::z_max))
    loop.prescribe(n, 2, -delta, history);
  // rollers: stop the rigid motions in x, y of each block at two corners
  for (int n :
       {blocks.prism.node_index(0, 0, 0), blocks.offset + blocks.prism.node_index(0, 0, 2)}) {
    loop.prescribe(n, 0, 0.0, held);
    loop.prescribe(n, 1, 0.0, held);
  }
  for (int n : {blocks.prism.node_index(2, 0, 0), blocks.offset + blocks.prism.node_index(2, 0, 2)})
    loop.prescribe(n, 1, 0.0, held);

  std::string failure;
  ASSERT_TRUE(loop.run_to(ramp + 10.0 * period, failure)) << failure;

  double contact_force = 0.0;
  for (const NodeContactState& state : contact.states(0))
    contact_force += state.normal_force;
  EXPECT_EQ(contact.statistics().nodes_in_contact, 9);
  const double top = -sum_over(loop.force(), blocks.upper(PrismFace::z_max), 2);
  const double bottom = sum_over(loop.force(), blocks.lower(PrismFace::z_min), 2);
  const double area = kSide * kSide;
  const double series =
      delta / (2.0 * kSide / (kE * area) + 1.0 / (settings.normal_penalty * area));
  EXPECT_NEAR(contact_force / top, 1.0, 1e-4);
  EXPECT_NEAR(contact_force / bottom, 1.0, 1e-4);
  EXPECT_NEAR(contact_force / series, 1.0, 1e-3);
  // energy balance: the reactions' work is stored in the blocks and the contact springs (or
  // damped out); the contact adds no energy of its own (1 %, as SolidExplicit's balance)
  const SolidEnergy& blocks_energy = model.energy();
  const double stored = blocks_energy.internal + blocks_energy.hourglass + contact.stored_energy() +
                        contact.dissipated_energy() + loop.kinetic_energy();
  const double balance =
      std::abs(loop.external_work() - loop.damping_work() - stored) / loop.external_work();
  EXPECT_LT(balance, 0.01);
  // the penalty layer under the uniform pressure F / A stores 1/2 F^2 / (penalty A)
  EXPECT_NEAR(contact.stored_energy() /
                  (0.5 * contact_force * contact_force / (settings.normal_penalty * area)),
              1.0, 1e-3);
  RecordProperty("contact_over_series", std::to_string(contact_force / series));
  RecordProperty("energy_balance_error", std::to_string(balance * 1e6) + "e-6");
  RecordProperty("steps", std::to_string(loop.steps()));
}

TEST(ContactBlocks, ABlockSlidOnAnotherUnderANormalLoadCarriesKappaN) {
  // The lower block is clamped at its bottom; the upper block's top face is pressed down by
  // delta (held), then moved 0.05 mm along x, far beyond the stick limit (kappa N / k_T per
  // node ~ 2e-5 mm). Coulomb (BRB_SOURCE_FACTS section 4): every interface node slides and
  // carries kappa N, so the friction force is kappa times the normal force, and the top's
  // horizontal reaction equals it (the upper block's equilibrium; 1e-3 after settling).
  TwoBlocks blocks;
  ElasticModel model(
      blocks.mesh, [](double) { return material::IsotropicElastic3D(kE, kNu); }, kDensity);
  NodeToSurfaceContactSettings settings;
  settings.normal_penalty = 10.0 * kE / kSide;
  settings.friction_coefficient = 0.1;
  settings.search_distance = 0.5;
  NodeToSurfaceContact contact(blocks.mesh.nodes, blocks.slave, blocks.master, settings);

  const double period = axial_period();
  ExplicitLoop loop(model, contact, 2.0 * std::numbers::pi / period);
  const double delta = 2e-3, slide = 0.05, ramp = 20.0 * period;
  const auto held = [](double) { return 0.0; };
  const auto press = [ramp](double t) { return smooth_ramp(t, ramp); };
  const auto push = [ramp](double t) { return smooth_ramp(t - 1.5 * ramp, ramp); };
  for (int n : blocks.lower(PrismFace::z_min))
    for (int direction = 0; direction < 3; ++direction)
      loop.prescribe(n, direction, 0.0, held);
  for (int n : blocks.upper(PrismFace::z_max)) {
    loop.prescribe(n, 0, slide, push);
    loop.prescribe(n, 1, 0.0, held);
    loop.prescribe(n, 2, -delta, press);
  }

  std::string failure;
  ASSERT_TRUE(loop.run_to(1.5 * ramp, failure)) << failure;
  EXPECT_EQ(contact.statistics().nodes_in_contact, 9);
  const double dissipated_before_slide = contact.dissipated_energy();
  ASSERT_TRUE(loop.run_to(2.5 * ramp + 10.0 * period, failure)) << failure;

  double normal = 0.0, friction_x = 0.0;
  for (const NodeContactState& state : contact.states(0)) {
    // every node stays at the Coulomb limit after the slide (T along +x: the spring's force,
    // the slave is pulled back along -x)
    EXPECT_NEAR(state.tangential_force.x() / (0.1 * state.normal_force), 1.0, 1e-3);
    friction_x += state.tangential_force.x();
    normal += state.normal_force;
  }
  // the plate pushes the block along +x: its reaction, the internal force of the top nodes
  const double top_x = sum_over(loop.force(), blocks.upper(PrismFace::z_max), 0);
  const double top_z = -sum_over(loop.force(), blocks.upper(PrismFace::z_max), 2);
  EXPECT_NEAR(friction_x / (0.1 * normal), 1.0, 1e-3);
  EXPECT_NEAR(top_x / friction_x, 1.0, 1e-3);
  EXPECT_NEAR(top_z / normal, 1.0, 1e-3);
  // Friction work: kappa N times the interface's slip, which is the plate's travel less the
  // lateral deflection of the two blocks under the friction force T, each a cantilever
  // clamped at its far end (Timoshenko: L^3 / (3 E I) + 1.2 L / (G A), I = side^4 / 12);
  // beam theory is approximate for a cube: 2 %.
  const double work = contact.dissipated_energy() - dissipated_before_slide;
  const double inertia = std::pow(kSide, 4) / 12.0, shear_modulus = kE / (2.0 * (1.0 + kNu));
  const double flexibility = 2.0 * (std::pow(kSide, 3) / (3.0 * kE * inertia) +
                                    1.2 * kSide / (shear_modulus * kSide * kSide));
  const double interface_slip = slide - flexibility * friction_x;
  EXPECT_NEAR(work / (0.1 * normal * interface_slip), 1.0, 0.02);
  // energy balance with friction: the plate's work is stored, dissipated by friction or damped
  const SolidEnergy& blocks_energy = model.energy();
  const double accounted = blocks_energy.internal + blocks_energy.hourglass +
                           contact.stored_energy() + contact.dissipated_energy() +
                           loop.kinetic_energy() + loop.damping_work();
  const double balance = std::abs(loop.external_work() - accounted) / loop.external_work();
  EXPECT_LT(balance, 0.01);
  RecordProperty("energy_balance_error", std::to_string(balance * 1e6) + "e-6");
  RecordProperty("friction_over_kappa_n", std::to_string(friction_x / (0.1 * normal)));
  RecordProperty("dissipated_over_kappa_n_slip",
                 std::to_string(work / (0.1 * normal * interface_slip)));
  RecordProperty("steps", std::to_string(loop.steps()));
}

} // namespace
} // namespace brb::solid
