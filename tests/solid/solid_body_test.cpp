// SolidBody: parts of different laws sharing nodes, interactions in the stable step and in the
// energy balance, and the explicit solver on a body.
#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/solid/solid_body.hpp"
#include "brb/solid/solid_explicit.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::solid {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kDensity = 7.85e-9; // MPa, -, tonne/mm^3
constexpr double kLength = 200.0, kSide = 20.0;

using Elastic = material::IsotropicElastic3D;
using Steel = material::SteelDamagePlasticity3D;

material::SteelParameters steel_parameters() {
  material::SteelParameters steel;
  steel.youngs_modulus = kE;
  steel.poissons_ratio = kNu;
  steel.yield_stress = 355.0;
  steel.kinematic_hardening = 21000.0;
  return steel;
}

/// The nodes of the elements i0 <= i < i1 of a structured prism, as a sub-mesh: its nodes are
/// the prism's nodes with i0 <= i <= i1, numbered in the prism's order; global_nodes maps them
/// back to the prism's indices.
struct SubMesh {
  HexMesh mesh;
  std::vector<int> global_nodes;
};
SubMesh slice(const StructuredPrismMesh& prism, int i0, int i1) {
  const PrismDivisions d = prism.divisions();
  SubMesh sub;
  std::vector<int> local(prism.mesh().node_count(), -1);
  for (int k = 0; k <= d.nz; ++k)
    for (int j = 0; j <= d.ny; ++j)
      for (int i = i0; i <= i1; ++i) {
        local[prism.node_index(i, j, k)] = static_cast<int>(sub.global_nodes.size());
        sub.global_nodes.push_back(prism.node_index(i, j, k));
      }
  sub.mesh.nodes.resize(3, static_cast<Eigen::Index>(sub.global_nodes.size()));
  for (std::size_t n = 0; n < sub.global_nodes.size(); ++n)
    sub.mesh.nodes.col(static_cast<Eigen::Index>(n)) = prism.mesh().nodes.col(sub.global_nodes[n]);
  for (int k = 0; k < d.nz; ++k)
    for (int j = 0; j < d.ny; ++j)
      for (int i = i0; i < i1; ++i) {
        HexConnectivity element = prism.mesh().elements[prism.element_index(i, j, k)];
        for (int& node : element)
          node = local[node];
        sub.mesh.elements.push_back(element);
      }
  return sub;
}

/// Roller supports at x = 0 (ux on the face, two nodes against rigid motions) and the tip face
/// pulled to `tip` along x.
PrescribedDisplacements bar_supports(const StructuredPrismMesh& prism, double tip) {
  PrescribedDisplacements supports;
  for (int n : prism.face_nodes(PrismFace::x_min))
    supports.add(n, 0, 0.0);
  supports.add(prism.node_index(0, 0, 0), 1, 0.0);
  supports.add(prism.node_index(0, 0, 0), 2, 0.0);
  supports.add(prism.node_index(0, prism.divisions().ny, 0), 2, 0.0);
  for (int n : prism.face_nodes(PrismFace::x_max))
    supports.add(n, 0, tip);
  return supports;
}

double tip_force(const StructuredPrismMesh& prism, const Eigen::VectorXd& force) {
  double sum = 0.0;
  for (int n : prism.face_nodes(PrismFace::x_max))
    sum += force[3 * n];
  return sum;
}

TEST(SolidBody, TwoPartBarHasTheSeriesStiffness) {
  // Steel (E = 210 GPa) over x < L/2 and an elastic part (E2 = 70 GPa) over x > L/2, sharing
  // the nodes of the plane x = L/2. nu2 = nu E2 / E keeps the lateral strains of the two parts
  // equal, so the stress stays uniaxial and the bar is two springs in series (theory):
  // F / delta = A / (L1 / E + L2 / E2). Loaded quasi-statically (1 - cos ramp over 20 axial
  // periods, then held 5 periods) to 2e-4 strain (elastic steel).
  const double e2 = 70000.0, nu2 = kNu * e2 / kE;
  const StructuredPrismMesh prism(Eigen::Vector3d(kLength, kSide, kSide), {20, 2, 2});
  SolidBody body(prism.mesh().nodes);
  SubMesh left = slice(prism, 0, 10), right = slice(prism, 10, 20);
  const material::SteelParameters steel = steel_parameters();
  body.add_part("steel",
                SolidModel<Steel>(
                    left.mesh, [&](double lc) { return Steel(steel, lc); }, kDensity),
                left.global_nodes);
  body.add_part("elastic",
                SolidModel<Elastic>(
                    right.mesh, [&](double) { return Elastic(e2, nu2); }, kDensity),
                right.global_nodes);
  EXPECT_EQ(body.element_count(), 80);

  const double delta = 2e-4 * kLength;
  SolidLoading loading;
  loading.prescribed = bar_supports(prism, delta);
  const double period = 4.0 * kLength / std::sqrt(e2 / kDensity);
  const double ramp = 20.0 * period;
  loading.history = [ramp](double t) { return smooth_ramp(t, ramp); };
  SolidExplicit<SolidBody> solver(body, loading);
  std::string failure;
  ASSERT_TRUE(solver.run_to(ramp + 5.0 * period, failure)) << failure;
  const double series = kSide * kSide / (0.5 * kLength / kE + 0.5 * kLength / e2);
  const double force = tip_force(prism, solver.internal_force());
  EXPECT_NEAR(force / (series * delta), 1.0, 0.01);
  EXPECT_LT(solver.energy().relative_error(), 0.01);
  RecordProperty("force_over_series", std::to_string(force / (series * delta)));
}

TEST(SolidBody, PartSplitMeshGivesTheUnsplitHistory) {
  // A steel bar pulled past yield, once as one SolidModel and once as a body of three parts
  // (elements i < 7, 7 <= i < 13, i >= 13) sharing the nodes of two planes: the same elements,
  // the same masses (a shared node gets both parts' shares), the same step; the histories
  // must agree to round-off (only the order of the nodal sums at the shared planes differs).
  const StructuredPrismMesh prism(Eigen::Vector3d(kLength, kSide, kSide), {20, 2, 2});
  const material::SteelParameters steel = steel_parameters();
  const auto law = [&](double lc) { return Steel(steel, lc); };
  SolidModel<Steel> whole(prism.mesh(), law, kDensity);
  SolidBody body(prism.mesh().nodes);
  for (const auto& [i0, i1] : {std::pair{0, 7}, std::pair{7, 13}, std::pair{13, 20}}) {
    SubMesh sub = slice(prism, i0, i1);
    body.add_part("steel " + std::to_string(i0), SolidModel<Steel>(sub.mesh, law, kDensity),
                  sub.global_nodes);
  }
  EXPECT_TRUE(body.lumped_mass().isApprox(whole.lumped_mass(), 1e-14));
  EXPECT_DOUBLE_EQ(body.stable_time_step(0.9), whole.stable_time_step(0.9));

  SolidLoading loading;
  loading.prescribed = bar_supports(prism, 5e-3 * kLength);
  const double duration = 4.0 * 4.0 * kLength / std::sqrt(kE / kDensity);
  loading.history = [duration](double t) { return smooth_ramp(t, duration); };
  SolidExplicit<Steel> one(whole, loading);
  SolidExplicit<SolidBody> split(body, loading);
  ASSERT_EQ(one.time_step(), split.time_step());
  std::string failure;
  double worst = 0.0, scale = 0.0;
  for (int k = 1; k <= 20; ++k) {
    ASSERT_TRUE(one.run_to(duration * k / 20, failure)) << failure;
    ASSERT_TRUE(split.run_to(duration * k / 20, failure)) << failure;
    worst = std::max(worst, (one.displacement() - split.displacement()).cwiseAbs().maxCoeff());
    scale = std::max(scale, one.displacement().cwiseAbs().maxCoeff());
  }
  EXPECT_GT(whole.states()[0].equivalent_plastic_strain, 1e-3); // it did yield
  EXPECT_LT(worst, 1e-10 * scale);
  EXPECT_NEAR(split.energy().internal / one.energy().internal, 1.0, 1e-10);
  RecordProperty("max_history_difference_mm", std::to_string(worst));
}

/// A test interaction: an elastic-perfectly-plastic axial spring (stiffness k, slip force
/// f_s) between two nodes along x: f = k (u_a - u_b - s) with |f| <= f_s by a return map on the
/// slip s. Stored energy f^2 / (2 k); dissipated energy sum f |ds| (exact for the return map:
/// the force is f_s during the slip increment).
class SlipSpring final : public SolidInteraction {
public:
  SlipSpring(int a, int b, double stiffness, double slip_force)
      : a_(a), b_(b), k_(stiffness), slip_force_(slip_force) {}
  bool add_force(const Eigen::VectorXd& u, Eigen::VectorXd& force, std::string&) override {
    const double stretch = u[3 * a_] - u[3 * b_];
    double f = k_ * (stretch - slip_);
    trial_slip_ = slip_;
    if (std::abs(f) > slip_force_) {
      const double sign = f > 0.0 ? 1.0 : -1.0;
      trial_slip_ = stretch - sign * slip_force_ / k_;
      f = sign * slip_force_;
    }
    trial_force_ = f;
    force[3 * a_] += f;
    force[3 * b_] -= f;
    return true;
  }
  void commit() override {
    dissipated_ += std::abs(trial_force_ * (trial_slip_ - slip_));
    slip_ = trial_slip_;
    force_ = trial_force_;
  }
  double stored_energy() const override { return force_ * force_ / (2.0 * k_); }
  double dissipated_energy() const override { return dissipated_; }
  double frequency_bound_squared(const Eigen::VectorXd& mass) const override {
    return k_ * (1.0 / mass[3 * a_] + 1.0 / mass[3 * b_]);
  }

private:
  int a_, b_;
  double k_, slip_force_;
  double slip_ = 0.0, trial_slip_ = 0.0, force_ = 0.0, trial_force_ = 0.0, dissipated_ = 0.0;
};

TEST(SolidBody, InteractionEntersTheStableStepAndTheEnergyBalance) {
  // An elastic bar whose tip node is tied to its middle node (free) by a slip spring 30 times
  // the bar's axial stiffness: its frequency bound k (1/m_a + 1/m_b) exceeds the elements'
  // (so the body's step must be shorter than the elements' alone, and a step at the
  // elements' bound is refused), and pulling the tip past the slip force then releasing it
  // must keep W_ext = KE + IE + HG + stored + dissipated (1 %) while the spring dissipates.
  const StructuredPrismMesh prism(Eigen::Vector3d(kLength, kSide, kSide), {20, 2, 2});
  SolidBody body(prism.mesh().nodes);
  std::vector<int> all(static_cast<std::size_t>(prism.mesh().node_count()));
  for (std::size_t n = 0; n < all.size(); ++n)
    all[n] = static_cast<int>(n);
  body.add_part("bar",
                SolidModel<Elastic>(
                    prism.mesh(), [](double) { return Elastic(kE, kNu); }, kDensity),
                all);
  const double element_step = body.stable_time_step(0.9);
  const double axial = kE * kSide * kSide / kLength;
  const double slip_force = 0.3 * axial * 1e-3 * kLength; // slips at 0.3e-3 strain
  const int tip = prism.node_index(20, 1, 1), middle = prism.node_index(10, 1, 1);
  body.add_interaction(std::make_unique<SlipSpring>(tip, middle, 30.0 * axial, slip_force));

  const Eigen::VectorXd mass = body.lumped_mass();
  const double w_el = body.element_frequency();
  const double w_int2 = 30.0 * axial * (1.0 / mass[3 * tip] + 1.0 / mass[3 * middle]);
  EXPECT_GT(w_int2, w_el * w_el);
  EXPECT_NEAR(body.stable_time_step(0.9), 0.9 * 2.0 / std::sqrt(w_el * w_el + w_int2),
              1e-12 * element_step);
  EXPECT_LT(body.stable_time_step(0.9), element_step);

  SolidLoading loading;
  for (int n : prism.face_nodes(PrismFace::x_min))
    loading.prescribed.add(n, 0, 0.0);
  loading.prescribed.add(prism.node_index(0, 0, 0), 1, 0.0);
  loading.prescribed.add(prism.node_index(0, 0, 0), 2, 0.0);
  loading.prescribed.add(prism.node_index(0, 2, 0), 2, 0.0);
  for (int n : prism.face_nodes(PrismFace::x_max))
    loading.prescribed.add(n, 0, 1e-3 * kLength);
  const double period = 4.0 * kLength / std::sqrt(kE / kDensity);
  const double half = 20.0 * period;
  // out to 1e-3 strain and back to 0
  loading.history = [half](double t) {
    return t <= half ? smooth_ramp(t, half) : 1.0 - smooth_ramp(t - half, half);
  };
  EXPECT_THROW(SolidExplicit<SolidBody>(body, loading, {0.9, element_step}), std::invalid_argument);
  SolidExplicit<SolidBody> solver(body, loading);
  std::string failure;
  double worst = 0.0;
  for (int k = 1; k <= 40; ++k) {
    ASSERT_TRUE(solver.run_to(2.0 * half * k / 40, failure)) << failure;
    worst = std::max(worst, solver.energy().relative_error());
  }
  const SolidExplicitEnergy& e = solver.energy();
  // the spring slipped both ways: its dissipation is a sizeable part of the external work
  EXPECT_GT(e.friction, 0.05 * e.external);
  EXPECT_LT(worst, 0.01);
  RecordProperty("friction_over_external", std::to_string(e.friction / e.external));
  RecordProperty("max_energy_error", std::to_string(worst));
  RecordProperty("steps", std::to_string(solver.steps()));
}

TEST(SolidBody, RefusesAPartWhoseNodesAreNotTheBodysNodes) {
  const StructuredPrismMesh prism(Eigen::Vector3d(10.0, 10.0, 10.0), {1, 1, 1});
  SolidBody body(prism.mesh().nodes);
  const auto law = [](double) { return Elastic(kE, kNu); };
  std::vector<int> shifted{1, 0, 2, 3, 4, 5, 6, 7}; // nodes 0 and 1 swapped: wrong coordinates
  EXPECT_THROW(body.add_part("a", SolidModel<Elastic>(prism.mesh(), law, kDensity), shifted),
               std::invalid_argument);
  std::vector<int> out_of_range{0, 1, 2, 3, 4, 5, 6, 8};
  EXPECT_THROW(body.add_part("b", SolidModel<Elastic>(prism.mesh(), law, kDensity), out_of_range),
               std::invalid_argument);
  EXPECT_THROW(body.set_threads(0), std::invalid_argument);
  EXPECT_THROW(body.add_interaction(nullptr), std::invalid_argument);
}

} // namespace
} // namespace brb::solid
