// The structured hexahedral mesh of a brace (see brace_mesh.hpp for the geometry).
#include "brb/solid/brace_mesh.hpp"

#include "brb/material/parameter_error.hpp"
#include "brb/solid/hex8.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace brb::solid {

namespace {

using model::SectionShape;
using model::SectionSpec;

void check(bool condition, const std::string& field, const std::string& expected) {
  if (!condition)
    throw ParameterError(field, expected);
}

std::string mm(double value) {
  std::ostringstream text;
  text << value << " mm";
  return text.str();
}

/// Grid lines of one axis: each interval [breaks[i], breaks[i + 1]] cut into divisions[i]
/// equal parts.
std::vector<double> axis_lines(const std::vector<double>& breaks,
                               const std::vector<int>& divisions) {
  std::vector<double> lines{breaks.front()};
  for (std::size_t i = 0; i < divisions.size(); ++i)
    for (int d = 1; d <= divisions[i]; ++d)
      lines.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * d / divisions[i]);
  return lines;
}

/// Interval of each cell of an axis cut by `divisions`.
std::vector<int> cell_intervals(const std::vector<int>& divisions) {
  std::vector<int> interval;
  for (std::size_t i = 0; i < divisions.size(); ++i)
    interval.insert(interval.end(), static_cast<std::size_t>(divisions[i]), static_cast<int>(i));
  return interval;
}

/// A masked tensor-product grid of quads in (y, z): cell (iy, iz) has a kind (-1: no cell),
/// grid node (iy, iz) a section-node index (-1: used by no cell).
struct SectionGrid {
  int ny = 0, nz = 0; // cells
  std::vector<int> kind;
  std::vector<int> node;
  int node_count = 0;

  int cell(int iy, int iz) const { return iy + ny * iz; }
  int kind_at(int iy, int iz) const {
    return iy < 0 || iz < 0 || iy >= ny || iz >= nz ? -1 : kind[cell(iy, iz)];
  }
  int grid_node(int iy, int iz) const { return iy + (ny + 1) * iz; }
};

template <class KindOf>
SectionGrid make_grid(const std::vector<int>& y_divisions, const std::vector<int>& z_divisions,
                      KindOf kind_of) {
  SectionGrid grid;
  const std::vector<int> y_interval = cell_intervals(y_divisions);
  const std::vector<int> z_interval = cell_intervals(z_divisions);
  grid.ny = static_cast<int>(y_interval.size());
  grid.nz = static_cast<int>(z_interval.size());
  grid.kind.resize(static_cast<std::size_t>(grid.ny) * grid.nz);
  for (int iz = 0; iz < grid.nz; ++iz)
    for (int iy = 0; iy < grid.ny; ++iy)
      grid.kind[grid.cell(iy, iz)] = kind_of(y_interval[iy], z_interval[iz]);
  grid.node.assign(static_cast<std::size_t>(grid.ny + 1) * (grid.nz + 1), -1);
  for (int iz = 0; iz <= grid.nz; ++iz)
    for (int iy = 0; iy <= grid.ny; ++iy) {
      bool used = false;
      for (int dz = -1; dz <= 0; ++dz)
        for (int dy = -1; dy <= 0; ++dy)
          used = used || grid.kind_at(iy + dy, iz + dz) >= 0;
      if (used)
        grid.node[grid.grid_node(iy, iz)] = grid.node_count++;
    }
  return grid;
}

/// Area and second moments of the cells of a grid of the given kind.
SectionProperties grid_properties(const SectionGrid& grid, const std::vector<double>& y,
                                  const std::vector<double>& z, int kind) {
  SectionProperties p;
  for (int iz = 0; iz < grid.nz; ++iz)
    for (int iy = 0; iy < grid.ny; ++iy) {
      if (grid.kind_at(iy, iz) != kind)
        continue;
      const double dy = y[iy + 1] - y[iy], dz = z[iz + 1] - z[iz];
      p.area += dy * dz;
      p.second_moment_y += dy * (std::pow(z[iz + 1], 3) - std::pow(z[iz], 3)) / 3.0;
      p.second_moment_z += dz * (std::pow(y[iy + 1], 3) - std::pow(y[iy], 3)) / 3.0;
    }
  return p;
}

/// A run of equal elements along the axis with one section scale.
struct Segment {
  double length = 0.0;
  double scale_y = 1.0, scale_z = 1.0;
  bool in_casing = false;
};

struct Station {
  double x = 0.0;
  double scale_y = 1.0, scale_z = 1.0;
  double offset_y = 0.0, offset_z = 0.0;
  bool in_casing = false;
};

/// Scales of the core grid (properties `grid`) that match a zone's area and weak-axis I.
std::pair<double, double> zone_scales(const SectionProperties& grid, const SectionSpec& zone) {
  const SectionProperties target = exact_section_properties(zone);
  if (target.second_moment_y <= target.second_moment_z) {
    const double scale_z =
        std::sqrt((target.second_moment_y / target.area) / (grid.second_moment_y / grid.area));
    return {target.area / (grid.area * scale_z), scale_z};
  }
  const double scale_y =
      std::sqrt((target.second_moment_z / target.area) / (grid.second_moment_z / grid.area));
  return {scale_y, target.area / (grid.area * scale_y)};
}

/// Weak-axis second moment of a rectangular ring (outer half-sizes Y, Z; inner y, z).
double ring_weak_moment(double outer_y, double outer_z, double inner_y, double inner_z) {
  const double about_y =
      (outer_y * std::pow(outer_z, 3) - inner_y * std::pow(inner_z, 3)) * 16.0 / 12.0;
  const double about_z =
      (outer_z * std::pow(outer_y, 3) - inner_z * std::pow(inner_y, 3)) * 16.0 / 12.0;
  return std::min(about_y, about_z);
}

/// Quad face of 4 global nodes, ordered so that its normal points along `outward`.
QuadFace oriented_face(const Eigen::Matrix3Xd& nodes, QuadFace face,
                       const Eigen::Vector3d& outward) {
  const Eigen::Vector3d normal =
      (nodes.col(face[1]) - nodes.col(face[0])).cross(nodes.col(face[3]) - nodes.col(face[0]));
  if (normal.dot(outward) < 0.0)
    std::swap(face[1], face[3]);
  return face;
}

/// Mean edge lengths of a hex along its three natural directions: longest / shortest, and
/// whether the axial (xi) direction is one of the two.
std::pair<double, bool> aspect_ratio(const Eigen::Matrix3Xd& nodes, const HexConnectivity& hex) {
  // edges along xi: (0,1) (3,2) (4,5) (7,6); eta: (0,3) (1,2) (4,7) (5,6); zeta: (0,4) ...
  static constexpr int kEdges[3][4][2] = {{{0, 1}, {3, 2}, {4, 5}, {7, 6}},
                                          {{0, 3}, {1, 2}, {4, 7}, {5, 6}},
                                          {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};
  double mean[3];
  for (int d = 0; d < 3; ++d) {
    mean[d] = 0.0;
    for (const auto& edge : kEdges[d])
      mean[d] += 0.25 * (nodes.col(hex[edge[0]]) - nodes.col(hex[edge[1]])).norm();
  }
  const double longest = std::max({mean[0], mean[1], mean[2]});
  const double shortest = std::min({mean[0], mean[1], mean[2]});
  return {longest / shortest, mean[0] == longest || mean[0] == shortest};
}

void validate_solid_spec(const model::SolidMeshSpec& solid) {
  check(solid.elements_across_core >= 2, "solid/elements_across_core",
        "at least 2 elements across the core's smaller side are needed to represent its "
        "bending (got " +
            std::to_string(solid.elements_across_core) + ")");
  check(solid.elements_through_mortar >= 2, "solid/elements_through_mortar",
        "at least 2 elements through the mortar's thickness are needed (got " +
            std::to_string(solid.elements_through_mortar) + ")");
  check(solid.axial_element_size >= 0.0 && std::isfinite(solid.axial_element_size),
        "solid/axial_element_size", "must be a length > 0 mm (or 0: 3 x the core's element size)");
  check(solid.steel_density > 0.0 && std::isfinite(solid.steel_density), "solid/steel_density",
        "must be > 0 tonne/mm^3 (steel: 7.85e-9)");
  check(solid.mortar_density > 0.0 && std::isfinite(solid.mortar_density), "solid/mortar_density",
        "must be > 0 tonne/mm^3 (mortar: 2.35e-9)");
  check(solid.mass_scaling >= 1.0 && std::isfinite(solid.mass_scaling), "solid/mass_scaling",
        "must be >= 1 (a factor on the densities)");
  check(solid.threads >= 1 && solid.threads <= 1024, "solid/threads",
        "must be a whole number >= 1");
  check(solid.hourglass_min_scale > 0.0 && solid.hourglass_min_scale <= 1.0,
        "solid/hourglass_min_scale", "must be in (0, 1] (default 0.05)");
}

/// The core's section grid (base size, unscaled) and its lines.
struct CoreGrid {
  SectionGrid grid;
  std::vector<double> y, z;
  double element_size = 0.0; ///< across the smaller side (mm)
};

CoreGrid core_grid(const SectionSpec& core, int across) {
  CoreGrid result;
  const auto count = [](double length, double size) {
    return std::max(1, static_cast<int>(std::lround(length / size)));
  };
  std::vector<double> y_breaks, z_breaks;
  std::vector<int> y_div, z_div;
  switch (core.shape) {
  case SectionShape::rectangle:
  case SectionShape::circle: {
    const double side_y = core.shape == SectionShape::circle
                              ? 0.5 * core.diameter * std::sqrt(std::numbers::pi)
                              : core.width;
    const double side_z = core.shape == SectionShape::circle ? side_y : core.depth;
    result.element_size = std::min(side_y, side_z) / across;
    y_breaks = {-0.5 * side_y, 0.5 * side_y};
    z_breaks = {-0.5 * side_z, 0.5 * side_z};
    y_div = {side_y <= side_z ? across : count(side_y, result.element_size)};
    z_div = {side_z < side_y ? across : count(side_z, result.element_size)};
    result.grid = make_grid(y_div, z_div, [](int, int) { return 0; });
    break;
  }
  case SectionShape::cruciform: {
    const double t = core.thickness;
    result.element_size = t / across;
    const double arm_y = 0.5 * (core.width - t), arm_z = 0.5 * (core.depth - t);
    check(std::min(arm_y, arm_z) >= result.element_size, "solid/elements_across_core",
          "a cruciform arm (" + mm(std::min(arm_y, arm_z)) +
              " beyond the centre square) is shorter than one element across the plate (" +
              mm(result.element_size) + "); use more elements across the core");
    y_breaks = {-0.5 * core.width, -0.5 * t, 0.5 * t, 0.5 * core.width};
    z_breaks = {-0.5 * core.depth, -0.5 * t, 0.5 * t, 0.5 * core.depth};
    y_div = {count(arm_y, result.element_size), across, count(arm_y, result.element_size)};
    z_div = {count(arm_z, result.element_size), across, count(arm_z, result.element_size)};
    result.grid =
        make_grid(y_div, z_div, [](int iy, int iz) { return iy == 1 || iz == 1 ? 0 : -1; });
    break;
  }
  default:
    throw ParameterError("core/section/shape", "the solid mesh takes a rectangle, circle or "
                                               "cruciform core");
  }
  result.y = axis_lines(y_breaks, y_div);
  result.z = axis_lines(z_breaks, z_div);
  return result;
}

/// Half-sizes of the casing outlines: the tube's inner and outer (equal without a tube part).
struct CasingOutline {
  double inner_y = 0.0, inner_z = 0.0, outer_y = 0.0, outer_z = 0.0;
  bool tube_part = false;
};

CasingOutline casing_outline(const model::CasingSpec& casing, const model::SolidMeshSpec& solid) {
  CasingOutline outline;
  const SectionSpec& tube = casing.tube;
  if (tube.shape == SectionShape::rectangular_tube) {
    outline.outer_y = 0.5 * tube.width;
    outline.outer_z = 0.5 * tube.depth;
  } else if (tube.shape == SectionShape::circular_tube) {
    // with a wall: the square ring of equal wall and area; wall 0: the equal-area square
    const double side = casing.steel_tube && tube.wall > 0.0
                            ? std::numbers::pi * (tube.diameter - tube.wall) / 4.0 + tube.wall
                            : 0.5 * tube.diameter * std::sqrt(std::numbers::pi);
    outline.outer_y = outline.outer_z = 0.5 * side;
  } else {
    throw ParameterError("casing/tube/shape", "must be rectangular_tube or circular_tube");
  }
  const double wall = casing.steel_tube ? tube.wall : 0.0;
  outline.inner_y = outline.outer_y - wall;
  outline.inner_z = outline.outer_z - wall;
  check(outline.inner_y > 0.0 && outline.inner_z > 0.0, "casing/tube",
        "the tube's wall leaves no inside");
  if (!casing.steel_tube || wall == 0.0)
    return outline;
  if (solid.tube == model::SolidTube::elements) {
    outline.tube_part = true;
    return outline;
  }
  // homogenised: widen the mortar by s on every side until E_c dI = E_s I_tube (weak axis)
  const double ratio = casing.tube_steel.youngs_modulus / casing.mortar.youngs_modulus;
  const double target =
      ratio * ring_weak_moment(outline.outer_y, outline.outer_z, outline.inner_y, outline.inner_z);
  const auto added = [&](double s) {
    return ring_weak_moment(outline.inner_y + s, outline.inner_z + s, outline.inner_y,
                            outline.inner_z);
  };
  double low = 0.0, high = wall;
  while (added(high) < target)
    high *= 2.0;
  for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (added(mid) < target ? low : high) = mid;
  }
  outline.outer_y = outline.inner_y + high;
  outline.outer_z = outline.inner_z + high;
  outline.inner_y = outline.outer_y;
  outline.inner_z = outline.outer_z;
  return outline;
}

/// The axial segments from the start (or mid-length in a half model) to the driven end.
std::vector<Segment> segments(const model::BraceSpec& brace, const SectionProperties& grid,
                              bool half) {
  const double overlap = brace.casing && brace.transition ? brace.casing->overlap : 0.0;
  const bool cased = brace.casing.has_value();
  std::vector<Segment> outward; // from mid-length to the end
  outward.push_back({0.5 * brace.yielding_length, 1.0, 1.0, cased});
  if (brace.transition) {
    const auto [sy, sz] = zone_scales(grid, brace.transition->section);
    if (overlap > 0.0)
      outward.push_back({overlap, sy, sz, true});
    if (brace.transition->length - overlap > 0.0)
      outward.push_back({brace.transition->length - overlap, sy, sz, false});
  }
  if (brace.connection) {
    const auto [sy, sz] = zone_scales(grid, brace.connection->section);
    outward.push_back({brace.connection->length, sy, sz, false});
  }
  std::vector<Segment> all;
  if (!half)
    all.assign(outward.rbegin(), outward.rend());
  all.insert(all.end(), outward.begin(), outward.end());
  return all;
}

} // namespace

SectionProperties exact_section_properties(const SectionSpec& s) {
  SectionProperties p;
  const auto rectangle = [](double w, double d) {
    return SectionProperties{w * d, w * d * d * d / 12.0, d * w * w * w / 12.0};
  };
  switch (s.shape) {
  case SectionShape::rectangle:
    return rectangle(s.width, s.depth);
  case SectionShape::circle:
    p.area = std::numbers::pi * s.diameter * s.diameter / 4.0;
    p.second_moment_y = p.second_moment_z = std::numbers::pi * std::pow(s.diameter, 4) / 64.0;
    return p;
  case SectionShape::cruciform: {
    const double t = s.thickness;
    p.area = s.width * t + s.depth * t - t * t;
    p.second_moment_y = (s.width * t * t * t + t * std::pow(s.depth, 3) - std::pow(t, 4)) / 12.0;
    p.second_moment_z = (t * std::pow(s.width, 3) + s.depth * t * t * t - std::pow(t, 4)) / 12.0;
    return p;
  }
  case SectionShape::rectangular_tube: {
    const SectionProperties outer = rectangle(s.width, s.depth);
    const SectionProperties inner = rectangle(s.width - 2.0 * s.wall, s.depth - 2.0 * s.wall);
    return {outer.area - inner.area, outer.second_moment_y - inner.second_moment_y,
            outer.second_moment_z - inner.second_moment_z};
  }
  case SectionShape::circular_tube: {
    const double inner = s.diameter - 2.0 * s.wall;
    p.area = std::numbers::pi * (s.diameter * s.diameter - inner * inner) / 4.0;
    p.second_moment_y = p.second_moment_z =
        std::numbers::pi * (std::pow(s.diameter, 4) - std::pow(inner, 4)) / 64.0;
    return p;
  }
  }
  return p;
}

BraceMesh mesh_brace(const model::BraceSpec& brace, const model::SolidMeshSpec& solid) {
  validate_solid_spec(solid);
  check(brace.yielding_length > 0.0, "core/yielding_length", "must be > 0 mm");
  const double total = brace.total_length();
  const model::ImperfectionSpec& bow = brace.imperfection;
  check(bow.amplitude == 0.0 || bow.shape == model::ImperfectionShape::bow, "imperfection/shape",
        "the solid mesh applies a bow only (a buckling-mode shape needs the reduced model's "
        "eigen-analysis)");
  if (brace.casing) {
    check(brace.casing->gap_y >= 0.0 && brace.casing->gap_z >= 0.0, "casing/gap",
          "the gap must be >= 0 mm per side: a negative gap makes the casing's opening overlap "
          "the core");
    check(!solid.half_length || brace.casing->stopper_position == 0.5, "casing/stopper/position",
          "the half-length model has its stopper at the symmetry plane: the position must be 0.5");
  }

  BraceMesh mesh;
  mesh.half_length = solid.half_length;
  const CoreGrid core = core_grid(brace.core_section, solid.elements_across_core);
  const SectionProperties core_properties = grid_properties(core.grid, core.y, core.z, 0);
  mesh.core_area = core_properties.area;
  const double axial_size =
      solid.axial_element_size > 0.0 ? solid.axial_element_size : 3.0 * core.element_size;

  // stations
  const std::vector<Segment> runs = segments(brace, core_properties, solid.half_length);
  std::vector<Station> stations;
  double x = solid.half_length ? 0.5 * total : 0.0;
  mesh.x_start = x;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Segment& run = runs[r];
    const int count = std::max(1, static_cast<int>(std::ceil(run.length / axial_size - 1e-9)));
    for (int e = (r == 0 ? 0 : 1); e <= count; ++e) {
      Station station;
      station.x = x + run.length * e / count;
      station.scale_y = run.scale_y;
      station.scale_z = run.scale_z;
      station.in_casing = run.in_casing;
      if (e == 0 || e == count) { // a zone boundary: the smaller section, the casing's span
        const Segment& other = e == 0 ? run : (r + 1 < runs.size() ? runs[r + 1] : run);
        if (other.scale_y * other.scale_z < run.scale_y * run.scale_z) {
          station.scale_y = other.scale_y;
          station.scale_z = other.scale_z;
        }
        station.in_casing = run.in_casing || other.in_casing;
      }
      stations.push_back(station);
    }
    x += run.length;
  }
  mesh.x_end = stations.back().x;
  for (Station& station : stations) {
    const double offset = bow.amplitude * std::sin(std::numbers::pi * station.x / total);
    (bow.direction == model::BendingAxis::y ? station.offset_y : station.offset_z) = offset;
    mesh.stations.push_back(station.x);
  }

  // core nodes: station-major, section node fastest
  const SectionGrid& cg = core.grid;
  const int core_section_nodes = cg.node_count;
  const int station_count = static_cast<int>(stations.size());
  const int core_nodes = core_section_nodes * station_count;
  std::vector<int> casing_stations;
  for (int k = 0; k < station_count; ++k)
    if (brace.casing && stations[k].in_casing)
      casing_stations.push_back(k);

  // casing section
  SectionGrid casing_grid;
  std::vector<int> y_div, z_div;
  CasingOutline outline;
  double core_half_y = 0.5 * (core.y.back() - core.y.front());
  double core_half_z = 0.5 * (core.z.back() - core.z.front());
  if (!casing_stations.empty()) {
    const model::CasingSpec& casing = *brace.casing;
    outline = casing_outline(casing, solid);
    const int m = solid.elements_through_mortar;
    const auto across = [&](double length) {
      return std::max(1, static_cast<int>(std::lround(length / core.element_size)));
    };
    const int open_y = across(2.0 * core_half_y + 2.0 * casing.gap_y);
    const int open_z = across(2.0 * core_half_z + 2.0 * casing.gap_z);
    if (outline.tube_part) {
      y_div = {1, m, open_y, m, 1};
      z_div = {1, m, open_z, m, 1};
      casing_grid = make_grid(y_div, z_div, [](int iy, int iz) {
        if (iy == 0 || iy == 4 || iz == 0 || iz == 4)
          return 2; // tube
        return iy == 2 && iz == 2 ? -1 : 1;
      });
    } else {
      y_div = {m, open_y, m};
      z_div = {m, open_z, m};
      casing_grid =
          make_grid(y_div, z_div, [](int iy, int iz) { return iy == 1 && iz == 1 ? -1 : 1; });
    }
  }
  const int casing_section_nodes = casing_grid.node_count;
  const int total_nodes =
      core_nodes + casing_section_nodes * static_cast<int>(casing_stations.size());
  mesh.nodes.resize(3, total_nodes);

  for (int k = 0; k < station_count; ++k) {
    const Station& s = stations[k];
    for (int iz = 0; iz <= cg.nz; ++iz)
      for (int iy = 0; iy <= cg.ny; ++iy) {
        const int local = cg.node[cg.grid_node(iy, iz)];
        if (local >= 0)
          mesh.nodes.col(k * core_section_nodes + local) = Eigen::Vector3d(
              s.x, s.scale_y * core.y[iy] + s.offset_y, s.scale_z * core.z[iz] + s.offset_z);
      }
  }
  // casing lines per station: the opening follows the core's scaled box and its bow
  const auto casing_lines = [&](const Station& s) {
    const model::CasingSpec& casing = *brace.casing;
    const double open_y = s.scale_y * core_half_y + casing.gap_y;
    const double open_z = s.scale_z * core_half_z + casing.gap_z;
    check(outline.inner_y - open_y - std::abs(s.offset_y) > 0.0 &&
              outline.inner_z - open_z - std::abs(s.offset_z) > 0.0,
          "casing/tube",
          "no room for mortar at x = " + mm(s.x) +
              ": the opening (core + gaps, bow included) "
              "reaches the tube's inside");
    std::vector<double> yb, zb;
    if (outline.tube_part) {
      yb = {-outline.outer_y,    -outline.inner_y, s.offset_y - open_y,
            s.offset_y + open_y, outline.inner_y,  outline.outer_y};
      zb = {-outline.outer_z,    -outline.inner_z, s.offset_z - open_z,
            s.offset_z + open_z, outline.inner_z,  outline.outer_z};
    } else {
      yb = {-outline.inner_y, s.offset_y - open_y, s.offset_y + open_y, outline.inner_y};
      zb = {-outline.inner_z, s.offset_z - open_z, s.offset_z + open_z, outline.inner_z};
    }
    return std::pair{axis_lines(yb, y_div), axis_lines(zb, z_div)};
  };
  for (std::size_t c = 0; c < casing_stations.size(); ++c) {
    const Station& s = stations[casing_stations[c]];
    const auto [yl, zl] = casing_lines(s);
    for (int iz = 0; iz <= casing_grid.nz; ++iz)
      for (int iy = 0; iy <= casing_grid.ny; ++iy) {
        const int local = casing_grid.node[casing_grid.grid_node(iy, iz)];
        if (local >= 0)
          mesh.nodes.col(core_nodes + static_cast<int>(c) * casing_section_nodes + local) =
              Eigen::Vector3d(s.x, yl[iy], zl[iz]);
      }
  }

  // parts: a part takes the cells of one kind of a grid over a run of stations
  const auto build_part = [&](BracePartMesh& part, const std::string& name, const SectionGrid& grid,
                              int kind, int first_global, const std::vector<int>& part_stations) {
    part.name = name;
    std::vector<int> section_local(static_cast<std::size_t>(grid.node_count), -1);
    int section_count = 0;
    for (int iz = 0; iz <= grid.nz; ++iz)
      for (int iy = 0; iy <= grid.ny; ++iy) {
        bool used = false;
        for (int dz = -1; dz <= 0; ++dz)
          for (int dy = -1; dy <= 0; ++dy)
            used = used || grid.kind_at(iy + dy, iz + dz) == kind;
        if (used)
          section_local[grid.node[grid.grid_node(iy, iz)]] = section_count++;
      }
    const int stations_in_part = static_cast<int>(part_stations.size());
    part.global_nodes.assign(static_cast<std::size_t>(section_count) * stations_in_part, -1);
    for (int k = 0; k < stations_in_part; ++k)
      for (int n = 0; n < grid.node_count; ++n)
        if (section_local[n] >= 0)
          part.global_nodes[k * section_count + section_local[n]] =
              first_global + k * grid.node_count + n;
    part.mesh.nodes.resize(3, static_cast<Eigen::Index>(part.global_nodes.size()));
    for (std::size_t n = 0; n < part.global_nodes.size(); ++n)
      part.mesh.nodes.col(static_cast<Eigen::Index>(n)) = mesh.nodes.col(part.global_nodes[n]);
    for (int k = 0; k + 1 < stations_in_part; ++k)
      for (int iz = 0; iz < grid.nz; ++iz)
        for (int iy = 0; iy < grid.ny; ++iy) {
          if (grid.kind_at(iy, iz) != kind)
            continue;
          HexConnectivity hex;
          for (int a = 0; a < 8; ++a) {
            const auto& corner = kNaturalCoordinates[a];
            const int station = k + (corner[0] + 1) / 2;
            const int node =
                grid.node[grid.grid_node(iy + (corner[1] + 1) / 2, iz + (corner[2] + 1) / 2)];
            hex[a] = station * section_count + section_local[node];
          }
          part.mesh.elements.push_back(hex);
        }
  };
  std::vector<int> all_stations(static_cast<std::size_t>(station_count));
  for (int k = 0; k < station_count; ++k)
    all_stations[k] = k;
  build_part(mesh.core, "core", cg, 0, 0, all_stations);
  if (!casing_stations.empty()) {
    build_part(mesh.mortar, "mortar", casing_grid, 1, core_nodes, casing_stations);
    if (outline.tube_part)
      build_part(mesh.tube, "tube", casing_grid, 2, core_nodes, casing_stations);
  }

  // element shapes: positive Jacobian (hex8_reference throws) and aspect ratio <= 20
  for (const BracePartMesh* part : {&mesh.core, &mesh.mortar, &mesh.tube}) {
    for (const HexConnectivity& hex : part->mesh.elements) {
      const auto [ratio, axial] = aspect_ratio(part->mesh.nodes, hex);
      if (ratio <= kMaxElementAspectRatio)
        continue;
      const std::string field = axial                ? "solid/axial_element_size"
                                : part == &mesh.core ? "solid/elements_across_core"
                                                     : "solid/elements_through_mortar";
      std::ostringstream text;
      text << "an element of the " << part->name << " has aspect ratio " << ratio
           << " (longest / shortest edge) over " << kMaxElementAspectRatio
           << " (axial element size " << axial_size << " mm, core element across "
           << core.element_size << " mm); choose sizes closer to each other";
      throw ParameterError(field, text.str());
    }
  }

  // node sets
  const auto core_station_nodes = [&](int k) {
    std::vector<int> nodes(static_cast<std::size_t>(core_section_nodes));
    for (int n = 0; n < core_section_nodes; ++n)
      nodes[n] = k * core_section_nodes + n;
    return nodes;
  };
  const auto casing_station_nodes = [&](std::size_t c) {
    std::vector<int> nodes(static_cast<std::size_t>(casing_section_nodes));
    for (int n = 0; n < casing_section_nodes; ++n)
      nodes[n] = core_nodes + static_cast<int>(c) * casing_section_nodes + n;
    return nodes;
  };
  mesh.loaded_end = core_station_nodes(station_count - 1);
  if (solid.half_length) {
    mesh.symmetry_plane = core_station_nodes(0);
    if (!casing_stations.empty()) {
      const std::vector<int> casing_nodes = casing_station_nodes(0);
      mesh.symmetry_plane.insert(mesh.symmetry_plane.end(), casing_nodes.begin(),
                                 casing_nodes.end());
    }
  } else {
    mesh.fixed_end = core_station_nodes(0);
  }
  if (!casing_stations.empty()) {
    mesh.casing_start = stations[casing_stations.front()].x;
    mesh.casing_end = stations[casing_stations.back()].x;
    if (!solid.half_length) {
      const double target = mesh.casing_start +
                            brace.casing->stopper_position * (mesh.casing_end - mesh.casing_start);
      std::size_t nearest = 0;
      for (std::size_t c = 1; c < casing_stations.size(); ++c)
        if (std::abs(stations[casing_stations[c]].x - target) <
            std::abs(stations[casing_stations[nearest]].x - target))
          nearest = c;
      mesh.stopper_core = core_station_nodes(casing_stations[nearest]);
      mesh.stopper_casing = casing_station_nodes(nearest);
      mesh.stopper_stiffness = brace.casing->stopper_stiffness_ratio * brace.steel.youngs_modulus *
                               mesh.core_area / brace.yielding_length;
    }
  } else {
    mesh.casing_start = mesh.casing_end = mesh.x_start;
  }

  // contact faces over the casing's length
  for (std::size_t c = 0; c + 1 < casing_stations.size(); ++c) {
    const int k = casing_stations[c];
    // core: faces on the bounding box (a neighbour outside the grid)
    for (int iz = 0; iz < cg.nz; ++iz)
      for (int iy = 0; iy < cg.ny; ++iy) {
        if (cg.kind_at(iy, iz) != 0)
          continue;
        const auto node = [&](int gy, int gz, int station) {
          return station * core_section_nodes + cg.node[cg.grid_node(gy, gz)];
        };
        const struct {
          bool on;
          int y0, z0, y1, z1;
          Eigen::Vector3d outward;
        } sides[4] = {{iy == cg.ny - 1, iy + 1, iz, iy + 1, iz + 1, Eigen::Vector3d::UnitY()},
                      {iy == 0, iy, iz, iy, iz + 1, -Eigen::Vector3d::UnitY()},
                      {iz == cg.nz - 1, iy, iz + 1, iy + 1, iz + 1, Eigen::Vector3d::UnitZ()},
                      {iz == 0, iy, iz, iy + 1, iz, -Eigen::Vector3d::UnitZ()}};
        for (const auto& side : sides)
          if (side.on)
            mesh.core_faces.push_back(
                oriented_face(mesh.nodes,
                              {node(side.y0, side.z0, k), node(side.y1, side.z1, k),
                               node(side.y1, side.z1, k + 1), node(side.y0, side.z0, k + 1)},
                              side.outward));
      }
    // casing: mortar faces whose neighbour is the opening
    const auto node = [&](int gy, int gz, std::size_t station) {
      return core_nodes + static_cast<int>(station) * casing_section_nodes +
             casing_grid.node[casing_grid.grid_node(gy, gz)];
    };
    for (int iz = 0; iz < casing_grid.nz; ++iz)
      for (int iy = 0; iy < casing_grid.ny; ++iy) {
        if (casing_grid.kind_at(iy, iz) != 1)
          continue;
        const auto hole = [&](int jy, int jz) {
          return jy >= 0 && jz >= 0 && jy < casing_grid.ny && jz < casing_grid.nz &&
                 casing_grid.kind_at(jy, jz) == -1;
        };
        const struct {
          bool on;
          int y0, z0, y1, z1;
          Eigen::Vector3d outward;
        } sides[4] = {{hole(iy + 1, iz), iy + 1, iz, iy + 1, iz + 1, Eigen::Vector3d::UnitY()},
                      {hole(iy - 1, iz), iy, iz, iy, iz + 1, -Eigen::Vector3d::UnitY()},
                      {hole(iy, iz + 1), iy, iz + 1, iy + 1, iz + 1, Eigen::Vector3d::UnitZ()},
                      {hole(iy, iz - 1), iy, iz, iy + 1, iz, -Eigen::Vector3d::UnitZ()}};
        for (const auto& side : sides)
          if (side.on)
            mesh.casing_faces.push_back(
                oriented_face(mesh.nodes,
                              {node(side.y0, side.z0, c), node(side.y1, side.z1, c),
                               node(side.y1, side.z1, c + 1), node(side.y0, side.z0, c + 1)},
                              side.outward));
      }
  }
  return mesh;
}

void validate_brace_mesh(const model::BraceSpec& brace, const model::SolidMeshSpec& solid) {
  (void)mesh_brace(brace, solid);
}

} // namespace brb::solid
