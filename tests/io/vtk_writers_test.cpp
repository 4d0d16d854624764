// VTK XML writers (io/vtk_xml.hpp, io/vtp_writer.hpp, io/porosity_vtk.hpp): the bytes of the
// encodings, the structure of the files, and the values against the traced run and closed forms.
// tests/io/vtk_readback.py reads the CLI's files back with VTK's own reader.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <regex>
#include <sstream>

#include "ssimarch/core/contract.hpp"
#include "ssimarch/io/porosity_vtk.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/vtk_xml.hpp"
#include "ssimarch/io/vtp_writer.hpp"

namespace ssimarch {
namespace {

// RFC 4648 section 10 decoding, written independently of the encoder.
std::string decode64(const std::string& s) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : 63;
  };
  std::string out;
  for (std::size_t i = 0; i + 3 < s.size(); i += 4) {
    const int n = s[i + 2] == '=' ? 1 : s[i + 3] == '=' ? 2 : 3;
    int w = 0;
    for (int k = 0; k < 4; ++k) w = w * 64 + (k <= n ? value(s[i + k]) : 0);
    for (int k = 0; k < n; ++k) out += static_cast<char>((w >> (16 - 8 * k)) & 255);
  }
  return out;
}

// The words between <DataArray ... Name="name" ...> (or <Array ...>) and its end tag, single-spaced.
std::string array_body(const std::string& xml, const std::string& name) {
  const std::regex re("<(Data)?Array [^>]*Name=\"" + name + "\"[^>]*>([^<]*)</(Data)?Array>");
  std::smatch m;
  if (!std::regex_search(xml, m, re)) return "<missing>";
  std::istringstream words(m[2].str());  // the values, single-spaced
  std::string body, w;
  while (words >> w) body += (body.empty() ? "" : " ") + w;
  return body;
}

std::vector<double> binary_doubles(const std::string& xml, const std::string& name) {
  const std::string bytes = decode64(array_body(xml, name));
  std::uint64_t n = 0;
  std::memcpy(&n, bytes.data(), sizeof n);
  EXPECT_EQ(n + sizeof n, bytes.size()) << name;
  std::vector<double> v(n / sizeof(double));
  std::memcpy(v.data(), bytes.data() + sizeof n, n);
  return v;
}

TEST(VtkXml, Base64MatchesTheRfcVectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

TEST(VtkXml, PolyDataAsciiAndBinaryHoldTheSameValues) {
  VtkPolyData d;
  d.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.1)};
  d.lines = {{0, 1, 2}};
  d.verts = {1};
  d.point_data = {VtkArray::real("kappa", {0.1, 1.0 / 3.0, 2.5}), VtkArray::text("type", {"a", "node", ""})};
  d.cell_data = {VtkArray::integer("branch", {7, 8})};
  std::ostringstream ascii, binary;
  write_vtp(ascii, d, VtkEncoding::kAscii);
  write_vtp(binary, d, VtkEncoding::kBase64);
  const std::string a = ascii.str(), b = binary.str();
  EXPECT_NE(a.find("NumberOfPoints=\"3\" NumberOfVerts=\"1\" NumberOfLines=\"1\""), std::string::npos);
  EXPECT_EQ(array_body(a, "kappa"), "0.10000000000000001 0.33333333333333331 2.5");  // 17 digits: exact
  EXPECT_EQ(array_body(a, "type"), "97 0 110 111 100 101 0 0");  // "a" NUL "node" NUL "" NUL as character codes
  EXPECT_EQ(array_body(a, "offsets"), "1");  // the Verts block comes first: one vertex
  const std::vector<double> k = binary_doubles(b, "kappa");
  ASSERT_EQ(k.size(), 3u);
  EXPECT_EQ(k[1], 1.0 / 3.0);  // binary: bit for bit
  const std::vector<double> p = binary_doubles(b, "Points");
  ASSERT_EQ(p.size(), 9u);
  EXPECT_EQ(p[8], 0.1);
  EXPECT_EQ(decode64(array_body(b, "type")).substr(8), std::string("a\0node\0\0", 8));
}

TEST(VtkXml, ArraysOfTheWrongLengthAreRefused) {
  VtkPolyData d;
  d.points = {Vec3(0, 0, 0)};
  d.point_data = {VtkArray::real("kappa", {1, 2})};
  std::ostringstream os;
  EXPECT_THROW(write_vtp(os, d, VtkEncoding::kAscii), ContractViolation);
  d.point_data.clear();
  d.lines = {{0, 1}};
  EXPECT_THROW(write_vtp(os, d, VtkEncoding::kAscii), ContractViolation);
}

TEST(VtkXml, ImageDataAndMultiblockHeaders) {
  PorosityMap m;
  m.r = {0.25, 0.75};
  m.z = {1.5, 2.5, 3.5};
  m.porosity = {0, 1, 2, 3, 4, 5};
  std::ostringstream os;
  write_vti(os, porosity_map_image_data(m), VtkEncoding::kAscii);
  EXPECT_NE(os.str().find("WholeExtent=\"0 1 0 0 0 2\" Origin=\"0.25 0 1.5\" Spacing=\"0.5 1 1\""), std::string::npos);
  EXPECT_EQ(array_body(os.str(), "porosity"), "0 1 2 3 4 5");
  m.z = {1.5, 2.5, 3.6};
  EXPECT_THROW(porosity_map_image_data(m), ContractViolation);
  std::ostringstream vtm;
  write_vtm(vtm, {{"curves", "a.vtp"}, {"points", "a_points.vtp"}});
  EXPECT_NE(vtm.str().find("<DataSet index=\"1\" name=\"points\" file=\"a_points.vtp\"/>"), std::string::npos);
}

TEST(VtkXml, ProfilesLieOnTheRadiusOrTheAxis) {
  PorosityProfile radial{{0.5, 1.0}, {}, {0.9, 0.4}, {}};
  const Container c{1.0, {2.0, 4.0}};
  const VtkPolyData r = radial_profile_poly_data(radial, c);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[1], Vec3(1.0, 0.0, 3.0));
  ASSERT_EQ(r.lines.size(), 1u);
  EXPECT_EQ(r.lines[0].size(), 2u);
  const VtkPolyData z = axial_profile_poly_data(radial);
  EXPECT_EQ(z.points[0], Vec3(0.0, 0.0, 0.5));
  PorosityProfile bins{{0.0, 0.5}, {0.5, 1.0}, {0.9, 0.4}, {}};
  EXPECT_EQ(bin_profile_poly_data(bins, c).points[1], Vec3(0.75, 0.0, 3.0));
}

std::vector<IntersectionRun> viviani_runs(const Scene& s) {
  std::vector<IntersectionRun> runs;
  for (const auto& spec : s.intersections) runs.push_back(run_intersection(s, spec));
  return runs;
}

// Viviani's curve: sphere of radius 2 and the cylinder of radius 1 through its centre. Its length,
// an elliptic integral, is 15.2807911561 (the value tests/io/writers_test.cpp checks too).
TEST(VtpWriter, CurvesCarryTheRunsPointsGeometryAndArcLength) {
  const Scene s = parse_scene(R"json({
    "surfaces": {"sphere": {"sphere": {"center": [0,0,0], "radius": 2}},
                 "cyl": {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]}},
    "intersections": [{"name": "viviani", "surfaces": ["sphere", "cyl"], "start": [1, -1, 1.4142],
                       "options": {"step_length": 0.1, "geometry": "exact"}}]})json", "s.json");
  const auto runs = viviani_runs(s);
  const TracedCurve& c = runs[0].result.curves.at(0);
  const VtkPolyData d = curves_poly_data(runs);
  ASSERT_EQ(d.points.size(), c.points.size());
  ASSERT_EQ(d.lines.size(), 1u);
  auto array = [&](const std::string& name) -> const VtkArray& {
    for (const VtkArray& a : d.point_data)
      if (a.name == name) return a;
    throw std::runtime_error("no array " + name);
  };
  const std::size_t n = c.points.size();
  EXPECT_NEAR(array("arc_length").reals.back(), 15.2807911561, 1e-4);
  EXPECT_NEAR(array("arc_length").reals.back(), c.length, 1e-9 * c.length);
  for (std::size_t i = 0; i < n; i += n / 7) {
    EXPECT_EQ(d.points[i], c.points[i].p);
    EXPECT_EQ(array("params").reals[4 * i], c.points[i].x[0]);
    EXPECT_TRUE(std::isnan(array("params").reals[4 * i + 2]));  // two unknowns, padded
    EXPECT_EQ(array("kappa").reals[i], runs[0].geometry[0][i].kappa);
    // Viviani's curve (1 + cos t, sin t, 2 sin(t/2)) has kappa = sqrt(13 + 3 cos t) / (3 + cos t)^(3/2),
    // and cos t = 1 - z^2/2 at height z (a rotation about the z axis maps the scene's curve onto it).
    const double cos_t = 1 - c.points[i].p.z() * c.points[i].p.z() / 2;
    EXPECT_NEAR(array("kappa").reals[i], std::sqrt(13 + 3 * cos_t) / std::pow(3 + cos_t, 1.5), 1e-6);
  }
  EXPECT_EQ(array("branch").integers[n - 1], 0);
}

TEST(VtpWriter, TraceFilesAreNamedAfterTheOutput) {
  const VtpTraceFiles f = vtp_trace_files("out/dir/run.vtm");
  EXPECT_EQ(f.curves, std::filesystem::path("out/dir/run.vtp"));
  EXPECT_EQ(f.points, std::filesystem::path("out/dir/run_points.vtp"));
  EXPECT_EQ(f.multiblock, std::filesystem::path("out/dir/run.vtm"));
  EXPECT_EQ(vtp_trace_files("run.vtp").multiblock, std::filesystem::path("run.vtm"));
}

}  // namespace
}  // namespace ssimarch
