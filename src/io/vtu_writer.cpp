#include "brb/io/vtu_writer.hpp"

#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"

#include <cmath>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <string_view>

namespace brb::io {
namespace {

/// Numbers per line of a data array: short lines keep the file readable and diffable.
constexpr std::size_t kNumbersPerLine = 12;

/// Text safe inside an XML attribute value (names of fields and files).
std::string xml_escaped(std::string_view text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
    case '&':
      escaped += "&amp;";
      break;
    case '<':
      escaped += "&lt;";
      break;
    case '>':
      escaped += "&gt;";
      break;
    case '"':
      escaped += "&quot;";
      break;
    default:
      escaped += c;
    }
  }
  return escaped;
}

void append_numbers(std::string& text, std::span<const double> values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    text += (i % kNumbersPerLine == 0) ? "\n          " : " ";
    text += format_number(values[i]);
  }
  text += "\n        ";
}

template <typename Integer>
void append_integers(std::string& text, const std::vector<Integer>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    text += (i % kNumbersPerLine == 0) ? "\n          " : " ";
    text += std::to_string(values[i]);
  }
  text += "\n        ";
}

void check_fields(const std::vector<VtuField>& fields, std::size_t count, std::string_view where,
                  std::string_view counted) {
  std::set<std::string> names;
  for (const VtuField& field : fields) {
    const std::string label = std::string(where) + " field \"" + field.name + "\"";
    if (field.name.empty())
      throw std::invalid_argument("vtu: a " + std::string(where) + " field has no name");
    if (!names.insert(field.name).second)
      throw std::invalid_argument("vtu: " + label + " is given twice");
    if (field.components != 1 && field.components != 3) {
      throw std::invalid_argument("vtu: " + label + ": components must be 1 (scalar) or 3 " +
                                  "(vector), got " + std::to_string(field.components));
    }
    const std::size_t expected = static_cast<std::size_t>(field.components) * count;
    if (field.values.size() != expected) {
      throw std::invalid_argument("vtu: " + label + ": expected " + std::to_string(expected) +
                                  " values (" + std::to_string(field.components) + " x " +
                                  std::to_string(count) + " " + std::string(counted) + "), got " +
                                  std::to_string(field.values.size()));
    }
    for (std::size_t i = 0; i < field.values.size(); ++i) {
      if (!std::isfinite(field.values[i])) {
        throw std::invalid_argument("vtu: " + label + ": value " + std::to_string(i) +
                                    " is not finite");
      }
    }
  }
}

void check_snapshot(const VtuSnapshot& snapshot) {
  if (!std::isfinite(snapshot.time))
    throw std::invalid_argument("vtu: the snapshot's time is not finite");
  if (!snapshot.points.allFinite())
    throw std::invalid_argument("vtu: a point coordinate is not finite");
  const auto points = static_cast<std::size_t>(snapshot.points.cols());
  for (std::size_t c = 0; c < snapshot.cells.size(); ++c) {
    for (const int index : snapshot.cells[c]) {
      if (index < 0 || static_cast<std::size_t>(index) >= points) {
        throw std::invalid_argument("vtu: cell " + std::to_string(c) + " names point " +
                                    std::to_string(index) + ", outside [0, " +
                                    std::to_string(points) + ")");
      }
    }
  }
  check_fields(snapshot.point_data, points, "point", "points");
  check_fields(snapshot.cell_data, snapshot.cells.size(), "cell", "cells");
}

/// PointData / CellData with every field; the first scalar and first vector are the active
/// ones (what ParaView colours by when the file opens).
void append_data(std::string& text, std::string_view tag, const std::vector<VtuField>& fields) {
  text += "      <" + std::string(tag);
  for (const int components : {1, 3}) {
    for (const VtuField& field : fields) {
      if (field.components == components) {
        text += std::string(components == 1 ? " Scalars" : " Vectors") + "=\"" +
                xml_escaped(field.name) + "\"";
        break;
      }
    }
  }
  text += ">\n";
  for (const VtuField& field : fields) {
    text += "        <DataArray type=\"Float64\" Name=\"" + xml_escaped(field.name) +
            "\" NumberOfComponents=\"" + std::to_string(field.components) + "\" format=\"ascii\">";
    append_numbers(text, field.values);
    text += "</DataArray>\n";
  }
  text += "      </" + std::string(tag) + ">\n";
}

} // namespace

std::string vtu_text(const VtuSnapshot& snapshot) {
  check_snapshot(snapshot);
  const auto points = static_cast<std::size_t>(snapshot.points.cols());
  const std::size_t cells = snapshot.cells.size();

  std::string text = "<?xml version=\"1.0\"?>\n"
                     "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
                     "byte_order=\"LittleEndian\">\n"
                     "  <UnstructuredGrid>\n"
                     "    <FieldData>\n"
                     "      <DataArray type=\"Float64\" Name=\"TimeValue\" "
                     "NumberOfTuples=\"1\" format=\"ascii\">" +
                     format_number(snapshot.time) +
                     "</DataArray>\n"
                     "    </FieldData>\n";
  text += "    <Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfCells=\"" +
          std::to_string(cells) + "\">\n";
  append_data(text, "PointData", snapshot.point_data);
  append_data(text, "CellData", snapshot.cell_data);

  // Eigen's Matrix3Xd is column-major: x y z of each point are contiguous, the order VTK wants.
  text += "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
          "format=\"ascii\">";
  append_numbers(text, std::span<const double>(snapshot.points.data(), 3 * points));
  text += "</DataArray>\n      </Points>\n";

  std::vector<long long> connectivity;
  connectivity.reserve(8 * cells);
  std::vector<long long> offsets; // the end of each cell's list (VTK XML convention)
  offsets.reserve(cells);
  for (const VtuHexahedron& cell : snapshot.cells) {
    connectivity.insert(connectivity.end(), cell.begin(), cell.end());
    offsets.push_back(static_cast<long long>(connectivity.size()));
  }
  const std::vector<int> types(cells, kVtkHexahedron);
  text += "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
          "format=\"ascii\">";
  append_integers(text, connectivity);
  text += "</DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">";
  append_integers(text, offsets);
  text += "</DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">";
  append_integers(text, types);
  text += "</DataArray>\n      </Cells>\n";
  text += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return text;
}

void write_vtu(const std::filesystem::path& file, const VtuSnapshot& snapshot) {
  write_file_atomically(file, vtu_text(snapshot));
}

std::string pvd_text(std::span<const PvdEntry> entries) {
  if (entries.empty())
    throw std::invalid_argument("pvd: a collection needs at least one file");
  std::string text = "<?xml version=\"1.0\"?>\n"
                     "<VTKFile type=\"Collection\" version=\"0.1\" "
                     "byte_order=\"LittleEndian\">\n"
                     "  <Collection>\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const PvdEntry& entry = entries[i];
    if (!std::isfinite(entry.time))
      throw std::invalid_argument("pvd: the time of entry " + std::to_string(i) + " is not finite");
    if (i > 0 && entry.time < entries[i - 1].time) {
      throw std::invalid_argument("pvd: the times must not decrease (entry " + std::to_string(i) +
                                  " at " + format_number(entry.time) + " after " +
                                  format_number(entries[i - 1].time) + ")");
    }
    if (entry.file.empty())
      throw std::invalid_argument("pvd: entry " + std::to_string(i) + " names no file");
    text += "    <DataSet timestep=\"" + format_number(entry.time) +
            "\" group=\"\" part=\"0\" file=\"" + xml_escaped(entry.file.generic_string()) +
            "\"/>\n";
  }
  text += "  </Collection>\n</VTKFile>\n";
  return text;
}

void write_pvd(const std::filesystem::path& file, std::span<const PvdEntry> entries) {
  write_file_atomically(file, pvd_text(entries));
}

} // namespace brb::io
