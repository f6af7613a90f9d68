// Node-to-surface penalty contact with Coulomb friction between two surfaces of a solid model
// (BRB_SOURCE_FACTS section 4: normal penalty on the gap, Coulomb friction with a tangential
// penalty, kappa = 0.1 in the source), e.g. the steel core and the mortar casing.
//
// Surfaces are lists of bilinear quad faces (bilinear_quad.hpp): 4 global node indices,
// counter-clockwise seen from outside the body the face bounds, so the right-hand normal
// points out of its own body, into the gap.
//
// Per slave node s (one pass; see two_pass):
//  - Normal (Wriggers, Computational Contact Mechanics, sec. 4.1): closest point x_c =
//    x(xi_c) of x_s on the master faces, gap g = (x_s - x_c) . n with n the master face's
//    outward normal at xi_c; N = k_N <-g>, k_N = penalty x tributary area of s (a quarter of
//    each adjacent slave face's reference area). Stored energy 1/2 k_N g^2, whose gradient is
//    exactly k_N g n on s and -k_N g N_a(xi_c) n on the master face's nodes (the closest
//    point's own variation drops out because x_s - x_c is normal to the face).
//  - Friction: a stick anchor, a material point of the master surface (face, xi_a), is where
//    the node first touched or last slid. d = x_s - x_a(xi_a) in 3D, its part in the tangent
//    plane at x_c, u = (I - n n^T) d, in the basis e_1 = t_1 / |t_1|, e_2 = n x e_1, goes to
//    material::PenaltyFriction (committed slip zero: the anchor carries the slip) for the
//    Coulomb return map and its dissipation. On slip the anchor moves by the slip increment,
//    x_a + s_1 e_1 + s_2 e_2, projected back on the master surface: the anchor can cross to
//    another face of the contact's normal cluster (the core slides along the whole casing) and
//    T = k_T u holds again with the new anchor. Only faces of that cluster (see Corners): the
//    projection of x_a + slip on a flat cluster moves nothing in its plane, so the anchor lands
//    on the target, the next step's spring is T / k_T, and the credited friction work T . slip
//    is exactly the work of T minus the change of 1/2 |T|^2 / k_T (steady sliding: T . dx).
//    Projected on the other face of a corner, the anchor would land off the target, and the
//    next step would read the offset as slip and credit kappa N x offset that no force did work
//    for. A target beyond the cluster's faces (a free edge) restarts the contact at the contact
//    point with T = 0, the trial spring energy 1/2 k_T |u|^2 credited as friction work.
//    Force: T = T_1 e_1 + T_2 e_2; T on s, -T N_b(xi_a) on the anchor face (internal-force
//    sense: the spring pulls the slave back towards its anchor).
//    Stored energy 1/2 |T|^2 / k_T = 1/2 k_T |u|^2 in stick; its exact gradient also has the
//    term of the tangent plane's rotation, -k_T (d . n) u . dn (d . n = g on a flat face):
//    kept (with dn from t_1, t_2 and the closest point's variation dxi), so in stick the force
//    is the exact gradient of the stored energy and the pair of forces has no moment.
//  - Edges: a node projects on a face when its closest point lies inside it; when it lies
//    inside no face, a face whose extension it projects on at most 0.05 beyond an edge (in
//    natural coordinates, 2.5 % of the face's size) is taken. This closes the dead zone of a
//    valley crease between two faces, where a penetrating node's closest points on both
//    faces' extensions lie outside both faces (a band of width ~ penetration x crease angle).
//    Neither face is taken when the point lies within that band of an edge (inside or beyond)
//    and deeper than half the face's smaller half-size: such a node lies beside a convex edge
//    of the master body (a casing node at the mouth once the core has slid out from under it,
//    or a casing node under the core's bearing face, which lies on the plane of the side faces'
//    edges, would otherwise 'penetrate' a side face by the core's half-width).
//  - Corners: master faces whose outward normals make less than 45 degrees with a contact's
//    normal are its normal cluster (coplanar neighbours, a crease as above, a warped face). The
//    node's first contact is its nearest face (as above); when it penetrates it, each further
//    cluster adds its nearest penetrated face that forms a valley with every face taken (each
//    face's centroid in front of the other's tangent plane at its contact point): a node in a
//    concave corner (a core corner in the corner of the casing's opening) is pushed out of each
//    face, N_i = k_N <-g_i>, with its own anchor and Coulomb state (at most kMaxFaceContacts).
//    The stored energy is the sum over the contacts, so in stick the force is still its exact
//    gradient. At a convex corner (centroids behind) the nearest face alone pushes the node out
//    (the shortest way out of the master body). A committed contact continues in the trial
//    contact of its cluster (the closest normal).
//  - Open (g >= 0 or no face), or a contact that leaves its cluster: no force; the anchor is
//    dropped (a new contact starts with T = 0, PenaltyFriction (F6)) and the spring's energy
//    1/2 |T|^2 / k_T is credited as friction work (it relaxes by slipping as the contact ends);
//    the node's dissipated energy is kept.
//
// Search: master faces in buckets along the master surface's longest axis (face_buckets.hpp),
// rebuilt when a master node has moved by more than half a bucket since the last build. For
// each slave node only the faces of its bucket are looked at, and only a face whose current
// bounding box is within search_distance of the node is projected (Newton). Cost of one call:
// O(M) for the moved check (M master nodes) + O(S c) box tests (S slave nodes, c faces per
// bucket) + one projection per (node, face) pair closer than search_distance (about one per
// node near the surface, none for a node far from it) + one more per slipping node (anchor);
// a rebuild, O(n + F), happens only after sliding half a bucket.
//
// Trial / commit as SolidInteraction: add_force() writes trial states only, commit() accepts
// them. Threads (set_threads): the slave nodes are shared among threads in contiguous blocks,
// each node writes only its own record (per contact at most 14 contributions on 9 nodes; its
// search counts), and the records are added to the force vector in node order by one thread,
// so results are bitwise the same for every thread count. Two-pass mode: each surface is also the
// master of the other's nodes, with half the penalty in each pass (symmetric treatment, no
// preferred surface).
#pragma once

#include "brb/material/penalty_friction.hpp"
#include "brb/model/thread_team.hpp"
#include "brb/solid/bilinear_quad.hpp"
#include "brb/solid/face_buckets.hpp"
#include "brb/solid/solid_interaction.hpp"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace brb::solid {

struct NodeToSurfaceContactSettings {
  double normal_penalty = 0.0;             ///< N/mm^3: k_N = it x tributary area (> 0)
  double tangential_stiffness_ratio = 1.0; ///< k_T / k_N (> 0)
  double friction_coefficient = 0.1;       ///< kappa (>= 0; source: 0.1)
  /// mm (> 0): faces whose bounding box is farther from a node are not projected; a
  /// penetration deeper than half of it is refused (add_force false), since one step deeper
  /// the node could leave the search box of its face and pass through unseen.
  double search_distance = 0.0;
  bool two_pass = false; ///< also the master surface's nodes on the slave faces, penalty / 2

  /// Throws ParameterError (a std::invalid_argument) naming the field.
  void validate() const;
};

/// At most this many contacts per slave node: one per cluster of master-face normals, so a node
/// in a concave corner (valley) of the master surface is pushed out of each face it penetrates
/// (two faces of a prismatic opening's corner, three at a box's inner corner).
inline constexpr int kMaxFaceContacts = 3;

/// Master faces whose outward normals make less than 45 degrees with a contact's normal belong
/// to its cluster: coplanar neighbours, a slight crease or a warped face, but not the other
/// face of a right-angled corner. cos(45 deg).
inline constexpr double kNormalClusterCosine = 0.70710678118654752;

/// One contact of a slave node with a master face (committed or trial).
struct FaceContact {
  int face = -1;                                              ///< master face of the contact point
  Eigen::Vector2d natural = Eigen::Vector2d::Zero();          ///< its natural coordinates
  double gap = 0.0;                                           ///< g (mm), < 0 in contact
  double normal_force = 0.0;                                  ///< N (N) >= 0, on the slave along n
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();           ///< master's outward normal at x_c
  Eigen::Vector3d tangential_force = Eigen::Vector3d::Zero(); ///< T (N); the slave gets -T
  int anchor_face = -1;                                       ///< stick anchor (master face)
  Eigen::Vector2d anchor_natural = Eigen::Vector2d::Zero();
};

/// The contact of one slave node (committed or trial). Its first contact (the nearest face's)
/// is the inherited FaceContact, where single-face users read it; a node in a concave corner
/// has its further contacts (one per further normal cluster) in corner_contacts.
struct NodeContactState : FaceContact {
  bool slipping = false; ///< any of its contacts slips
  int contact_count = 0; ///< 0 open, 1 one face, 2 or 3 a concave corner
  std::array<FaceContact, kMaxFaceContacts - 1> corner_contacts{};
  double dissipated_energy = 0.0; ///< friction work of this node since the start (N mm)

  bool in_contact() const { return contact_count > 0; }
  /// Contact k < contact_count: 0 the nearest face's, then the corner's further ones.
  const FaceContact& contact(int k) const {
    return k == 0 ? static_cast<const FaceContact&>(*this)
                  : corner_contacts[static_cast<std::size_t>(k - 1)];
  }
  FaceContact& contact(int k) {
    return k == 0 ? static_cast<FaceContact&>(*this)
                  : corner_contacts[static_cast<std::size_t>(k - 1)];
  }
};

/// What the last add_force() did (the search's cost) and how often the buckets were built.
struct ContactStatistics {
  long projections_last_call = 0; ///< closest-point projections (Newton)
  long box_tests_last_call = 0;   ///< faces whose bounding box was checked
  long bucket_builds = 0;         ///< since construction
  int nodes_in_contact = 0;       ///< trial
  int nodes_slipping = 0;         ///< trial
  int nodes_in_corners = 0;       ///< trial: nodes touching faces of more than one normal cluster
};

class NodeToSurfaceContact final : public SolidInteraction {
public:
  /// reference: coordinates of all nodes of the model (3 x n, mm). Throws
  /// std::invalid_argument for bad settings (naming the field) or a bad face (naming the
  /// surface, the face and what is wrong: a node out of range, repeated nodes, zero area).
  NodeToSurfaceContact(Eigen::Matrix3Xd reference, std::vector<QuadFace> slave_surface,
                       std::vector<QuadFace> master_surface,
                       const NodeToSurfaceContactSettings& settings);

  bool add_force(const Eigen::VectorXd& displacement, Eigen::VectorXd& force,
                 std::string& reason) override;
  void commit() override;
  double stored_energy() const override;
  double dissipated_energy() const override;
  double frequency_bound_squared(const Eigen::VectorXd& lumped_mass) const override;

  /// Energies of the last add_force().
  double trial_stored_energy() const;
  double trial_dissipated_energy() const;

  /// Threads of the slave-node loop (>= 1; default 1). Throws std::invalid_argument below 1.
  void set_threads(int threads);
  int threads() const { return team_.threads(); }

  const NodeToSurfaceContactSettings& settings() const { return settings_; }
  const ContactStatistics& statistics() const { return statistics_; }

  /// Pass 0: slave nodes on the master faces; pass 1 (two-pass mode only): the reverse.
  int pass_count() const { return static_cast<int>(passes_.size()); }
  const std::vector<int>& slave_nodes(int pass) const;
  const std::vector<QuadFace>& master_faces(int pass) const;
  /// k_N of each slave node (N/mm), in the order of slave_nodes().
  const std::vector<double>& normal_stiffness(int pass) const;
  const std::vector<NodeContactState>& states(int pass) const;
  const std::vector<NodeContactState>& trial_states(int pass) const;

private:
  /// A master face on which a point projects (see collect_hits).
  struct Hit {
    int face = -1;
    QuadProjection projection;
  };

  /// What one slave node adds to the force vector, and what its search cost.
  struct NodeRecord {
    // per contact: slave (normal + friction, rotation), contact face (normal, rotation),
    // anchor face
    static constexpr int kCapacity = 16 * kMaxFaceContacts;
    int count = 0;
    std::array<int, kCapacity> node{};
    std::array<Eigen::Vector3d, kCapacity> value;
    long projections = 0;
    long box_tests = 0;
    bool failed = false;
    std::string reason;
    std::vector<Hit> hits; // of the last collect_hits (kept: no allocation once grown)

    void add(int at, const Eigen::Vector3d& force) {
      node[static_cast<std::size_t>(count)] = at;
      value[static_cast<std::size_t>(count)] = force;
      ++count;
    }
  };

  struct Pass {
    std::vector<int> slave_nodes;
    std::vector<double> normal_stiffness;
    std::vector<material::PenaltyFriction> laws;
    std::vector<QuadFace> master_faces;
    std::vector<int> master_nodes;
    FaceBuckets buckets;
    bool buckets_built = false;
    Eigen::Matrix3Xd master_displacement_at_build; // one column per master node
    std::vector<NodeContactState> committed, trial;
    std::vector<NodeRecord> records; // of the last add_force, one per slave node
  };

  struct Configuration; // reference + displacement, node by node (no O(n) copy per call)

  static Pass make_pass(const Eigen::Matrix3Xd& reference, const std::vector<QuadFace>& slave,
                        std::vector<QuadFace> master, double penalty,
                        const NodeToSurfaceContactSettings& settings);
  /// Into record.hits, in the bucket's order: the master faces of `point`'s bucket within
  /// search_distance on which it projects inside or at most 0.05 (natural) beyond an edge, but
  /// not beside a convex edge. Faces holding `own_node` (the slave itself, when the surfaces
  /// share nodes) are skipped.
  void collect_hits(const Pass& pass, const Configuration& configuration,
                    const Eigen::Vector3d& point, int own_node, NodeRecord& record) const;
  /// The node's contacts among `hits` into `contacts` (the nearest face, then at a concave
  /// corner one face per further normal cluster; see the header comment); returns their count,
  /// 0 when the nearest face is not penetrated.
  int select_contacts(const Pass& pass, const Configuration& configuration,
                      const std::vector<Hit>& hits,
                      std::array<Hit, kMaxFaceContacts>& contacts) const;
  /// (C2), (C4), (C5) of one contact into `record` (node_to_surface_contact.cpp):
  /// normal_offset = (x_s - x_a) . n.
  static void add_contact_forces(NodeRecord& record, int slave, const QuadPoint& contact,
                                 const QuadFace& contact_face, const QuadFace& anchor_nodes,
                                 const Eigen::Vector2d& anchor_natural, double N,
                                 const Eigen::Vector3d& T, double normal_offset, double gap,
                                 double k_T);
  /// Rebuilds the pass's buckets when a master node moved by more than half a bucket.
  void update_buckets(Pass& pass, const Configuration& configuration);
  /// The trial contact of slave `i` of `pass` into pass.trial[i] and pass.records[i] (its
  /// own slots: safe on any thread); record.failed on a too deep penetration or a non-finite
  /// force.
  void contact_of_node(Pass& pass, std::size_t i, const Configuration& configuration) const;

  Eigen::Matrix3Xd reference_;
  NodeToSurfaceContactSettings settings_;
  model::ThreadTeam team_;
  std::vector<Pass> passes_;
  ContactStatistics statistics_;
};

} // namespace brb::solid
