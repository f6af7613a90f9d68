// Field snapshots of a hexahedral mesh for ParaView (issue 6, item 5): VTK XML unstructured
// grids (.vtu) and the collection file (.pvd) that lists them with their times, written by
// hand (no VTK library): the format is plain XML, described in "VTK File Formats" (VTK User's
// Guide, 11th ed., ch. 19, section "XML File Formats": UnstructuredGrid, Piece, Points, Cells
// with connectivity / offsets / types, PointData, CellData; Collection / DataSet for .pvd).
//
// Choices:
// - ASCII data (format="ascii"), numbers in the shortest decimal form that reads back to the
//   same double (std::to_chars), so a snapshot is exact to the last bit and diffable.
// - Every cell is a VTK_HEXAHEDRON (type 12) of 8 point indices in VTK's order: the face
//   zeta = -1 counter-clockwise seen from +zeta, then the face zeta = +1 in the same order,
//   which is the order of solid/hex_mesh.hpp (checked in tests/io/vtu_writer_test.cpp against
//   VTK's parametric coordinates of the hexahedron).
// - The snapshot's time goes into the grid's FieldData as the array "TimeValue", the name
//   ParaView's XML readers take as the dataset's time; the .pvd also lists it per file.
// - Files are written atomically (atomic_file.hpp).
#pragma once

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace brb::io {

/// VTK's cell type number of the linear hexahedron (vtkCellType.h: VTK_HEXAHEDRON = 12).
inline constexpr int kVtkHexahedron = 12;

/// 8 point indices (0-based) of a hexahedron, in VTK_HEXAHEDRON order.
using VtuHexahedron = std::array<int, 8>;

/// A named field over the points or the cells: a scalar (1 component) or a 3-vector
/// (3 components, e.g. the displacement in mm). `values` holds components x count numbers,
/// the components of one point or cell together (x0 y0 z0 x1 y1 z1 ...).
struct VtuField {
  std::string name;
  int components = 1; ///< 1 or 3
  std::vector<double> values;
};

/// One state of the mesh: current or reference point coordinates (mm, one column per
/// point), the cells and the fields, at `time` (s, or the analysis' pseudo-time).
struct VtuSnapshot {
  double time = 0.0;
  Eigen::Matrix3Xd points;
  std::vector<VtuHexahedron> cells;
  std::vector<VtuField> point_data;
  std::vector<VtuField> cell_data;
};

/// The .vtu text of `snapshot`. Throws std::invalid_argument, naming what is wrong, when a
/// coordinate, value or the time is not finite, a cell's point index is outside
/// [0, points), a field has no name, a repeated name (within point or cell data), components
/// other than 1 or 3, or a number of values other than components x points (point data) or
/// components x cells (cell data).
std::string vtu_text(const VtuSnapshot& snapshot);

/// Writes vtu_text(snapshot) to `file` atomically (std::invalid_argument as vtu_text, before
/// anything is written; std::system_error when the file cannot be written).
void write_vtu(const std::filesystem::path& file, const VtuSnapshot& snapshot);

/// One file of a time series: its time and its path as the .pvd names it (normally relative to
/// the .pvd's directory, so that the series can be moved as a whole).
struct PvdEntry {
  double time = 0.0;
  std::filesystem::path file;
};

/// The .pvd text listing `entries` in order. Throws std::invalid_argument for no entry, a
/// time that is not finite or smaller than the one before, or an empty file name.
std::string pvd_text(std::span<const PvdEntry> entries);

/// Writes pvd_text(entries) to `file` atomically.
void write_pvd(const std::filesystem::path& file, std::span<const PvdEntry> entries);

} // namespace brb::io
