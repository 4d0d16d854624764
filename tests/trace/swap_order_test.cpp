// Order independence (issue 11 item 4, issue 13 item 4): every intersection of every scene in
// examples/ and bench/peers/scenes/ (the benchmark pairs), traced with its two surfaces in the
// given and in the swapped order, gives the same curve network: the same components, branches
// and closed flags, branch and edge lengths to 1e-9, vertices to 1e-10 (model units). The vertices are matched by their
// 3D points, the branches by length: ids and curve order are not part of the comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

#include "testing/simpson.hpp"

namespace ssimarch {
namespace {

// Lengths agree to 1e-9 relative (issue 26 item 2), at least 1e-9 model units (issue 11 item 4).
// An absolute 1e-9 asked more of OpenCASCADE's bug32850 (coordinates ~2000, a branch of 13.01)
// than either order's own accuracy: at the default step both lie 2.4e-9 and 3.5e-9 from the
// length both converge to at steps of 0.1 (13.0138342234), and the germ length of the node, which
// the two orders' local curves give slightly differently, moves where the march restarts.
double length_tolerance(double a, double b) { return 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)}); }
constexpr double kVertexTolerance = 1e-10;

std::string swapped_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  nlohmann::json scene = nlohmann::json::parse(in);
  for (auto& i : scene["intersections"]) {
    std::reverse(i["surfaces"].begin(), i["surfaces"].end());
    if (i.contains("as")) std::reverse(i["as"].begin(), i["as"].end());
  }
  return scene.dump();
}

// A component as a comparable summary: its closed flags and branch lengths (sorted: branches
// whose lengths differ by less than the tolerance may sort either way, and compare equal either
// way), and its vertices' kinds and points.
struct ComponentKey {
  std::vector<std::pair<bool, double>> branches;
  std::vector<std::pair<VertexKind, Vec3>> vertices;
};

std::vector<ComponentKey> keys(const CurveNetwork& net) {
  std::vector<ComponentKey> out;
  for (const NetworkComponent& c : net.components) {
    ComponentKey k;
    for (int b : c.branches)
      k.branches.push_back(
          {net.branches[static_cast<std::size_t>(b)].closed, net.branches[static_cast<std::size_t>(b)].length});
    for (int v : c.vertices)
      k.vertices.push_back(
          {net.vertices[static_cast<std::size_t>(v)].kind, net.vertices[static_cast<std::size_t>(v)].p});
    std::sort(k.branches.begin(), k.branches.end());
    std::sort(k.vertices.begin(), k.vertices.end(), [](const auto& a, const auto& b) {
      return std::lexicographical_compare(a.second.data(), a.second.data() + 3, b.second.data(), b.second.data() + 3);
    });
    out.push_back(std::move(k));
  }
  return out;
}

bool same_vertices(const ComponentKey& a, const ComponentKey& b) {
  if (a.vertices.size() != b.vertices.size()) return false;
  std::vector<bool> used(b.vertices.size(), false);
  for (const auto& [kind, p] : a.vertices) {
    bool found = false;
    for (std::size_t j = 0; j < b.vertices.size() && !found; ++j)
      if (!used[j] && b.vertices[j].first == kind && (b.vertices[j].second - p).norm() <= kVertexTolerance)
        used[j] = found = true;
    if (!found) return false;
  }
  return true;
}

bool same_component(const ComponentKey& a, const ComponentKey& b) {
  if (a.branches.size() != b.branches.size()) return false;
  for (std::size_t i = 0; i < a.branches.size(); ++i)
    if (a.branches[i].first != b.branches[i].first || std::abs(a.branches[i].second - b.branches[i].second) >
                                                          length_tolerance(a.branches[i].second, b.branches[i].second))
      return false;
  return same_vertices(a, b);
}

void expect_same_network(const CurveNetwork& a, const CurveNetwork& b) {
  ASSERT_EQ(a.branches.size(), b.branches.size());
  ASSERT_EQ(a.components.size(), b.components.size());
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(a.edges.size(), b.edges.size());
  EXPECT_EQ(a.complete(), b.complete());
  std::vector<double> ea, eb;
  for (const NetworkEdge& e : a.edges) ea.push_back(e.length);
  for (const NetworkEdge& e : b.edges) eb.push_back(e.length);
  std::sort(ea.begin(), ea.end());
  std::sort(eb.begin(), eb.end());
  for (std::size_t i = 0; i < std::min(ea.size(), eb.size()); ++i)
    EXPECT_NEAR(ea[i], eb[i], length_tolerance(ea[i], eb[i])) << "edge " << i;
  // Each component of one network matches its own component of the other (components of equal
  // length, e.g. mirror images, are told apart by their vertices).
  const auto ka = keys(a), kb = keys(b);
  std::vector<bool> used(kb.size(), false);
  for (std::size_t c = 0; c < ka.size(); ++c) {
    bool found = false;
    for (std::size_t d = 0; d < kb.size() && !found; ++d)
      if (!used[d] && same_component(ka[c], kb[d])) used[d] = found = true;
    EXPECT_TRUE(found) << "component " << c << " (" << ka[c].branches.size() << " branches, " << ka[c].vertices.size()
                       << " vertices) has no match in the swapped order";
  }
}

class SwapOrder : public ::testing::TestWithParam<std::string> {};

TEST_P(SwapOrder, SameNetwork) {
  const std::filesystem::path file = std::filesystem::path(SSIMARCH_SOURCE_DIR) / GetParam();
  const Scene given = load_scene(file);
  const Scene swapped = parse_scene(swapped_text(file), file.string() + " (surfaces swapped)");
  ASSERT_EQ(given.intersections.size(), swapped.intersections.size());
  for (std::size_t i = 0; i < given.intersections.size(); ++i) {
    const std::string name = GetParam() + ":" + given.intersections[i].name;
    SCOPED_TRACE(name);
    const IntersectionRun a = run_intersection(given, given.intersections[i]);
    const IntersectionRun b = run_intersection(swapped, swapped.intersections[i]);
    expect_same_network(a.network, b.network);
  }
}

// The scenes of a folder of the source tree, as paths relative to it.
std::vector<std::string> scene_files(const std::string& folder) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(SSIMARCH_SOURCE_DIR) / folder))
    if (e.path().extension() == ".json") files.push_back(folder + "/" + e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& file) {
  std::string n = std::filesystem::path(file.param).stem().string();
  std::replace_if(
      n.begin(), n.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return n;
}

INSTANTIATE_TEST_SUITE_P(Examples, SwapOrder, ::testing::ValuesIn(scene_files("examples")), test_name);
// The benchmark pairs (docs/benchmarks.md, peers section: the cases of the peer comparison).
INSTANTIATE_TEST_SUITE_P(BenchmarkPairs, SwapOrder, ::testing::ValuesIn(scene_files("bench/peers/scenes")), test_name);

using testing::simpson;

// Issue 13's case: the rational two-cylinder example (seed 000 Ex. 5) gave 2 curves of total
// length 3.63 in one order and 4 curves of 14.9 in the other. Both orders now give the four
// arcs of the two ellipses x = +-z that the rational parametrisations cover, each ending on
// the v bounds.
TEST(SwapOrder, RationalTwoCylinders) {
  const std::filesystem::path file =
      std::filesystem::path(SSIMARCH_SOURCE_DIR) / "examples" / "s000_ex5_two_cylinders.json";
  const Scene given = load_scene(file);
  const Scene swapped = parse_scene(swapped_text(file), "swapped");
  for (const Scene* s : {&given, &swapped}) {
    const IntersectionRun run = run_intersection(*s, s->intersections[0]);
    ASSERT_EQ(run.result.curves.size(), 4u);
    double total = 0;
    for (const TracedCurve& c : run.result.curves) {
      EXPECT_FALSE(c.closed);
      EXPECT_EQ(c.start_end, Termination::kLeftDomain);
      EXPECT_EQ(c.end_end, Termination::kLeftDomain);
      total += c.length;
    }
    // Each ellipse x = +-z on x^2 + y^2 = 1 = y^2 + z^2 misses two arcs: F's rational circle
    // (v in [-50, 50]) leaves out the angles within g = pi - 2 atan 50 of (y, z) = (-1, 0),
    // G's those within g of (x, y) = (-1, 0); arc elements sqrt(1 + cos^2) and sqrt(1 + sin^2).
    const double g = M_PI - 2 * std::atan(50.0);
    auto element_c = [](double t) { return std::sqrt(1 + std::cos(t) * std::cos(t)); };
    auto element_s = [](double t) { return std::sqrt(1 + std::sin(t) * std::sin(t)); };
    const double expected = 2 * (simpson(element_c, 0, 2 * M_PI) - simpson(element_c, M_PI - g, M_PI + g) -
                                 simpson(element_s, M_PI - g, M_PI + g));
    EXPECT_NEAR(total, expected, 1e-6);
    EXPECT_TRUE(run.network.complete());
  }
}

}  // namespace
}  // namespace ssimarch
