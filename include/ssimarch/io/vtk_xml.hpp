// VTK XML files (ParaView's own formats; "VTK File Formats", VTK User's Guide, XML section): a
// small writer for PolyData (.vtp), ImageData (.vti) and MultiBlock (.vtm) files, with every data
// array in ASCII (17 significant digits: doubles read back exactly) or inline base64 binary
// (format="binary", no compression, an UInt64 byte count before each array's bytes, encoded
// together as VTK's own writer does). docs/output-format.md, "ParaView / VTK".
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

enum class VtkEncoding { kAscii, kBase64 };

/// One named array: Float64 or Int32 tuples of `components` values, or strings (VTK's
/// vtkStringArray, written as an <Array> element).
struct VtkArray {
  enum class Type { kFloat64, kInt32, kString };
  std::string name;
  Type type = Type::kFloat64;
  int components = 1;
  std::vector<double> reals;            // kFloat64
  std::vector<std::int32_t> integers;   // kInt32
  std::vector<std::string> strings;     // kString (no NUL characters)

  static VtkArray real(std::string name, std::vector<double> values, int components = 1);
  static VtkArray integer(std::string name, std::vector<std::int32_t> values);
  static VtkArray text(std::string name, std::vector<std::string> values);
  /// Tuples held (values / components).
  std::size_t tuples() const;
};

/// Points, each polyline as a list of point indices, each vertex cell as one point index.
struct VtkPolyData {
  std::vector<Vec3> points;
  std::vector<std::vector<std::int64_t>> lines;
  std::vector<std::int64_t> verts;
  std::vector<VtkArray> point_data;  // one tuple per point
  std::vector<VtkArray> cell_data;   // one tuple per cell: the verts first, then the lines (VTK's order)
  std::vector<VtkArray> field_data;  // any number of tuples
};

/// A regular grid of dims[0] x dims[1] x dims[2] points, point (i, j, k) at origin + (i, j, k) *
/// spacing; point data indexed i + dims[0] (j + dims[1] k).
struct VtkImageData {
  std::array<int, 3> dims{1, 1, 1};
  Vec3 origin = Vec3::Zero();
  Vec3 spacing = Vec3::Ones();
  std::vector<VtkArray> point_data;
  std::vector<VtkArray> field_data;
};

/// Throw std::invalid_argument when an array's length does not fit its data set.
void write_vtp(std::ostream& out, const VtkPolyData& data, VtkEncoding encoding);
void write_vti(std::ostream& out, const VtkImageData& data, VtkEncoding encoding);
/// A multiblock file: (block name, file name relative to the .vtm's folder) per block.
void write_vtm(std::ostream& out, const std::vector<std::pair<std::string, std::string>>& blocks);

/// RFC 4648 base64 of `bytes`, with padding (exposed for tests).
std::string base64(const std::string& bytes);

}  // namespace ssimarch
