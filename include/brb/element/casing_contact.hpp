// CasingContact: the link between a core node and the casing node at the same station
// (DESIGN.md section 4, BRB_SOURCE_FACTS sections 3-4). In each transverse direction
// (section y and z) the core has a clearance `gap` to the casing on both sides; once it
// closes, the core bears on the mortar: the bearing stress follows the mortar damage law at
// the strain penetration / bearing depth (the mortar's thickness in that direction), over
// the bearing area (local crushing softens it,
// and each of the four faces keeps its own damage). An always-active soft spring models the
// unbonding layer (it keeps the casing stable while gaps are open). Along the axis, Coulomb
// friction acts with the total bearing force as normal force.
//
// Directions are the initial (global) axes of the brace: the link is geometrically linear,
// which is exact for the small rotations of the casing relative to the core's axis.
// DOF: 6 per node (translations used), force on the core = -force on the casing.
//
// Core expansion (issue 4, optional: CoreExpansion): a yielding core in compression grows
// sideways (plastic incompressibility, lateral strain -0.5 x axial strain) and closes the
// clearance even when it stays straight. The link then also holds the core nodes before and
// after its station (the chord between them gives the core's axial strain eps there) and the
// core's half-extent along y and z grows by e = -nu_c eps h / 2. Each face's penetration is
//   p(+y) = r_y - gap_y + e_y,   p(-y) = -r_y - gap_y + e_y   (and z),
// so both faces of a direction can bear at once (a confined core: equal and opposite lateral
// forces, twice the normal force for friction). The bearing forces are the derivatives of
// the faces' stored energy, so the chord's nodes get F dp/de de/dx along the chord, and the
// tangent is the exact second derivative (plus friction's dT/dN dN/dx).
//
// Open links (DESIGN.md section 10): while no face is penetrated only the layer spring acts
// (friction has no normal force: zero force and tangent, its slip follows the axial motion),
// so the tangent is the constant layer tangent, kept from construction; the bearing and
// friction laws are not called. `skip_open_links` false takes the general path (the
// benchmark's reference); both give the same numbers bit for bit.
#pragma once

#include "brb/element/element.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/penalty_friction.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <array>
#include <optional>
#include <vector>

namespace brb::element {

/// Splitting of a mortar-only casing (issue 4/6: the thesis's small BRB, BRB_SOURCE_FACTS
/// section 6). The two faces of a direction bear on the two halves of the casing, which only
/// the mortar walls beside the core's opening hold together; a core pressing both faces (its
/// expansion, or a bearing on one face, half of which the walls carry) pulls those walls
/// apart. Measured on brb solid (solid_small_case1_gap0, session 25): the mortar cracks at a
/// contact pressure of about 9 MPa, far below the bearing's crushing at f_c = 40 MPa, and the
/// pressure then stays near 14 MPa. Model: per direction the casing's inner opening grows by
/// w >= 0 (w / 2 at each face), so the faces' penetrations are p(+-) = +-r - g + e - w / 2,
/// and the walls stretch by w over their length L_w (the casing's extent in that direction)
/// following the mortar damage law (tension: f_t, then softening with G_f over L_w). w is
/// internal: the energy's stationarity in w gives the walls' force T(w) = (F+ + F-) / 2
/// (the faces' forces' symmetric part; the antisymmetric part moves the casing as a beam),
/// solved per direction in the link, and the tangent is condensed over w. With a steel tube
/// the tube holds the split (not modelled: the casing is rigid across, as without this).
struct CasingSplitting {
  /// Mortar that the split of the y faces pulls apart: the walls beside the opening along
  /// z, (casing extent along z - opening along z) x tributary length (mm^2); and of z.
  double wall_area_y = 0.0;
  double wall_area_z = 0.0;
  /// L_w of the y faces' split: the casing's extent along y (mm); and along z.
  double wall_length_y = 0.0;
  double wall_length_z = 0.0;

  /// The pair's member for a lateral direction (0: the y faces' split, 1: the z faces').
  double wall_area(std::size_t lateral) const { return lateral == 0 ? wall_area_y : wall_area_z; }
  double wall_length(std::size_t lateral) const {
    return lateral == 0 ? wall_length_y : wall_length_z;
  }

  /// Throws ParameterError naming the key (wall_area_y, ...).
  void validate() const;
};

struct CasingContactParameters {
  Matrix3 axes = Matrix3::Identity(); ///< columns: brace axis, section y, section z (global)
  double gap_y = 0.0;                 ///< clearance on each side along y (mm), >= 0
  double gap_z = 0.0;                 ///< clearance on each side along z (mm), >= 0
  double bearing_area_y = 0.0;        ///< area bearing on a y face (mm^2)
  double bearing_area_z = 0.0;        ///< area bearing on a z face (mm^2)
  /// Mortar depth turning penetration into strain on a y face and on a z face (mm): the
  /// mortar's thickness in that direction (a plate core in a square tube has two).
  double bearing_depth_y = 0.0;
  double bearing_depth_z = 0.0;
  material::MortarParameters mortar;        ///< bearing law
  double layer_stiffness = 0.0;             ///< unbonding layer spring per direction (N/mm), >= 0
  double friction_coefficient = 0.1;        ///< kappa (source: 0.1)
  double tangential_stiffness = 0.0;        ///< stick penalty along the axis (N/mm)
  std::optional<CasingSplitting> splitting; ///< a mortar-only casing's split (none: rigid)

  /// The y or z member of a pair for a lateral direction (0: y, 1: z).
  double gap(std::size_t lateral) const { return lateral == 0 ? gap_y : gap_z; }
  double bearing_area(std::size_t lateral) const {
    return lateral == 0 ? bearing_area_y : bearing_area_z;
  }
  double bearing_depth(std::size_t lateral) const {
    return lateral == 0 ? bearing_depth_y : bearing_depth_z;
  }

  /// Throws ParameterError naming the key (gap_y, gap_z, bearing_area_y, ...).
  void validate() const;
};

/// The core's lateral expansion at a link's station: the core nodes before and after it
/// along the core (at an end station one of them is the station's own core node), whose
/// chord measures the core's axial strain, and the core's extents there.
struct CoreExpansion {
  int previous_node = -1;
  int next_node = -1;
  Vector3 previous_position = Vector3::Zero(); ///< initial positions (mm)
  Vector3 next_position = Vector3::Zero();
  double extent_y = 0.0; ///< h_y: the core's extent along section y at the station (mm)
  double extent_z = 0.0; ///< h_z (mm)
  /// nu_c: lateral over axial strain of the core. 0.5 (plastic incompressibility): the
  /// strains that close a clearance are plastic (a few %), next to which the elastic part
  /// (nu = 0.3 on fy / E = 0.0013-0.0017) is negligible.
  double ratio = 0.5;

  /// Throws ParameterError naming the key (expansion_nodes, extent_y, extent_z, core_expansion).
  void validate() const;
};

/// Sub-element high-mode waves (issue 4, optional): the friction of the buckling waves that
/// are too short for the beam chain. A core yielding in compression inside a clearance g
/// buckles in ever shorter half-waves l, each crest bearing on the casing. Tangent-modulus
/// theory gives the half-wave (Lin, Chang & Wu 2024, Eng. Struct. 118320, found it fits the
/// measured waves of flat cores): l = pi r sqrt(E_t / sigma), r the radius of gyration in
/// the buckling direction, E_t the core's tangent modulus at its compressive stress sigma.
/// A half-wave between opposite crests spans the lateral offset 2 g, so by the moment
/// equilibrium of the half-wave (zero moment at the crests) its shear is 2 P g / l and each
/// crest bears R = 4 P g / l (the crest factor c = 4): per unit length the crests bear
///   q = c g P / l^2,
/// pressing both walls alternately (no net lateral force), and the axial friction they add
/// is kappa q. The beam chain resolves half-waves down to about two of its elements
/// (measured: 13 half-waves on 24 elements, validation/README.md), and its own links bear
/// those; the link adds only the part of q below that resolution:
///   N_w = c g P h max(0, 1 / l^2 - 1 / l_mesh^2),
/// h the tributary length, l_mesh twice the element length, l not below the core's
/// thickness in that direction (a wave shorter than the plate is thick is not a beam wave).
/// sigma and E_t come from the core's steel law driven by the chord strain of the link's
/// neighbour core nodes (CoreExpansion's chord), taken at the start of the step (lagged by
/// one step: N_w has no derivative in the tangent, and dE_t/deps would need the law's
/// second derivative). Tension, or a tangent modulus of E and a long elastic half-wave, give
/// N_w = 0.
struct HighModeWaves {
  material::SteelParameters steel; ///< the core's steel
  double area = 0.0;               ///< core area A (mm^2)
  double gyration_radius = 0.0;    ///< r of the buckling direction (mm)
  double thickness = 0.0;          ///< the core's extent in that direction: the shortest l (mm)
  double gap = 0.0;                ///< clearance per side in that direction (mm)
  double tributary_length = 0.0;   ///< h (mm)
  double resolved_half_wave = 0.0; ///< l_mesh (mm)
  double crest_factor = 4.0;       ///< c

  /// Throws ParameterError naming the key (area, gyration_radius, ...).
  void validate() const;
  /// N_w (N, >= 0) at the core's stress sigma (MPa, compression negative) and tangent E_t.
  double normal_force(double stress, double tangent_modulus) const;
};

class CasingContact final : public Element {
public:
  /// nodes: {core node, casing node}, coincident in the reference configuration up to the
  /// initial imperfection (the relative displacement counts from the initial offset).
  /// `expansion`: the core's expansion at the station (its neighbour nodes join the link's
  /// nodes after these two, once each); none: the core keeps its size.
  CasingContact(std::array<int, 2> nodes, const Vector3& core_position,
                const Vector3& casing_position, const CasingContactParameters& parameters,
                bool skip_open_links = true,
                const std::optional<CoreExpansion>& expansion = std::nullopt,
                const std::optional<HighModeWaves>& waves = std::nullopt);

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override {
    committed_ = trial_;
    path_opening_ = committed_.opening;
  }
  void revert_to_committed() override {
    trial_ = committed_;
    path_opening_ = committed_.opening;
  }
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  void save_state(io::StateWriter& out) const override;
  void load_state(io::StateReader& in) override;
  /// Checkpoints: the committed state, the expansion and the active-set bookkeeping; a reader
  /// follows with revert_to_committed().
  template <class Archive, class Self>
  requires io::state_of<Self, CasingContact>
  friend void state_fields(Archive& archive, Self& link) {
    archive(link.committed_, link.expansion_, link.in_contact_, link.open_evaluations_);
  }
  ElementEnergy energy() const override;

  /// Bearing force on the core per direction (N, along y and z, resisting) and friction (N;
  /// trial state).
  const Vector3& link_force() const { return trial_.link_force; }
  /// Bearing force of each face, +y, -y, +z, -z (N, >= 0; trial state).
  const std::array<double, 4>& face_forces() const { return trial_.face_force; }
  /// Friction's normal force: the sum of the four faces' bearing forces (N; trial state).
  double normal_force() const {
    const std::array<double, 4>& faces = trial_.face_force;
    return faces[0] + faces[1] + faces[2] + faces[3];
  }
  /// N_w of the sub-element waves in this step (N; 0 without HighModeWaves).
  double wave_normal_force() const { return trial_.wave_normal_force; }
  /// The core's half-extent growth e_y, e_z (mm; trial state; 0 without expansion).
  const Eigen::Vector2d& core_expansion() const { return expansion_; }
  /// Path control (Element::mark_path_point): the faces' and the split walls' damage and the
  /// split opening at the last path point.
  void mark_path_point() override;
  /// A face (or a split wall) intact at the last path point (damage below kPathIntactDamage)
  /// is crushed (cracked) now (damage above kPathCrushedDamage): its force went from below its
  /// peak to far past it with no point in between (the mortar's damage grows continuously
  /// from 0 at the peak, MortarUniaxial).
  bool jumped_past_peak() const override;
  static constexpr double kPathIntactDamage = 0.05;
  static constexpr double kPathCrushedDamage = 0.5;

  /// Largest mortar damage over the four faces and the split walls (trial state).
  double max_mortar_damage() const;
  /// Smallest residual strength over the four faces (a fraction of f_c) and the split walls
  /// (of f_t): MortarUniaxial::residual_strength, trial state; 1 while all are intact.
  double min_residual_strength() const;
  /// The casing's split opening w per direction, y and z (mm, >= 0; trial state; 0 without
  /// CasingSplitting).
  const std::array<double, 2>& split_opening() const { return trial_.opening; }
  /// The split walls' force T per direction (N, >= 0; trial state).
  const std::array<double, 2>& split_force() const { return trial_.wall_force; }
  /// The split walls' damage per direction (trial state).
  std::array<double, 2> split_damage() const {
    return {trial_.walls[0].damage, trial_.walls[1].damage};
  }
  /// Whether any face is in contact (trial state).
  bool in_contact() const { return in_contact_; }
  /// Evaluations that took the open-link path (for the benchmark and its tests).
  long open_evaluations() const { return open_evaluations_; }

private:
  struct State {
    std::array<material::MortarState, 4> faces{}; ///< +y, -y, +z, -z
    material::FrictionState friction;
    std::array<double, 4> bearing_strain{}; ///< for the free energy
    // CasingSplitting: per direction the walls' law state, strain w / L_w, the opening w
    // (mm) and the walls' force T (N).
    std::array<material::MortarState, 2> walls{};
    std::array<double, 2> wall_strain{};
    std::array<double, 2> opening{};
    std::array<double, 2> wall_force{};
    /// Local relative displacement of the core from the casing (axis, y, z; mm).
    Vector3 relative = Vector3::Zero();
    /// Resisting force on the core (friction along the axis, bearing + layer along y, z; N).
    Vector3 link_force = Vector3::Zero();
    std::array<double, 4> face_force{}; ///< bearing force of each face (N, >= 0)
    // The trapezoidal stress work (energy().integration_misfit): the faces' signed
    // penetrations (negative when open), with face_force, relative and link_force the
    // kinematics and forces it is summed on, and the work so far (N mm).
    std::array<double, 4> penetration{};
    double stress_work = 0.0;
    // Sub-element waves: the core's steel at the chord strain (its stress and tangent feed
    // the next step's N_w) and this step's N_w.
    material::SteelStateUniaxial wave_steel;
    double wave_stress = 0.0;
    double wave_tangent = 0.0;
    double wave_normal_force = 0.0;

    template <class Archive, class Self>
    requires io::state_of<Self, State>
    friend void state_fields(Archive& archive, Self& state) {
      archive(state.faces, state.friction, state.bearing_strain, state.walls, state.wall_strain,
              state.opening, state.wall_force, state.relative, state.link_force, state.face_force,
              state.penetration, state.stress_work, state.wave_steel, state.wave_stress,
              state.wave_tangent, state.wave_normal_force);
    }
  };

  /// The core's axial strain at the station from the chord of its neighbour nodes, with the
  /// chord's current unit direction and length.
  struct Chord {
    double strain = 0.0;
    Vector3 direction = Vector3::Zero();
    double length = 0.0;
  };

  std::vector<int> nodes_; ///< core, casing, then the expansion's neighbours not yet listed
  Vector3 initial_offset_;
  /// Indices into nodes_ of the chord's two ends (-1: no expansion).
  std::array<int, 2> chord_ends_{-1, -1};
  double chord_initial_length_ = 0.0;
  /// de/deps per direction: -nu_c h / 2 (mm), y and z.
  Eigen::Vector2d expansion_per_strain_ = Eigen::Vector2d::Zero();
  CasingContactParameters parameters_;
  std::optional<HighModeWaves> waves_;
  std::optional<material::SteelUniaxial> wave_steel_; ///< the core's steel law, for waves_
  /// Bearing law of the y faces and of the z faces (their characteristic lengths are the
  /// bearing depths, so that crushing dissipates G_f per unit area of face).
  std::array<material::MortarUniaxial, 2> bearing_;
  /// The split walls' law per direction (characteristic length L_w: G_f per unit area of
  /// the crack through the walls); empty without CasingSplitting.
  std::vector<material::MortarUniaxial> walls_;
  material::PenaltyFriction friction_;
  State committed_;
  State trial_;
  std::array<double, 4> path_damage_{};      ///< faces' damage at the last path point
  std::array<double, 2> path_wall_damage_{}; ///< split walls' damage at the last path point
  /// Split opening per direction at the last path point (or at the committed state, if no
  /// point was marked since): where solve_split starts. A crushed face can give the opening
  /// equation several roots; starting from the path's last opening keeps the solve on the
  /// root the path is on (from the committed opening it jumped to another, and the path
  /// control refused every pseudo-time step: validation/README, casing splitting).
  std::array<double, 2> path_opening_{};
  Eigen::Vector2d expansion_ = Eigen::Vector2d::Zero();
  bool in_contact_ = false;
  bool skip_open_links_ = true;
  Eigen::MatrixXd open_tangent_; ///< 6n x 6n tangent of an open link (layer springs only)
  long open_evaluations_ = 0;

  bool has_expansion() const { return chord_ends_[0] >= 0; }
  /// A face's bearing at penetration p: force F (>= 0), stiffness dF/dp, law state and strain.
  struct FaceBearing {
    double force = 0.0;
    double stiffness = 0.0;
    material::MortarState state;
    double strain = 0.0;
    bool loaded = false; ///< p > 0
  };
  FaceBearing bear(int face, double face_penetration, std::string& failure) const;
  /// The split walls of a direction (1: y, 2: z) at opening w: force T and dT/dw.
  struct WallResponse {
    double force = 0.0;
    double stiffness = 0.0;
    material::MortarState state;
    double strain = 0.0;
  };
  WallResponse stretch_walls(int direction, double opening) const;
  /// Solves T(w) = (F+(w) + F-(w)) / 2 for the direction's opening w in [0, w_open] (faces'
  /// kinematic penetrations p_kin; w_open = 2 max p_kin opens both faces), bracketed Newton
  /// from `opening` (in: the start, path_opening_; out: the root). Returns false (with `failure`)
  /// if a law gives a non-finite value.
  bool solve_split(int direction, const std::array<double, 2>& kinematic,
                   std::array<FaceBearing, 2>& faces, WallResponse& walls, double& opening,
                   std::string& failure) const;
  Chord chord(std::span<const NodeConfiguration> configuration) const;
  /// Penetration of a face (0: +y, 1: -y, 2: +z, 3: -z) at the trial relative displacement and
  /// expansion_ (shared by the open test and the general path so that they decide alike).
  double penetration(int face) const;
  /// The local tangent (axis, y, z) when every face is open, and the force and tangent
  /// scattered onto the core and casing nodes (shared by both paths so that they round alike).
  Matrix3 open_local_tangent() const;
  /// Records the trial faces' penetrations and sums the step's stress work from the committed
  /// state (shared by both paths, so that an open link sums alike).
  void record_stress_work();
  void scatter(const Vector3& local_force, const Matrix3& local_tangent, Eigen::VectorXd& force,
               Eigen::MatrixXd& tangent) const;
  /// Adds the expansion's forces on the chord's ends and its tangent terms, from the bearing
  /// force S and stiffness K per direction (sums over its two faces), dN/d(relative) and
  /// friction's dT/dN.
  void add_expansion_terms(const Chord& core_chord, const Eigen::Vector2d& direction_force,
                           const Eigen::Vector2d& direction_stiffness,
                           const Eigen::RowVector3d& normal_rate, double friction_normal_rate,
                           Eigen::VectorXd& force, Eigen::MatrixXd& tangent) const;
};

} // namespace brb::element
