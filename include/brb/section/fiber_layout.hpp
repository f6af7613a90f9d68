// Fiber meshes of the cross-sections a BRB core or casing uses. A layout is plain
// geometry: fiber centroids (y, z) in the section's principal axes, and areas, stored
// as contiguous arrays (structure of arrays) for the section's hot loop. Units: mm, mm^2.
//
// Section axes: x along the member, y and z in the section; all meshers centre the
// section on its centroid and align it with its principal axes.
#pragma once

#include <vector>

namespace brb::section {

struct FiberLayout {
  std::vector<double> y;         ///< fiber centroid coordinate (mm)
  std::vector<double> z;         ///< fiber centroid coordinate (mm)
  std::vector<double> area;      ///< fiber area (mm^2)
  double torsion_constant = 0.0; ///< Saint-Venant J of the whole section (mm^4)

  std::size_t size() const { return area.size(); }
  double total_area() const;
  /// Second moment about the y axis, sum A z^2 (bending about y: curvature kappa_y).
  double second_moment_y() const;
  /// Second moment about the z axis, sum A y^2.
  double second_moment_z() const;
  void append(double fiber_y, double fiber_z, double fiber_area);
};

/// Solid rectangle, `width` along y and `depth` along z, ny x nz equal cells.
FiberLayout mesh_rectangle(double width, double depth, int ny, int nz);

/// Solid circle of `diameter`: `rings` x `sectors` ring sectors with exact areas
/// (the centroids keep the polar moment of each sector exactly).
FiberLayout mesh_circle(double diameter, int rings, int sectors);

/// Circular hollow section (tube): outer diameter, wall thickness.
FiberLayout mesh_circular_tube(double outer_diameter, double wall, int rings, int sectors);

/// Rectangular hollow section: outer width (y) and depth (z), wall thickness;
/// `along` cells along each wall, `through` cells through the thickness.
FiberLayout mesh_rectangular_tube(double width, double depth, double wall, int along, int through);

/// Cruciform core: a plate of extent `width` along y and one of extent `depth` along z,
/// both of thickness `thickness`, crossing at the centroid (the central square counted
/// once). `along` cells along each arm, `through` cells through the thickness.
FiberLayout mesh_cruciform(double width, double depth, double thickness, int along, int through);

/// Saint-Venant torsion constant of a solid rectangle b x t (any order), by the series
/// J = b t^3 [1/3 - (64/pi^5)(t/b) sum_{n odd} tanh(n pi b / 2t) / n^5] (Timoshenko & Goodier).
double rectangle_torsion_constant(double width, double depth);

} // namespace brb::section
