// FrameSpec: what a frame model file says (README "Frame model files"), as plain values,
// independent of how it is read and before anything is built. Units: N, mm, s, MPa, tonne.
//
// Node ids are the user's ids everywhere in the spec (supports, constraints, masses,
// elements, gravity loads, stories, floors); the builder maps them to model indices. The
// reader has checked every reference, range and length, so a builder may rely on them.
#pragma once

#include "brb/element/beam_integration.hpp"
#include "brb/element/elastic_beam_column.hpp"
#include "brb/element/element.hpp"
#include "brb/element/uniaxial_law.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_parameters.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/model/model.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace brb::model {

/// Standard gravity (mm/s^2) for `"from_masses": true` gravity loads: W = m g with m in tonne
/// gives N (1 tonne x 1 mm/s^2 = 1 N).
inline constexpr double kStandardGravity = 9806.65;

/// Planar models lie in the global X-Z plane; their DOF map keeps ux, uz, ry of every node.
enum class FrameDimension { planar = 2, spatial = 3 };

struct FrameNodeSpec {
  int id = 0;
  element::Vector3 coordinates = element::Vector3::Zero(); ///< mm
};

struct SupportSpec {
  int node = 0;
  std::array<bool, kDofPerNode> fixed{}; ///< indexed by Dof (ux, uy, uz, rx, ry, rz)
};

struct NodalMassSpec {
  int node = 0;
  NodalMass mass{}; ///< tonne (ux, uy, uz), tonne mm^2 (rx, ry, rz)
};

/// Elastic section properties of an `elastic_beam` (the file's "sections" entries): the
/// element's own property set (E, G, A, Iy, Iz, J).
using ElasticSectionSpec = element::ElasticBeamProperties;

/// A linear elastic uniaxial law: sigma = E eps (or force = E x deformation in a spring).
using ElasticLaw = element::ElasticLawParameters;

/// A uniaxial law of a truss or spring (the file's "materials" entries): elastic, the steel
/// law or the mortar law with the parameters of `brb material --params` files, without lc
/// (the characteristic length comes from the element that uses the law).
using UniaxialLawSpec = element::UniaxialLawParameters;

/// A named material of the file and its law.
struct NamedLaw {
  std::string name;
  UniaxialLawSpec law;
};

using element::BeamGeometry;

/// `elastic_beam`: an elastic beam-column. Orientation: a vector in the local x-z plane
/// (OpenSees vecxz); absent: global Z for a member not along Z, global X for one along Z.
struct ElasticBeamSpec {
  std::string section_name;
  ElasticSectionSpec section;
  BeamGeometry geometry = BeamGeometry::linear;
  std::optional<element::Vector3> orientation;
};

/// `truss`: a co-rotational truss of area A with a uniaxial law.
struct TrussSpec {
  double area = 0.0; ///< mm^2
  NamedLaw material;
};

/// `spring`: a zero-length spring with one uniaxial law per listed DOF (global axes), read as
/// force-deformation (N, mm) or moment-rotation (N mm, rad).
struct SpringSpec {
  std::array<std::optional<NamedLaw>, kDofPerNode> dofs; ///< indexed by Dof
};

/// `fiber_beam`: a co-rotational fiber beam of the brace-file section and steel, cut into
/// `subdivisions` elements.
struct FiberBeamSpec {
  SectionSpec section;
  material::SteelParameters steel;
  int subdivisions = 1;
  element::IntegrationRule integration_rule = element::IntegrationRule::gauss_lobatto;
  int integration_points = 3;
  std::optional<element::Vector3> orientation;
};

/// Fidelity of a brace in a frame: `automatic` ("auto" in the file) is resolved by the
/// builder's rule into truss or full.
enum class BraceFidelity { truss, full, automatic };

/// `brb`: a buckling-restrained brace between two work points. Its fidelity and mode are the
/// frame element's (the brace file's own "element" block is not used in frames).
struct BraceElementSpec {
  BraceSpec brace;
  BraceFidelity fidelity = BraceFidelity::automatic;
  ElementMode mode = ElementMode::condensed;
  /// The brace file as resolved against the frame file's folder; empty for an inline brace.
  std::filesystem::path source_file;
  /// A vector in the brace's local x-z plane (section z); absent: the BRB element's default.
  std::optional<element::Vector3> orientation;
};

using FrameElementKind =
    std::variant<ElasticBeamSpec, TrussSpec, SpringSpec, FiberBeamSpec, BraceElementSpec>;

struct FrameElementSpec {
  int id = 0;
  std::array<int, 2> nodes{}; ///< node ids i, j
  FrameElementKind kind;
};

struct NodalLoadSpec {
  int node = 0;
  std::array<double, kDofPerNode> force{}; ///< N (ux, uy, uz), N mm (rx, ry, rz)
};

/// Static loads applied in `steps` load-control steps before the dynamic run, then held.
struct GravitySpec {
  bool from_masses = false; ///< adds m g along -Z for each nodal translational mass (uz's)
  std::vector<NodalLoadSpec> loads;
  int steps = 10;
};

/// C = a0 M + a1 K0 with the ratios at the two modes' frequencies (K0: initial stiffness).
struct RayleighDampingSpec {
  std::array<int, 2> modes{1, 3};         ///< mode numbers (1 = first)
  std::array<double, 2> ratios{0.0, 0.0}; ///< damping ratios at those modes
  bool exclude_braces = true;             ///< the brb elements stay out of K0
};

/// The same ratio on the first `modes` modes.
struct ModalDampingSpec {
  double ratio = 0.0;
  int modes = 1;
};

using DampingSpecVariant = std::variant<RayleighDampingSpec, ModalDampingSpec>;

enum class Integrator { newmark, hht, explicit_central_difference };

struct AnalysisSpec {
  Integrator integrator = Integrator::newmark;
  std::optional<double> dt;    ///< s; absent: the record's dt
  double alpha = 0.0;          ///< HHT alpha in [-1/3, 0] (0 unless hht)
  double free_vibration = 0.0; ///< s after the record
  double drift_limit = 0.10;   ///< collapse: a story drift ratio above it stops the run
};

/// Ground-motion components: the two horizontal axes and the vertical.
enum class GroundDirection { x, y, z };

struct StorySpec {
  std::string name;
  int bottom = 0; ///< node id
  int top = 0;    ///< node id, above bottom
};

struct FloorSpec {
  std::string name;
  int node = 0;
};

struct RecorderSpec {
  bool drifts = false;
  bool floor_accelerations = false;
  bool base_shear = false;
  bool energy = false;
  bool all_braces = false;    ///< "braces": "all"
  std::vector<int> brace_ids; ///< "braces": [ids] (empty with "none" or "all")
};

struct FrameSpec {
  std::string title;
  FrameDimension dimension = FrameDimension::spatial;
  std::vector<FrameNodeSpec> nodes;
  std::vector<SupportSpec> supports;
  /// Constraints between node ids (not indices).
  std::vector<EqualDofConstraint> equal_dofs;
  std::vector<RigidDiaphragmConstraint> rigid_diaphragms;
  std::vector<NodalMassSpec> masses;
  std::map<std::string, ElasticSectionSpec> sections;
  std::map<std::string, UniaxialLawSpec> materials;
  std::vector<FrameElementSpec> elements;
  std::optional<GravitySpec> gravity;
  std::optional<DampingSpecVariant> damping; ///< absent: no viscous damping
  AnalysisSpec analysis;
  std::vector<GroundDirection> ground_directions{GroundDirection::x};
  std::vector<StorySpec> stories;
  std::vector<FloorSpec> floors;
  RecorderSpec recorders;

  /// The node with this id (the reader guarantees that referenced ids exist); throws
  /// std::out_of_range otherwise.
  const FrameNodeSpec& node(int id) const;
  /// Distance between an element's two nodes (mm).
  double element_length(const FrameElementSpec& element) const;
  /// Gives every brace (`brb` element) `count` core elements instead of its brace file's (a
  /// mesh study of the frame's full braces).
  void set_brace_core_elements(int count);
};

} // namespace brb::model
