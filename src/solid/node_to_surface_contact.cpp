// Node-to-surface penalty contact with Coulomb friction (see node_to_surface_contact.hpp).
//
// Forces (internal-force sense, f = dW/dx with W the stored energy) of a slave node s in
// contact with face c at xi_c, its anchor on face b at xi_a (a node in a concave corner has one
// such contact per face of the corner, each adding its own (C1)-(C5)):
//   (C1) g = (x_s - x_c) . n,  N = -k_N g
//   (C2) normal:  f_s += -N n,  f_a += N N_a(xi_c) n (a on face c)
//   (C3) d = x_s - x_b(xi_a),  u = (I - n n^T) d = T / k_T after the return map
//   (C4) friction spring:  f_s += T,  f_b -= T N_b(xi_a)
//   (C5) rotation of the tangent plane, -k_T (d . n) u . dn, with
//        u . dn = sum_alpha c_alpha . dt_alpha,  c_1 = t_2 x u / J,  c_2 = u x t_1 / J,
//        J = |t_1 x t_2|, dt_alpha = sum_a N_a,alpha dx_a + x_12 dxi_beta (beta != alpha),
//        and the closest point's variation A dxi = (dx_s - sum_a N_a dx_a) . t_alpha
//        + g n . sum_a N_a,alpha dx_a,  A = [t_a . t_b - g n . x_ab] (from (x_s - x_c) . t_alpha
//        = 0); with r_beta = c_alpha . x_12 (alpha != beta), w = A^-1 r:
//        f_s += -k_T (d . n) sum_alpha w_alpha t_alpha
//        f_a += -k_T (d . n) [sum_alpha N_a,alpha c_alpha - N_a sum_alpha w_alpha t_alpha
//                             + g (sum_alpha w_alpha N_a,alpha) n]
#include "brb/solid/node_to_surface_contact.hpp"
#include "brb/model/thread_team.hpp"

#include "brb/material/parameter_error.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace brb::solid {

struct NodeToSurfaceContact::Configuration {
  const Eigen::Matrix3Xd& reference;
  Eigen::Map<const Eigen::Matrix3Xd> displacement;

  Eigen::Vector3d position(int node) const { return reference.col(node) + displacement.col(node); }
  Eigen::Matrix<double, 3, 4> face(const QuadFace& face) const {
    Eigen::Matrix<double, 3, 4> nodes;
    for (int a = 0; a < 4; ++a)
      nodes.col(a) = position(face[a]);
    return nodes;
  }
  /// The current nodes of master face `index` of `pass`.
  Eigen::Matrix<double, 3, 4> master_face(const Pass& pass, int index) const {
    return face(pass.master_faces[static_cast<std::size_t>(index)]);
  }
};

namespace {

void require(bool valid, const char* field, const std::string& expected, double value) {
  if (valid)
    return;
  std::ostringstream message;
  message << "node-to-surface contact: " << field << " must be " << expected << ", got " << value;
  throw ParameterError(field, message.str());
}

/// Distance from `point` to the axis-aligned bounding box of the face's current nodes.
double distance_to_box(const Eigen::Matrix<double, 3, 4>& nodes, const Eigen::Vector3d& point) {
  const Eigen::Vector3d low = nodes.rowwise().minCoeff();
  const Eigen::Vector3d high = nodes.rowwise().maxCoeff();
  const Eigen::Vector3d outside =
      (low - point).cwiseMax(point - high).cwiseMax(Eigen::Vector3d::Zero());
  return outside.norm();
}

void check_surface(const std::vector<QuadFace>& faces, const char* name,
                   const Eigen::Matrix3Xd& reference) {
  const auto fail = [&](std::size_t f, const std::string& what) {
    std::ostringstream message;
    message << "node-to-surface contact: " << name << "[" << f << "]: " << what;
    throw std::invalid_argument(message.str());
  };
  if (faces.empty()) {
    std::ostringstream message;
    message << "node-to-surface contact: " << name << " has no face (expected at least one)";
    throw std::invalid_argument(message.str());
  }
  const long node_count = reference.cols();
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Eigen::Matrix<double, 3, 4> nodes;
    for (int a = 0; a < 4; ++a) {
      const int node = faces[f][a];
      if (node < 0 || node >= node_count)
        fail(f, "node " + std::to_string(node) + " is not a node of the model (expected 0.." +
                    std::to_string(node_count - 1) + ")");
      for (int b = 0; b < a; ++b)
        if (faces[f][b] == node)
          fail(f, "node " + std::to_string(node) + " appears twice (expected 4 distinct nodes)");
      nodes.col(a) = reference.col(node);
    }
    if (!(quad_area(nodes) > 0.0))
      fail(f, "the face has no area (expected 4 nodes spanning a quadrilateral)");
  }
}

} // namespace

void NodeToSurfaceContactSettings::validate() const {
  require(std::isfinite(normal_penalty) && normal_penalty > 0.0, "normal_penalty",
          "finite and > 0 N/mm^3", normal_penalty);
  require(std::isfinite(tangential_stiffness_ratio) && tangential_stiffness_ratio > 0.0,
          "tangential_stiffness_ratio", "finite and > 0 (k_T / k_N)", tangential_stiffness_ratio);
  require(std::isfinite(friction_coefficient) && friction_coefficient >= 0.0,
          "friction_coefficient", "finite and >= 0", friction_coefficient);
  require(std::isfinite(search_distance) && search_distance > 0.0, "search_distance",
          "finite and > 0 mm", search_distance);
}

NodeToSurfaceContact::Pass
NodeToSurfaceContact::make_pass(const Eigen::Matrix3Xd& reference,
                                const std::vector<QuadFace>& slave, std::vector<QuadFace> master,
                                double penalty, const NodeToSurfaceContactSettings& settings) {
  Pass pass;
  // tributary area: a quarter of each adjacent slave face's reference area
  std::vector<double> area(static_cast<std::size_t>(reference.cols()), 0.0);
  for (const QuadFace& face : slave) {
    Eigen::Matrix<double, 3, 4> nodes;
    for (int a = 0; a < 4; ++a)
      nodes.col(a) = reference.col(face[a]);
    const double quarter = 0.25 * quad_area(nodes);
    for (int node : face)
      area[static_cast<std::size_t>(node)] += quarter;
  }
  for (std::size_t node = 0; node < area.size(); ++node)
    if (area[node] > 0.0) {
      const double normal_stiffness = penalty * area[node];
      pass.slave_nodes.push_back(static_cast<int>(node));
      pass.normal_stiffness.push_back(normal_stiffness);
      pass.laws.emplace_back(material::PenaltyFrictionParameters{
          normal_stiffness, settings.tangential_stiffness_ratio * normal_stiffness,
          settings.friction_coefficient});
    }
  pass.master_faces = std::move(master);
  for (const QuadFace& face : pass.master_faces)
    pass.master_nodes.insert(pass.master_nodes.end(), face.begin(), face.end());
  std::sort(pass.master_nodes.begin(), pass.master_nodes.end());
  pass.master_nodes.erase(std::unique(pass.master_nodes.begin(), pass.master_nodes.end()),
                          pass.master_nodes.end());
  pass.committed.resize(pass.slave_nodes.size());
  pass.trial = pass.committed;
  return pass;
}

NodeToSurfaceContact::NodeToSurfaceContact(Eigen::Matrix3Xd reference,
                                           std::vector<QuadFace> slave_surface,
                                           std::vector<QuadFace> master_surface,
                                           const NodeToSurfaceContactSettings& settings)
    : reference_(std::move(reference)), settings_(settings) {
  settings_.validate();
  if (!reference_.allFinite())
    throw std::invalid_argument(
        "node-to-surface contact: reference coordinates must be finite numbers");
  check_surface(slave_surface, "slave_surface", reference_);
  check_surface(master_surface, "master_surface", reference_);
  // two-pass: each surface is the other's master with half the penalty, so the pair is as
  // stiff as one pass when both see the same penetration
  const double penalty =
      settings_.two_pass ? 0.5 * settings_.normal_penalty : settings_.normal_penalty;
  passes_.push_back(make_pass(reference_, slave_surface, master_surface, penalty, settings_));
  if (settings_.two_pass)
    passes_.push_back(make_pass(reference_, master_surface, slave_surface, penalty, settings_));
}

void NodeToSurfaceContact::update_buckets(Pass& pass, const Configuration& configuration) {
  bool rebuild = !pass.buckets_built;
  if (!rebuild) {
    const double limit = 0.5 * pass.buckets.width();
    for (std::size_t m = 0; m < pass.master_nodes.size() && !rebuild; ++m)
      rebuild = (configuration.displacement.col(pass.master_nodes[m]) -
                 pass.master_displacement_at_build.col(static_cast<Eigen::Index>(m)))
                    .norm() > limit;
  }
  if (!rebuild)
    return;
  const Eigen::Matrix3Xd current = reference_ + configuration.displacement;
  pass.buckets.build(current, pass.master_faces, settings_.search_distance);
  pass.master_displacement_at_build.resize(3, static_cast<Eigen::Index>(pass.master_nodes.size()));
  for (std::size_t m = 0; m < pass.master_nodes.size(); ++m)
    pass.master_displacement_at_build.col(static_cast<Eigen::Index>(m)) =
        configuration.displacement.col(pass.master_nodes[m]);
  pass.buckets_built = true;
  ++statistics_.bucket_builds;
}

namespace {

/// A projection just beyond a face's edge with a penetration deeper than half the face's
/// smaller half-size (|dx/dxi|, |dx/deta|) is a node beside a convex edge of the master body
/// (e.g. a casing node at the mouth once the core has slid out from under it: beside the core's
/// side face, 'penetrating' it by the core's half-width), not a node under a valley crease,
/// whose band is as deep as penalty penetrations are (a small fraction of a face).
bool beside_convex_edge(const QuadProjection& projection) {
  const double half_size =
      std::min(projection.point.tangents.col(0).norm(), projection.point.tangents.col(1).norm());
  return projection.gap < -0.5 * half_size;
}

} // namespace

void NodeToSurfaceContact::collect_hits(const Pass& pass, const Configuration& configuration,
                                        const Eigen::Vector3d& point, int own_node,
                                        NodeRecord& record) const {
  // a face on whose extension the point projects at most kEdgeTolerance beyond an edge is a
  // candidate too (the valley crease's dead zone, see the header); nearest_of prefers faces
  // on which it projects inside
  constexpr double kEdgeTolerance = 0.05;
  record.hits.clear();
  for (int f : pass.buckets.candidates(point)) {
    const QuadFace& face = pass.master_faces[static_cast<std::size_t>(f)];
    if (std::find(face.begin(), face.end(), own_node) != face.end())
      continue;
    const Eigen::Matrix<double, 3, 4> nodes = configuration.face(face);
    ++record.box_tests;
    if (distance_to_box(nodes, point) > settings_.search_distance)
      continue;
    ++record.projections;
    const QuadProjection projection = project_on_quad(nodes, point);
    if (!projection.converged || projection.excess > kEdgeTolerance)
      continue;
    // within the edge band (inside or just beyond an edge) and half a face deep: beside a
    // convex edge, whichever side of the edge round-off puts it (a node under the core's
    // bearing face lies on the plane of its side faces' edges: 'inside' a side face at its
    // edge, a half-width deep)
    if (projection.excess > -kEdgeTolerance && beside_convex_edge(projection))
      continue;
    record.hits.push_back({f, projection});
  }
}

namespace {

/// Among `hits` that `admit` accepts, the nearest (smallest |gap|) of those on whose face the
/// point projects inside; when there is none, the nearest of those beyond an edge. Face -1
/// when none; ties go to the first in the bucket's order (the same for any thread count).
template <class HitType, class Admit>
HitType nearest_of(const std::vector<HitType>& hits, const Admit& admit) {
  HitType inside, near_edge;
  double inside_distance = std::numeric_limits<double>::infinity();
  double near_edge_distance = inside_distance;
  for (const HitType& hit : hits) {
    if (!admit(hit))
      continue;
    const double distance = std::abs(hit.projection.gap);
    if (hit.projection.inside && distance < inside_distance) {
      inside_distance = distance;
      inside = hit;
    } else if (!hit.projection.inside && distance < near_edge_distance) {
      near_edge_distance = distance;
      near_edge = hit;
    }
  }
  return inside.face >= 0 ? inside : near_edge;
}

/// Two master faces, each with the slave node's contact point and outward normal on it, form
/// a valley (a concave corner of the master body, which the node can penetrate on both sides)
/// when each face's centroid lies in front of the other's tangent plane at its contact point;
/// at a convex corner both lie behind, and the node keeps the nearest face only (the shortest
/// way out of the body).
bool form_valley(const Eigen::Matrix<double, 3, 4>& nodes_a, const QuadPoint& point_a,
                 const Eigen::Matrix<double, 3, 4>& nodes_b, const QuadPoint& point_b) {
  const Eigen::Vector3d centroid_a = nodes_a.rowwise().mean();
  const Eigen::Vector3d centroid_b = nodes_b.rowwise().mean();
  return (centroid_b - point_a.position).dot(point_a.normal) > 0.0 &&
         (centroid_a - point_b.position).dot(point_b.normal) > 0.0;
}

/// Each committed contact of `committed` continues in the trial contact of its normal cluster
/// (the closest normal, within kNormalClusterCosine), keeping its stick anchor:
/// predecessor[k] the committed contact trial contact k continues (-1: a new contact),
/// continued[j] whether committed contact j continues.
template <class HitType>
void match_committed_contacts(const NodeContactState& committed,
                              const std::array<HitType, kMaxFaceContacts>& contacts, int count,
                              std::array<int, kMaxFaceContacts>& predecessor,
                              std::array<bool, kMaxFaceContacts>& continued) {
  predecessor.fill(-1);
  continued.fill(false);
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d& n = contacts[static_cast<std::size_t>(k)].projection.point.normal;
    double closest = kNormalClusterCosine;
    int& match = predecessor[static_cast<std::size_t>(k)];
    for (int j = 0; j < committed.contact_count; ++j) {
      const double cosine = committed.contact(j).normal.dot(n);
      if (!continued[static_cast<std::size_t>(j)] && cosine > closest) {
        closest = cosine;
        match = j;
      }
    }
    if (match >= 0)
      continued[static_cast<std::size_t>(match)] = true;
  }
}

} // namespace

void NodeToSurfaceContact::add_contact_forces(
    NodeRecord& record, int slave, const QuadPoint& contact, const QuadFace& contact_face,
    const QuadFace& anchor_nodes, const Eigen::Vector2d& anchor_natural, double N,
    const Eigen::Vector3d& T, double normal_offset, double gap, double k_T) {
  const Eigen::Vector3d& n = contact.normal;
  // (C2) normal, (C4) friction spring
  record.add(slave, -N * n + T);
  for (int a = 0; a < 4; ++a)
    record.add(contact_face[a], N * contact.shape.value[a] * n);
  const QuadShape anchor_shape = QuadShape::at(anchor_natural);
  for (int b = 0; b < 4; ++b)
    record.add(anchor_nodes[b], -anchor_shape.value[b] * T);

  // (C5) rotation of the tangent plane
  if (normal_offset != 0.0 && T.squaredNorm() > 0.0) {
    const Eigen::Vector3d u = T / k_T;
    const Eigen::Vector3d t1 = contact.tangents.col(0), t2 = contact.tangents.col(1);
    const Eigen::Vector3d c1 = t2.cross(u) / contact.area_density;
    const Eigen::Vector3d c2 = u.cross(t1) / contact.area_density;
    Eigen::Matrix2d A;
    A(0, 0) = t1.dot(t1);
    A(1, 1) = t2.dot(t2);
    A(0, 1) = A(1, 0) = t1.dot(t2) - gap * n.dot(contact.twist);
    const Eigen::Vector2d r(c2.dot(contact.twist), c1.dot(contact.twist));
    const Eigen::Vector2d w = A.inverse() * r;
    const Eigen::Vector3d w_t = w.x() * t1 + w.y() * t2;
    const double scale = -k_T * normal_offset;
    record.add(slave, scale * w_t);
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector2d dN = contact.shape.gradient.row(a).transpose();
      record.add(contact_face[a], scale * (dN.x() * c1 + dN.y() * c2 -
                                           contact.shape.value[a] * w_t + gap * w.dot(dN) * n));
    }
  }
}

int NodeToSurfaceContact::select_contacts(const Pass& pass, const Configuration& configuration,
                                          const std::vector<Hit>& hits,
                                          std::array<Hit, kMaxFaceContacts>& contacts) const {
  // the nearest face (inside first, see nearest_of); when the node penetrates it, the nearest
  // penetrated face of each further normal cluster that forms a valley with every face already
  // taken (a concave corner: two independent penalties, one per face)
  const Hit nearest = nearest_of(hits, [](const Hit&) { return true; });
  if (nearest.face < 0 || !(nearest.projection.gap < 0.0))
    return 0;
  contacts[0] = nearest;
  int count = 1;
  while (count < kMaxFaceContacts) {
    const Hit further = nearest_of(hits, [&](const Hit& hit) {
      if (!(hit.projection.gap < 0.0))
        return false;
      for (int k = 0; k < count; ++k) {
        const Hit& taken = contacts[static_cast<std::size_t>(k)];
        if (hit.projection.point.normal.dot(taken.projection.point.normal) > kNormalClusterCosine ||
            !form_valley(configuration.master_face(pass, hit.face), hit.projection.point,
                         configuration.master_face(pass, taken.face), taken.projection.point))
          return false;
      }
      return true;
    });
    if (further.face < 0)
      break;
    contacts[static_cast<std::size_t>(count++)] = further;
  }
  return count;
}

void NodeToSurfaceContact::contact_of_node(Pass& pass, std::size_t i,
                                           const Configuration& configuration) const {
  const int slave = pass.slave_nodes[i];
  const NodeContactState& committed = pass.committed[i];
  NodeContactState& trial = pass.trial[i];
  trial = NodeContactState{};
  NodeRecord& record = pass.records[i];
  record.count = 0;
  record.projections = 0;
  record.box_tests = 0;
  record.failed = false;
  const material::PenaltyFriction& law = pass.laws[i];
  const double k_T = law.parameters().tangential_stiffness;
  const Eigen::Vector3d x_s = configuration.position(slave);
  collect_hits(pass, configuration, x_s, slave, record);
  std::array<Hit, kMaxFaceContacts> contacts;
  const int count = select_contacts(pass, configuration, record.hits, contacts);

  // a committed contact that does not continue ends: its friction spring relaxes, and the
  // spring's energy 1/2 |T|^2 / k_T is credited as friction work, so the stored energy it
  // leaves is not lost from the balance
  std::array<int, kMaxFaceContacts> predecessor;
  std::array<bool, kMaxFaceContacts> continued{};
  match_committed_contacts(committed, contacts, count, predecessor, continued);
  double dissipated = committed.dissipated_energy;
  for (int j = 0; j < committed.contact_count; ++j)
    if (!continued[static_cast<std::size_t>(j)])
      dissipated += 0.5 * committed.contact(j).tangential_force.squaredNorm() / k_T;

  const auto anchor_position = [&](int face, const Eigen::Vector2d& natural) {
    return QuadPoint::at(configuration.master_face(pass, face), natural).position;
  };
  for (int k = 0; k < count; ++k) {
    const Hit& hit = contacts[static_cast<std::size_t>(k)];
    const QuadPoint& contact = hit.projection.point;
    const double gap = hit.projection.gap; // (C1)
    if (gap < -0.5 * settings_.search_distance) {
      std::ostringstream message;
      message << "node-to-surface contact: node " << slave << " at (" << x_s.x() << ", " << x_s.y()
              << ", " << x_s.z() << ") penetrates master face " << hit.face << " by " << -gap
              << " mm (natural coordinates " << contact.natural.x() << ", " << contact.natural.y()
              << (hit.projection.inside ? ", inside the face" : ", beyond its edge")
              << "), more than half the search distance (" << settings_.search_distance
              << " mm): the penalty is too soft or the step too large";
      record.failed = true;
      record.reason = message.str();
      return;
    }
    const QuadFace& contact_face = pass.master_faces[static_cast<std::size_t>(hit.face)];
    const Eigen::Vector3d& n = contact.normal;

    // stick anchor: the committed one of this cluster, or the contact point for a new contact
    int anchor_face = hit.face;
    Eigen::Vector2d anchor_natural = contact.natural;
    if (const int j = predecessor[static_cast<std::size_t>(k)]; j >= 0) {
      anchor_face = committed.contact(j).anchor_face;
      anchor_natural = committed.contact(j).anchor_natural;
    }
    Eigen::Vector3d x_a = anchor_position(anchor_face, anchor_natural);

    // (C3) tangential relative displacement in the tangent plane's basis
    const Eigen::Vector3d e1 = contact.tangents.col(0).normalized();
    const Eigen::Vector3d e2 = n.cross(e1);
    Eigen::Vector3d d = x_s - x_a;
    const Eigen::Vector2d u_trial(e1.dot(d), e2.dot(d));
    material::FrictionState start;
    start.dissipated_energy = dissipated; // slip zero: the anchor carries it
    const material::PenaltyFriction::Response response = law.evaluate(start, gap, u_trial);
    Eigen::Vector3d T = response.tangential_force.x() * e1 + response.tangential_force.y() * e2;
    dissipated = response.state.dissipated_energy;

    if (response.slipping) {
      // move the anchor by the slip increment, back onto a face of this contact's normal
      // cluster (maybe another face: the core slides along the whole casing). Never onto a
      // face of another direction (the other side of a corner): its projection would put the
      // anchor off x_a + slip, and the next step would read the offset as slip and credit
      // kappa N x offset that no force did work for.
      const Eigen::Vector3d target =
          x_a + response.state.slip.x() * e1 + response.state.slip.y() * e2;
      collect_hits(pass, configuration, target, slave, record);
      const Hit moved = nearest_of(record.hits, [&](const Hit& candidate) {
        return candidate.projection.point.normal.dot(n) > kNormalClusterCosine;
      });
      if (moved.face >= 0) {
        anchor_face = moved.face;
        anchor_natural = moved.projection.point.natural;
      } else {
        // slid off the cluster's faces (a free edge): the contact restarts at the contact
        // point with T = 0, and the whole trial spring energy 1/2 k_T |u|^2 is friction work
        anchor_face = hit.face;
        anchor_natural = contact.natural;
        T.setZero();
        dissipated = start.dissipated_energy + 0.5 * k_T * u_trial.squaredNorm();
      }
      x_a = anchor_position(anchor_face, anchor_natural);
      d = x_s - x_a;
    }
    const double N = response.normal_force;

    add_contact_forces(record, slave, contact, contact_face,
                       pass.master_faces[static_cast<std::size_t>(anchor_face)], anchor_natural, N,
                       T, d.dot(n), gap, k_T);

    FaceContact& state = trial.contact(k);
    state.face = hit.face;
    state.natural = contact.natural;
    state.gap = gap;
    state.normal_force = N;
    state.normal = n;
    state.tangential_force = T;
    state.anchor_face = anchor_face;
    state.anchor_natural = anchor_natural;
    trial.slipping = trial.slipping || response.slipping;
    if (!T.allFinite() || !std::isfinite(N)) {
      record.failed = true;
      record.reason = "node-to-surface contact: non-finite force at node " + std::to_string(slave);
    }
  }
  trial.contact_count = count;
  trial.dissipated_energy = dissipated;
}

void NodeToSurfaceContact::set_threads(int threads) {
  team_ = model::ThreadTeam(threads); // throws std::invalid_argument for threads < 1
}

bool NodeToSurfaceContact::add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                                     std::string& reason) {
  const Eigen::Index dofs = 3 * reference_.cols();
  if (displacement.size() != dofs || force.size() != dofs) {
    reason = "node-to-surface contact: displacement and force must have " + std::to_string(dofs) +
             " entries (3 per node)";
    return false;
  }
  if (!displacement.allFinite()) {
    reason = "node-to-surface contact: non-finite displacement";
    return false;
  }
  const Configuration configuration{
      reference_, Eigen::Map<const Eigen::Matrix3Xd>(displacement.data(), 3, reference_.cols())};
  statistics_.projections_last_call = 0;
  statistics_.box_tests_last_call = 0;
  statistics_.nodes_in_contact = 0;
  statistics_.nodes_slipping = 0;
  statistics_.nodes_in_corners = 0;
  for (Pass& pass : passes_) {
    update_buckets(pass, configuration);
    const std::size_t n = pass.slave_nodes.size();
    pass.records.resize(n);
    const auto block = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        contact_of_node(pass, i, configuration);
    };
    team_.run(n, block);
    // in node order: the first failure, the forces and the counts (the same for any threads)
    for (std::size_t i = 0; i < n; ++i) {
      const NodeRecord& record = pass.records[i];
      if (record.failed) {
        reason = record.reason;
        return false;
      }
      for (int k = 0; k < record.count; ++k)
        force.segment<3>(3 * static_cast<Eigen::Index>(record.node[static_cast<std::size_t>(k)])) +=
            record.value[static_cast<std::size_t>(k)];
      statistics_.projections_last_call += record.projections;
      statistics_.box_tests_last_call += record.box_tests;
      statistics_.nodes_in_contact += pass.trial[i].in_contact() ? 1 : 0;
      statistics_.nodes_slipping += pass.trial[i].slipping ? 1 : 0;
      statistics_.nodes_in_corners += pass.trial[i].contact_count > 1 ? 1 : 0;
    }
  }
  return true;
}

void NodeToSurfaceContact::commit() {
  for (Pass& pass : passes_)
    pass.committed = pass.trial;
}

namespace {

double stored_energy_of(const std::vector<NodeContactState>& states,
                        const std::vector<material::PenaltyFriction>& laws) {
  double energy = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const material::PenaltyFrictionParameters& p = laws[i].parameters();
    for (int k = 0; k < states[i].contact_count; ++k) { // independent penalties: the sum
      const FaceContact& contact = states[i].contact(k);
      energy += 0.5 * p.normal_stiffness * contact.gap * contact.gap +
                0.5 * contact.tangential_force.squaredNorm() / p.tangential_stiffness;
    }
  }
  return energy;
}

double dissipated_energy_of(const std::vector<NodeContactState>& states) {
  double energy = 0.0;
  for (const NodeContactState& state : states)
    energy += state.dissipated_energy;
  return energy;
}

} // namespace

double NodeToSurfaceContact::stored_energy() const {
  double energy = 0.0;
  for (const Pass& pass : passes_)
    energy += stored_energy_of(pass.committed, pass.laws);
  return energy;
}

double NodeToSurfaceContact::dissipated_energy() const {
  double energy = 0.0;
  for (const Pass& pass : passes_)
    energy += dissipated_energy_of(pass.committed);
  return energy;
}

double NodeToSurfaceContact::trial_stored_energy() const {
  double energy = 0.0;
  for (const Pass& pass : passes_)
    energy += stored_energy_of(pass.trial, pass.laws);
  return energy;
}

double NodeToSurfaceContact::trial_dissipated_energy() const {
  double energy = 0.0;
  for (const Pass& pass : passes_)
    energy += dissipated_energy_of(pass.trial);
  return energy;
}

double NodeToSurfaceContact::frequency_bound_squared(const Eigen::VectorXd& lumped_mass) const {
  if (lumped_mass.size() != 3 * reference_.cols())
    throw std::invalid_argument("node-to-surface contact: lumped mass must have " +
                                std::to_string(3 * reference_.cols()) + " entries (3 per node)");
  const auto node_mass = [&](int node) {
    return lumped_mass.segment<3>(3 * static_cast<Eigen::Index>(node)).minCoeff();
  };
  // the contact point's force is shared by N_a, so its effective inverse mass
  // sum_a N_a^2 / m_a is at most that of the lightest master node
  double bound = 0.0;
  for (const Pass& pass : passes_) {
    double lightest_master = std::numeric_limits<double>::infinity();
    for (int node : pass.master_nodes)
      lightest_master = std::min(lightest_master, node_mass(node));
    for (std::size_t i = 0; i < pass.slave_nodes.size(); ++i) {
      const material::PenaltyFrictionParameters& p = pass.laws[i].parameters();
      const double stiffness = std::max(p.normal_stiffness, p.tangential_stiffness);
      bound = std::max(bound,
                       stiffness * (1.0 / node_mass(pass.slave_nodes[i]) + 1.0 / lightest_master));
    }
  }
  return bound;
}

const std::vector<int>& NodeToSurfaceContact::slave_nodes(int pass) const {
  return passes_.at(static_cast<std::size_t>(pass)).slave_nodes;
}
const std::vector<QuadFace>& NodeToSurfaceContact::master_faces(int pass) const {
  return passes_.at(static_cast<std::size_t>(pass)).master_faces;
}
const std::vector<double>& NodeToSurfaceContact::normal_stiffness(int pass) const {
  return passes_.at(static_cast<std::size_t>(pass)).normal_stiffness;
}
const std::vector<NodeContactState>& NodeToSurfaceContact::states(int pass) const {
  return passes_.at(static_cast<std::size_t>(pass)).committed;
}
const std::vector<NodeContactState>& NodeToSurfaceContact::trial_states(int pass) const {
  return passes_.at(static_cast<std::size_t>(pass)).trial;
}

} // namespace brb::solid
