// VTK XML writer (see vtk_xml.hpp).
#include "ssimarch/io/vtk_xml.hpp"

#include <bit>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "ssimarch/core/contract.hpp"

namespace ssimarch {

namespace {

const char* byte_order() { return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian"; }

const char* type_name(VtkArray::Type t) {
  switch (t) {
    case VtkArray::Type::kFloat64: return "Float64";
    case VtkArray::Type::kInt32: return "Int32";
    case VtkArray::Type::kString: return "String";
  }
  return "";
}

std::string xml_escaped(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '&') r += "&amp;";
    else if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else if (c == '"') r += "&quot;";
    else r += c;
  }
  return r;
}

template <class T>
void append_bytes(std::string* bytes, const std::vector<T>& values) {
  const std::size_t n = values.size() * sizeof(T);
  const std::size_t at = bytes->size();
  bytes->resize(at + n);
  if (n) std::memcpy(bytes->data() + at, values.data(), n);
}

// The array's values as raw bytes (strings: each followed by its NUL, as vtkStringArray is read).
std::string raw_bytes(const VtkArray& a) {
  std::string bytes;
  if (a.type == VtkArray::Type::kFloat64) append_bytes(&bytes, a.reals);
  else if (a.type == VtkArray::Type::kInt32) append_bytes(&bytes, a.integers);
  else
    for (const std::string& s : a.strings) bytes.append(s).push_back('\0');
  return bytes;
}

// format="binary": the byte count (UInt64, header_type) and the bytes, base64-encoded together.
std::string binary_block(const std::string& data) {
  const std::uint64_t n = data.size();
  std::string block(sizeof n, '\0');
  std::memcpy(block.data(), &n, sizeof n);
  return base64(block + data);
}

void write_ascii_values(std::ostream& out, const VtkArray& a) {
  std::ostringstream o;
  o.precision(std::numeric_limits<double>::max_digits10);
  std::size_t k = 0;
  auto sep = [&] { o << (k++ % 9 == 0 ? "\n        " : " "); };
  if (a.type == VtkArray::Type::kFloat64)
    for (double v : a.reals) sep(), o << v;
  else if (a.type == VtkArray::Type::kInt32)
    for (std::int32_t v : a.integers) sep(), o << v;
  else
    for (const std::string& s : a.strings) {
      for (unsigned char c : s) sep(), o << static_cast<int>(c);
      sep(), o << 0;
    }
  out << o.str() << "\n      ";
}

void write_array(std::ostream& out, const VtkArray& a, VtkEncoding encoding) {
  for (const std::string& s : a.strings)
    SSIMARCH_EXPECTS(s.find('\0') == std::string::npos, "VTK array " + a.name + ": a string holds a NUL");
  const char* element = a.type == VtkArray::Type::kString ? "Array" : "DataArray";
  out << "      <" << element << " type=\"" << type_name(a.type) << "\" Name=\"" << xml_escaped(a.name) << "\"";
  if (a.components != 1) out << " NumberOfComponents=\"" << a.components << "\"";
  out << " NumberOfTuples=\"" << a.tuples() << "\" format=\"" << (encoding == VtkEncoding::kAscii ? "ascii" : "binary")
      << "\">";
  if (encoding == VtkEncoding::kAscii) {
    write_ascii_values(out, a);
  } else {
    out << "\n        " << binary_block(raw_bytes(a)) << "\n      ";
  }
  out << "</" << element << ">\n";
}

void write_arrays(std::ostream& out, const char* tag, const std::vector<VtkArray>& arrays, std::size_t tuples,
                  VtkEncoding encoding, bool check) {
  out << "    <" << tag << ">\n";
  for (const VtkArray& a : arrays) {
    SSIMARCH_EXPECTS(!check || a.tuples() == tuples, std::string("VTK ") + tag + " array " + a.name + ": " +
                                                         std::to_string(a.tuples()) + " tuples for " +
                                                         std::to_string(tuples));
    write_array(out, a, encoding);
  }
  out << "    </" << tag << ">\n";
}

// A cell block (Verts, Lines): connectivity and end offsets, Int64.
void write_cells(std::ostream& out, const char* tag, const std::vector<std::vector<std::int64_t>>& cells,
                 std::size_t points, VtkEncoding encoding) {
  std::vector<std::int64_t> conn, offsets;
  for (const auto& c : cells) {
    for (std::int64_t i : c) {
      SSIMARCH_EXPECTS(i >= 0 && static_cast<std::size_t>(i) < points, "VTK cell: point index out of range");
      conn.push_back(i);
    }
    offsets.push_back(static_cast<std::int64_t>(conn.size()));
  }
  // The only Int64 arrays of these files (VtkArray has no Int64 type).
  auto put = [&](const char* name, const std::vector<std::int64_t>& v) {
    out << "      <DataArray type=\"Int64\" Name=\"" << name << "\" format=\"" << (encoding == VtkEncoding::kAscii ? "ascii" : "binary") << "\">";
    if (encoding == VtkEncoding::kAscii) {
      out << "\n       ";
      for (std::int64_t x : v) out << " " << x;
      out << "\n      ";
    } else {
      std::string data;
      append_bytes(&data, v);
      out << "\n        " << binary_block(data) << "\n      ";
    }
    out << "</DataArray>\n";
  };
  out << "    <" << tag << ">\n";
  put("connectivity", conn);
  put("offsets", offsets);
  out << "    </" << tag << ">\n";
}

void begin_file(std::ostream& out, const char* type) {
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"" << type << "\" version=\"1.0\" byte_order=\"" << byte_order()
      << "\" header_type=\"UInt64\">\n";
}

}  // namespace

VtkArray VtkArray::real(std::string name, std::vector<double> values, int components) {
  VtkArray a;
  a.name = std::move(name);
  a.type = Type::kFloat64;
  a.components = components;
  a.reals = std::move(values);
  return a;
}

VtkArray VtkArray::integer(std::string name, std::vector<std::int32_t> values) {
  VtkArray a;
  a.name = std::move(name);
  a.type = Type::kInt32;
  a.integers = std::move(values);
  return a;
}

VtkArray VtkArray::text(std::string name, std::vector<std::string> values) {
  VtkArray a;
  a.name = std::move(name);
  a.type = Type::kString;
  a.strings = std::move(values);
  return a;
}

std::size_t VtkArray::tuples() const {
  const std::size_t n = type == Type::kFloat64 ? reals.size() : type == Type::kInt32 ? integers.size() : strings.size();
  return components > 0 ? n / static_cast<std::size_t>(components) : 0;
}

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string r;
  r.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t w = 0;
    for (std::size_t k = 0; k < 3; ++k)
      w = (w << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) r += k <= n ? kAlphabet[(w >> (18 - 6 * k)) & 63] : '=';
  }
  return r;
}

void write_vtp(std::ostream& out, const VtkPolyData& d, VtkEncoding encoding) {
  const std::size_t np = d.points.size();
  begin_file(out, "PolyData");
  out << "  <PolyData>\n";
  if (!d.field_data.empty()) {
    out << "  ";
    write_arrays(out, "FieldData", d.field_data, 0, encoding, false);
  }
  out << "  <Piece NumberOfPoints=\"" << np << "\" NumberOfVerts=\"" << d.verts.size() << "\" NumberOfLines=\""
      << d.lines.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  write_arrays(out, "PointData", d.point_data, np, encoding, true);
  write_arrays(out, "CellData", d.cell_data, d.verts.size() + d.lines.size(), encoding, true);
  std::vector<double> xyz;
  xyz.reserve(3 * np);
  for (const Vec3& p : d.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  out << "    <Points>\n";
  write_array(out, VtkArray::real("Points", std::move(xyz), 3), encoding);
  out << "    </Points>\n";
  std::vector<std::vector<std::int64_t>> verts;
  for (std::int64_t v : d.verts) verts.push_back({v});
  write_cells(out, "Verts", verts, np, encoding);
  write_cells(out, "Lines", d.lines, np, encoding);
  out << "  </Piece>\n  </PolyData>\n</VTKFile>\n";
}

void write_vti(std::ostream& out, const VtkImageData& d, VtkEncoding encoding) {
  for (int n : d.dims) SSIMARCH_EXPECTS(n >= 1, "VTK image: every dimension needs at least one point");
  const std::size_t np = static_cast<std::size_t>(d.dims[0]) * d.dims[1] * d.dims[2];
  std::ostringstream o;
  o.precision(std::numeric_limits<double>::max_digits10);
  o << "0 " << d.dims[0] - 1 << " 0 " << d.dims[1] - 1 << " 0 " << d.dims[2] - 1;
  const std::string extent = o.str();
  o.str("");
  o << d.origin.x() << " " << d.origin.y() << " " << d.origin.z() << "\" Spacing=\"" << d.spacing.x() << " "
    << d.spacing.y() << " " << d.spacing.z();
  begin_file(out, "ImageData");
  out << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << o.str() << "\">\n";
  if (!d.field_data.empty()) {
    out << "  ";
    write_arrays(out, "FieldData", d.field_data, 0, encoding, false);
  }
  out << "  <Piece Extent=\"" << extent << "\">\n";
  write_arrays(out, "PointData", d.point_data, np, encoding, true);
  out << "    <CellData>\n    </CellData>\n  </Piece>\n  </ImageData>\n</VTKFile>\n";
}

void write_vtm(std::ostream& out, const std::vector<std::pair<std::string, std::string>>& blocks) {
  begin_file(out, "vtkMultiBlockDataSet");
  out << "  <vtkMultiBlockDataSet>\n";
  for (std::size_t i = 0; i < blocks.size(); ++i)
    out << "    <DataSet index=\"" << i << "\" name=\"" << xml_escaped(blocks[i].first) << "\" file=\""
        << xml_escaped(blocks[i].second) << "\"/>\n";
  out << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
}

}  // namespace ssimarch
