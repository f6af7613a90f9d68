// VTK XML output (issue 6, item 5): a two-hexahedron mesh written and read back with a small
// XML parse (counts, offsets, types, connectivity, values bit for bit), the .pvd collection,
// refused inputs, and the node order of solid/hex_mesh.hpp against VTK's hexahedron.
#include "brb/io/vtu_writer.hpp"
#include "brb/solid/hex_mesh.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace brb::io {
namespace {

using testing::read_file;
using testing::ScratchDirectory;

// ---------------------------------------------------------------------------------------
// A small XML reader, enough for the files written here: elements with attributes and text.

struct XmlElement {
  std::map<std::string, std::string> attributes;
  std::string text; ///< between the start and end tags (empty for <.../>)
};

/// Every element `<tag ...>text</tag>` or `<tag .../>` of `xml`, in document order.
std::vector<XmlElement> elements(const std::string& xml, const std::string& tag) {
  const std::regex element("<" + tag + R"(((?:\s+[A-Za-z_]+="[^"]*")*)\s*(?:/>|>([^<]*)</)" + tag +
                           ">)");
  const std::regex attribute(R"(([A-Za-z_]+)="([^"]*)\")");
  std::vector<XmlElement> found;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), element);
       it != std::sregex_iterator(); ++it) {
    XmlElement item;
    const std::string attributes = (*it)[1];
    for (auto a = std::sregex_iterator(attributes.begin(), attributes.end(), attribute);
         a != std::sregex_iterator(); ++a)
      item.attributes[(*a)[1]] = (*a)[2];
    item.text = (*it)[2];
    found.push_back(item);
  }
  return found;
}

/// The start tag's attributes of the first `<tag ...>` (elements with children).
std::map<std::string, std::string> start_tag(const std::string& xml, const std::string& tag) {
  const std::regex start("<" + tag + R"(((?:\s+[A-Za-z_]+="[^"]*")*)\s*>)");
  const std::regex attribute(R"(([A-Za-z_]+)="([^"]*)\")");
  std::smatch match;
  std::map<std::string, std::string> attributes;
  if (!std::regex_search(xml, match, start))
    return attributes;
  const std::string text = match[1];
  for (auto a = std::sregex_iterator(text.begin(), text.end(), attribute);
       a != std::sregex_iterator(); ++a)
    attributes[(*a)[1]] = (*a)[2];
  return attributes;
}

/// The numbers of a data array's text, read exactly (std::from_chars).
std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  const char* cursor = text.data();
  const char* end = text.data() + text.size();
  while (cursor < end) {
    while (cursor < end && std::isspace(static_cast<unsigned char>(*cursor)))
      ++cursor;
    if (cursor == end)
      break;
    double value = 0.0;
    const auto [next, status] = std::from_chars(cursor, end, value);
    if (status != std::errc{})
      throw std::runtime_error("not a number in a data array: " + std::string(cursor, end));
    values.push_back(value);
    cursor = next;
  }
  return values;
}

/// The DataArray named `name` (the first one).
XmlElement data_array(const std::string& xml, const std::string& name) {
  for (const XmlElement& array : elements(xml, "DataArray")) {
    if (array.attributes.count("Name") && array.attributes.at("Name") == name)
      return array;
  }
  throw std::runtime_error("no DataArray named " + name);
}

// ---------------------------------------------------------------------------------------

/// Two hexahedra side by side along x (12 points), moved by a displacement field with values
/// that need all 17 significant digits, and fields over points and cells.
VtuSnapshot two_hexahedra() {
  const solid::StructuredPrismMesh prism({2.0 / 3.0, 1.0, std::numbers::pi}, {2, 1, 1});
  VtuSnapshot snapshot;
  snapshot.time = 0.1 + 0.2; // 0.30000000000000004: needs every digit
  const int n = prism.mesh().node_count();
  VtuField displacement{"displacement", 3, {}};
  VtuField temperature{"distance", 1, {}};
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < 3; ++i)
      displacement.values.push_back(std::sqrt(2.0 + a + 0.1 * i) / 7.0);
    temperature.values.push_back(std::exp(-a / 3.0));
  }
  snapshot.points = prism.mesh().nodes;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i)
      snapshot.points(i, a) += displacement.values[3 * a + i];
  snapshot.cells.assign(prism.mesh().elements.begin(), prism.mesh().elements.end());
  snapshot.point_data = {temperature, displacement};
  snapshot.cell_data = {{"plastic_strain", 1, {1.0 / 3.0, 2.0 / 7.0}},
                        {"steel_damage", 1, {0.0, 1e-300}},
                        {"part_id", 1, {1.0, 2.0}}};
  return snapshot;
}

TEST(VtuWriter, TwoHexahedraReadBackExactly) {
  const VtuSnapshot snapshot = two_hexahedra();
  const std::string xml = vtu_text(snapshot);

  EXPECT_EQ(start_tag(xml, "VTKFile").at("type"), "UnstructuredGrid");
  const auto piece = start_tag(xml, "Piece");
  EXPECT_EQ(piece.at("NumberOfPoints"), "12");
  EXPECT_EQ(piece.at("NumberOfCells"), "2");

  // The time, at full precision, under ParaView's name.
  const std::vector<double> time = numbers(data_array(xml, "TimeValue").text);
  ASSERT_EQ(time.size(), 1u);
  EXPECT_EQ(time[0], snapshot.time);

  // Points: x y z of each point, exactly.
  const std::size_t points_at = xml.find("<Points>");
  ASSERT_NE(points_at, std::string::npos);
  const XmlElement coordinates = elements(xml.substr(points_at), "DataArray").front();
  EXPECT_EQ(coordinates.attributes.at("NumberOfComponents"), "3");
  const std::vector<double> xyz = numbers(coordinates.text);
  ASSERT_EQ(xyz.size(), 36u);
  for (int a = 0; a < 12; ++a)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(xyz[3 * a + i], snapshot.points(i, a)) << "point " << a << " component " << i;

  // Cells: the connectivity of the mesh, end offsets 8 and 16, two VTK_HEXAHEDRON (12).
  const std::vector<double> connectivity = numbers(data_array(xml, "connectivity").text);
  ASSERT_EQ(connectivity.size(), 16u);
  for (int c = 0; c < 2; ++c)
    for (int a = 0; a < 8; ++a)
      EXPECT_EQ(connectivity[8 * c + a], snapshot.cells[c][a]);
  EXPECT_EQ(numbers(data_array(xml, "offsets").text), (std::vector<double>{8, 16}));
  EXPECT_EQ(numbers(data_array(xml, "types").text), (std::vector<double>{12, 12}));
  EXPECT_EQ(data_array(xml, "types").attributes.at("type"), "UInt8");

  // Fields: components and values bit for bit.
  for (const VtuField& field : snapshot.point_data) {
    const XmlElement array = data_array(xml, field.name);
    EXPECT_EQ(array.attributes.at("NumberOfComponents"), std::to_string(field.components));
    EXPECT_EQ(numbers(array.text), field.values) << field.name;
  }
  for (const VtuField& field : snapshot.cell_data)
    EXPECT_EQ(numbers(data_array(xml, field.name).text), field.values) << field.name;
  // The point fields sit inside PointData, the cell fields inside CellData, and the first
  // scalar and vector are the active ones.
  const std::size_t point_data = xml.find("<PointData");
  const std::size_t cell_data = xml.find("<CellData");
  EXPECT_LT(point_data, xml.find("Name=\"displacement\""));
  EXPECT_LT(xml.find("Name=\"displacement\""), cell_data);
  EXPECT_LT(cell_data, xml.find("Name=\"plastic_strain\""));
  EXPECT_EQ(start_tag(xml, "PointData").at("Scalars"), "distance");
  EXPECT_EQ(start_tag(xml, "PointData").at("Vectors"), "displacement");
  EXPECT_EQ(start_tag(xml, "CellData").at("Scalars"), "plastic_strain");
}

TEST(VtuWriter, WritesTheFileAtomically) {
  ScratchDirectory scratch;
  const auto file = scratch.path() / "snapshot_0001.vtu";
  const VtuSnapshot snapshot = two_hexahedra();
  write_vtu(file, snapshot);
  EXPECT_EQ(read_file(file), vtu_text(snapshot));
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"snapshot_0001.vtu"});

  // A refused snapshot leaves the file as it was.
  VtuSnapshot wrong = snapshot;
  wrong.cell_data[0].values.pop_back();
  EXPECT_THROW(write_vtu(file, wrong), std::invalid_argument);
  EXPECT_EQ(read_file(file), vtu_text(snapshot));
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"snapshot_0001.vtu"});
}

/// The message of the std::invalid_argument `snapshot` is refused with.
std::string refusal(const VtuSnapshot& snapshot) {
  try {
    vtu_text(snapshot);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(VtuWriter, RefusesMismatchedSizesAndBadCells) {
  const VtuSnapshot good = two_hexahedra();

  VtuSnapshot short_points = good;
  short_points.point_data[1].values.resize(35); // displacement: 3 x 12 = 36 values
  EXPECT_EQ(refusal(short_points), "vtu: point field \"displacement\": expected 36 values "
                                   "(3 x 12 points), got 35");

  VtuSnapshot long_cells = good;
  long_cells.cell_data[2].values.push_back(3.0);
  EXPECT_EQ(refusal(long_cells), "vtu: cell field \"part_id\": expected 2 values (1 x 2 cells), "
                                 "got 3");

  VtuSnapshot two_components = good;
  two_components.point_data[0] = {"distance", 2, std::vector<double>(24, 0.0)};
  EXPECT_NE(refusal(two_components).find("components must be 1 (scalar) or 3"), std::string::npos);

  VtuSnapshot outside = good;
  outside.cells[1][5] = 12;
  EXPECT_EQ(refusal(outside), "vtu: cell 1 names point 12, outside [0, 12)");

  VtuSnapshot twice = good;
  twice.cell_data.push_back(twice.cell_data[0]);
  EXPECT_EQ(refusal(twice), "vtu: cell field \"plastic_strain\" is given twice");

  VtuSnapshot unnamed = good;
  unnamed.point_data[0].name.clear();
  EXPECT_EQ(refusal(unnamed), "vtu: a point field has no name");

  VtuSnapshot not_finite = good;
  not_finite.cell_data[1].values[1] = std::nan("");
  EXPECT_EQ(refusal(not_finite), "vtu: cell field \"steel_damage\": value 1 is not finite");
}

TEST(VtuWriter, EscapesNamesForXml) {
  VtuSnapshot snapshot = two_hexahedra();
  snapshot.cell_data[0].name = "sigma<11> & \"more\"";
  const std::string xml = vtu_text(snapshot);
  EXPECT_NE(xml.find("Name=\"sigma&lt;11&gt; &amp; &quot;more&quot;\""), std::string::npos);
}

TEST(PvdWriter, ListsEveryFileWithItsTime) {
  ScratchDirectory scratch;
  const std::vector<PvdEntry> entries{
      {0.0, "brace_0000.vtu"}, {0.1 + 0.2, "brace_0001.vtu"}, {1.0 / 3.0, "fields/brace_0002.vtu"}};
  const auto file = scratch.path() / "brace.pvd";
  write_pvd(file, entries);
  const std::string xml = read_file(file);
  EXPECT_EQ(start_tag(xml, "VTKFile").at("type"), "Collection");
  const std::vector<XmlElement> datasets = elements(xml, "DataSet");
  ASSERT_EQ(datasets.size(), entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    EXPECT_EQ(datasets[i].attributes.at("file"), entries[i].file.generic_string());
    EXPECT_EQ(numbers(datasets[i].attributes.at("timestep")), std::vector<double>{entries[i].time});
  }
}

TEST(PvdWriter, RefusesDecreasingTimesAndEmptyLists) {
  const std::vector<PvdEntry> backwards{{1.0, "a.vtu"}, {0.5, "b.vtu"}};
  EXPECT_THROW(pvd_text(backwards), std::invalid_argument);
  EXPECT_THROW(pvd_text(std::vector<PvdEntry>{}), std::invalid_argument);
  EXPECT_THROW(pvd_text(std::vector<PvdEntry>{{0.0, ""}}), std::invalid_argument);
}

// VTK's hexahedron (vtkHexahedron.cxx, its parametric coordinates, VTK File Formats figure
// of VTK_HEXAHEDRON): point a sits at (r, s, t) in [0, 1]^3 as listed here. hex_mesh.hpp's
// natural coordinates (-1 or +1 each) must map onto them by (xi + 1) / 2, so that a mesh's
// connectivity can be written as is.
TEST(VtuWriter, HexMeshNodeOrderIsVtkHexahedronOrder) {
  constexpr std::array<std::array<int, 3>, 8> vtk_parametric{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ((solid::kNaturalCoordinates[a][i] + 1) / 2, vtk_parametric[a][i]) << a;

  // And the mesh's elements follow it: node a of an element sits at the element's lower
  // corner plus the parametric coordinates times the spacing.
  const solid::StructuredPrismMesh prism({2.0, 3.0, 5.0}, {2, 3, 5});
  const solid::HexMesh& mesh = prism.mesh();
  for (const solid::HexConnectivity& element : mesh.elements) {
    const Eigen::Vector3d corner = mesh.nodes.col(element[0]);
    for (int a = 0; a < 8; ++a) {
      for (int i = 0; i < 3; ++i)
        EXPECT_DOUBLE_EQ(mesh.nodes(i, element[a]), corner(i) + vtk_parametric[a][i]);
    }
  }
}

} // namespace
} // namespace brb::io
