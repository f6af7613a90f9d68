#include "brb/section/fiber_layout.hpp"

#include "brb/material/parameter_error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace brb::section {
namespace {

void require_positive(double value, const char* field) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw ParameterError(field, std::string("must be > 0 mm (got ") + std::to_string(value) + ")");
  }
}

void require_count(int value, const char* field) {
  if (value < 1) {
    throw ParameterError(field, "must be >= 1 (got " + std::to_string(value) + ")");
  }
}

/// Cells of the rectangle [y0, y1] x [z0, z1], ny x nz.
void append_rectangle(FiberLayout& layout, double y0, double y1, double z0, double z1, int ny,
                      int nz) {
  const double dy = (y1 - y0) / ny;
  const double dz = (z1 - z0) / nz;
  for (int i = 0; i < ny; ++i) {
    for (int j = 0; j < nz; ++j) {
      layout.append(y0 + (i + 0.5) * dy, z0 + (j + 0.5) * dz, dy * dz);
    }
  }
}

/// Ring sectors between radii r_in and r_out. Each fiber sits at the radius that keeps
/// the sector's polar moment, sqrt((r_out^2 + r_in^2) / 2), so the mesh reproduces
/// I = pi (D^4 - d^4) / 64 for any number of sectors >= 3 (sum cos^2 = n/2).
void append_annulus(FiberLayout& layout, double r_in, double r_out, int rings, int sectors) {
  const double ring_width = (r_out - r_in) / rings;
  const double angle = 2.0 * std::numbers::pi / sectors;
  for (int ring = 0; ring < rings; ++ring) {
    const double inner = r_in + ring * ring_width;
    const double outer = inner + ring_width;
    const double radius = std::sqrt(0.5 * (outer * outer + inner * inner));
    const double area = 0.5 * angle * (outer * outer - inner * inner);
    for (int sector = 0; sector < sectors; ++sector) {
      const double theta = (sector + 0.5) * angle;
      layout.append(radius * std::cos(theta), radius * std::sin(theta), area);
    }
  }
}

} // namespace

double FiberLayout::total_area() const {
  double sum = 0.0;
  for (const double a : area)
    sum += a;
  return sum;
}

double FiberLayout::second_moment_y() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < size(); ++i)
    sum += area[i] * z[i] * z[i];
  return sum;
}

double FiberLayout::second_moment_z() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < size(); ++i)
    sum += area[i] * y[i] * y[i];
  return sum;
}

void FiberLayout::append(double fiber_y, double fiber_z, double fiber_area) {
  y.push_back(fiber_y);
  z.push_back(fiber_z);
  area.push_back(fiber_area);
}

double rectangle_torsion_constant(double width, double depth) {
  const double long_side = std::max(width, depth);
  const double short_side = std::min(width, depth);
  double series = 0.0;
  for (int n = 1; n < 200; n += 2) {
    series += std::tanh(n * std::numbers::pi * long_side / (2.0 * short_side)) / std::pow(n, 5);
  }
  const double pi5 = std::pow(std::numbers::pi, 5);
  return long_side * std::pow(short_side, 3) *
         (1.0 / 3.0 - 64.0 / pi5 * short_side / long_side * series);
}

FiberLayout mesh_rectangle(double width, double depth, int ny, int nz) {
  require_positive(width, "width");
  require_positive(depth, "depth");
  require_count(ny, "fibers_y");
  require_count(nz, "fibers_z");
  FiberLayout layout;
  append_rectangle(layout, -0.5 * width, 0.5 * width, -0.5 * depth, 0.5 * depth, ny, nz);
  layout.torsion_constant = rectangle_torsion_constant(width, depth);
  return layout;
}

FiberLayout mesh_circle(double diameter, int rings, int sectors) {
  require_positive(diameter, "diameter");
  require_count(rings, "rings");
  if (sectors < 3)
    throw ParameterError("sectors", "must be >= 3");
  FiberLayout layout;
  append_annulus(layout, 0.0, 0.5 * diameter, rings, sectors);
  layout.torsion_constant = std::numbers::pi * std::pow(diameter, 4) / 32.0;
  return layout;
}

FiberLayout mesh_circular_tube(double outer_diameter, double wall, int rings, int sectors) {
  require_positive(outer_diameter, "diameter");
  require_positive(wall, "wall");
  if (2.0 * wall >= outer_diameter) {
    throw ParameterError("wall", "must be < half the outer diameter");
  }
  require_count(rings, "rings");
  if (sectors < 3)
    throw ParameterError("sectors", "must be >= 3");
  FiberLayout layout;
  const double inner_diameter = outer_diameter - 2.0 * wall;
  append_annulus(layout, 0.5 * inner_diameter, 0.5 * outer_diameter, rings, sectors);
  layout.torsion_constant =
      std::numbers::pi * (std::pow(outer_diameter, 4) - std::pow(inner_diameter, 4)) / 32.0;
  return layout;
}

FiberLayout mesh_rectangular_tube(double width, double depth, double wall, int along, int through) {
  require_positive(width, "width");
  require_positive(depth, "depth");
  require_positive(wall, "wall");
  if (2.0 * wall >= std::min(width, depth)) {
    throw ParameterError("wall", "must be < half the smaller outer dimension");
  }
  require_count(along, "fibers_along");
  require_count(through, "fibers_through");
  FiberLayout layout;
  const double y_out = 0.5 * width, z_out = 0.5 * depth;
  const double y_in = y_out - wall, z_in = z_out - wall;
  // flanges (full width, top and bottom), then webs between them
  append_rectangle(layout, -y_out, y_out, z_in, z_out, along, through);
  append_rectangle(layout, -y_out, y_out, -z_out, -z_in, along, through);
  append_rectangle(layout, y_in, y_out, -z_in, z_in, through, along);
  append_rectangle(layout, -y_out, -y_in, -z_in, z_in, through, along);
  // Bredt: J = 4 A_m^2 t / p_m on the wall midline.
  const double mid_width = width - wall, mid_depth = depth - wall;
  layout.torsion_constant =
      4.0 * std::pow(mid_width * mid_depth, 2) * wall / (2.0 * (mid_width + mid_depth));
  return layout;
}

FiberLayout mesh_cruciform(double width, double depth, double thickness, int along, int through) {
  require_positive(width, "width");
  require_positive(depth, "depth");
  require_positive(thickness, "thickness");
  if (thickness >= std::min(width, depth)) {
    throw ParameterError("thickness", "must be smaller than both plate widths");
  }
  require_count(along, "fibers_along");
  require_count(through, "fibers_through");
  FiberLayout layout;
  const double half_t = 0.5 * thickness;
  append_rectangle(layout, -half_t, half_t, -half_t, half_t, through, through);
  append_rectangle(layout, half_t, 0.5 * width, -half_t, half_t, along, through);
  append_rectangle(layout, -0.5 * width, -half_t, -half_t, half_t, along, through);
  append_rectangle(layout, -half_t, half_t, half_t, 0.5 * depth, through, along);
  append_rectangle(layout, -half_t, half_t, -0.5 * depth, -half_t, through, along);
  // Open thin-walled section: J = sum of its plates (the crossing counted once).
  layout.torsion_constant = rectangle_torsion_constant(width, thickness) +
                            rectangle_torsion_constant(depth - thickness, thickness);
  return layout;
}

} // namespace brb::section
