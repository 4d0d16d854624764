// Viewer pages (io/html_writer): the page data of a trace holds display meshes on the scene's
// surfaces and its start points; the page inlines script and data safely; bad input is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/html_writer.hpp"
#include "ssimarch/io/scene.hpp"

namespace ssimarch {
namespace {

constexpr const char* kScene = R"({
  "surfaces": {
    "sphere": {"sphere": {"center": [0, 0, 0], "radius": 2}},
    "cyl": {"implicit": "x^2 + (y+1)^2 - 1", "box": [[-1.5, 1.5], [-2.5, 0.5], [-2.5, 2.5]]}
  },
  "intersections": [{"name": "viviani", "surfaces": ["sphere", "cyl"], "start": [1, -1, 1.4142135623730951]}]
})";

nlohmann::json result_naming(const char* a, const char* b) {
  return {{"intersections", {{{"name", "viviani"}, {"surfaces", nlohmann::json::array({a, b})}, {"curves", nlohmann::json::array()}}}}};
}

TEST(HtmlWriter, TracePageHasMeshesOnTheSurfacesAndTheStartPoints) {
  const Scene scene = parse_scene(kScene, "scene.json");
  const nlohmann::json data = trace_page_data(result_naming("sphere", "cyl"), &scene, "t", {.grid = 16, .cells = 24});
  EXPECT_EQ(data["kind"], "trace");
  const auto& sphere = data["surfaces"]["sphere"];
  EXPECT_EQ(sphere["form"], "parametric");
  EXPECT_EQ(sphere["positions"].size(), 3u * 17 * 17);
  const auto& cyl = data["surfaces"]["cyl"];
  EXPECT_EQ(cyl["form"], "implicit");
  ASSERT_GT(cyl["triangles"].size(), 300u);
  const auto& p = cyl["positions"];
  for (std::size_t i = 0; i < p.size(); i += 3) {  // on x^2 + (y+1)^2 = 1 up to the display rounding (1e-5 of 2.5)
    const double x = p[i], y = p[i + 1];
    ASSERT_NEAR(std::hypot(x, y + 1), 1.0, 3e-5);
  }
  for (const auto& t : cyl["triangles"]) ASSERT_LT(t.get<std::size_t>(), p.size() / 3);
  ASSERT_EQ(data["starts"]["viviani"].size(), 1u);
  EXPECT_DOUBLE_EQ(data["starts"]["viviani"][0][2].get<double>(), 1.4142135623730951);
  // Without a scene: no meshes, no start points.
  EXPECT_TRUE(trace_page_data(result_naming("sphere", "cyl"), nullptr, "t")["surfaces"].empty());
}

TEST(HtmlWriter, RefusesResultsItCannotShow) {
  const Scene scene = parse_scene(kScene, "scene.json");
  EXPECT_THROW(trace_page_data(nlohmann::json{{"curves", 1}}, &scene, "t"), InputError);
  EXPECT_THROW(trace_page_data(result_naming("sphere", "torus"), &scene, "t"), InputError);  // not in the scene
}

TEST(HtmlWriter, PageInlinesScriptAndDataSafely) {
  const nlohmann::json data = {{"kind", "trace"}, {"title", "a < b & c"}, {"note", "</script><b>"}};
  std::ostringstream out;
  write_viewer_page(out, data, "console.log(1)");
  const std::string page = out.str();
  EXPECT_NE(page.find("<title>a &lt; b &amp; c - ssimarch viewer</title>"), std::string::npos);
  EXPECT_NE(page.find(R"("note":"<\/script><b>")"), std::string::npos);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_NE(page.find("<script>console.log(1)</script>"), std::string::npos);
  EXPECT_EQ(page.find("src="), std::string::npos);  // nothing to fetch
  // The data reads back as the same JSON.
  const auto a = page.find("id=\"ssimarch-data\">") + 19, b = page.find("</script>", a);
  EXPECT_EQ(nlohmann::json::parse(page.substr(a, b - a)), data);
  std::ostringstream sink;
  EXPECT_THROW(write_viewer_page(sink, data, ""), std::logic_error);
  EXPECT_THROW(write_viewer_page(sink, data, "x = '</script>'"), std::logic_error);
}

}  // namespace
}  // namespace ssimarch
