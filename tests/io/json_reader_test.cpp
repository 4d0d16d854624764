// Strict input: every malformed JSON is an InputError naming the file and the JSON path or the
// line:column, and the rule; no exception of the JSON library escapes (issue 13, "Strict input").
#include "ssimarch/io/json_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"

namespace ssimarch {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::AllOf;

std::string parse_error_of(const std::string& text) {
  try {
    parse_json_text(text, "f.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string scene_error_of(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("(not an InputError) ") + e.what();
  }
  return "(no error)";
}

const std::string kSurfaces =
    R"("surfaces": {"a": {"sphere": {"center": [0,0,0], "radius": 1}}, "b": {"implicit": "z", "box": [[-2,2],[-2,2],[-2,2]]}})";

TEST(JsonReader, DuplicateKeysNameTheirPath) {
  EXPECT_EQ(parse_error_of(R"({"a": 1, "a": 2})"), "f.json: a: duplicate key \"a\" (a key may appear only once in an object)");
  EXPECT_THAT(parse_error_of(R"({"x": [0, {"k": 1}, {"k": 1, "k": 2}]})"), HasSubstr("f.json: x[2].k: duplicate key \"k\""));
  EXPECT_THAT(parse_error_of(R"({"x": {"y": {"z": 1}}, "w": {"z": 1, "q": {"z": 2, "z": 3}}})"), HasSubstr("f.json: w.q.z:"));
  // The same key in different objects is fine.
  EXPECT_EQ(parse_error_of(R"({"x": {"k": 1}, "y": {"k": 1}, "z": [{"k": 1}, {"k": 2}]})"), "(no error)");
  EXPECT_THAT(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"surfaces": ["a", "b"], "options": {"tolerance": 1e-9, "tolerance": 1e-8}}]})"),
              HasSubstr("s.json: intersections[0].options.tolerance: duplicate key"));
}

TEST(JsonReader, NumbersOutsideDoubleRange) {
  EXPECT_EQ(parse_error_of("{\n  \"r\": 1e400\n}"), "f.json:2:8: a number outside the range of double precision (about 1.8e308)");
  EXPECT_THAT(parse_error_of("[-1e999]"), HasSubstr("f.json:1:2: a number outside the range"));
}

TEST(JsonReader, TrailingGarbageAndNulBytes) {
  EXPECT_EQ(parse_error_of(std::string("{\"a\": 1}\0", 9)), "f.json:1:9: a NUL byte: JSON text must not contain one");
  EXPECT_EQ(parse_error_of(std::string("{\"a\": 1}\n\0junk", 14)), "f.json:2:1: a NUL byte: JSON text must not contain one");
  EXPECT_THAT(parse_error_of("{\"a\": 1} x"), HasSubstr("f.json:1:10: invalid JSON: syntax error"));
  EXPECT_THAT(parse_error_of("{\"a\": 1}}"), HasSubstr("f.json:1:9: invalid JSON"));
  EXPECT_THAT(parse_error_of("{\"a\": 1 // comment\n}"), "(no error)");
}

TEST(JsonReader, WrongTypesAreInputErrorsWithTheirPath) {
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"name": 5, "surfaces": ["a", "b"]}]})"),
            "s.json: intersections[0].name: expected a name, got a number");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"name": "", "surfaces": ["a", "b"]}]})"),
            "s.json: intersections[0].name: must not be empty");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"surfaces": ["a", 7]}]})"),
            "s.json: intersections[0].surfaces[1]: expected a surface name, got a number");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"surfaces": ["a", "b"], "start": [1, true, 0]}]})"),
            "s.json: intersections[0].start[1]: expected a number or an expression string, got a boolean");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"surfaces": ["a", "b"], "options": {"max_points": [3]}}]})"),
            "s.json: intersections[0].options.max_points: must be an integer in [2, 1e+15], got an array");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"surfaces": ["a", "b"], "options": {"predictor": 3}}]})"),
            "s.json: intersections[0].options.predictor: expected a predictor name (one of tangent, circle, circle-wu-andrade, "
            "parabola, polynomial, helix, taylor), got a number");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [{"surfaces": ["a", "b"], "options": 3}]})"),
            "s.json: intersections[0].options: must be an object, got a number");
  EXPECT_EQ(scene_error_of("{" + kSurfaces + R"(, "intersections": [7]})"), "s.json: intersections[0]: must be an object, got a number");
  EXPECT_EQ(scene_error_of(R"({"constants": {"R": [1]}, )" + kSurfaces + "}"),
            "s.json: constants.R: expected a number or an expression string, got an array");
}

TEST(JsonReader, ReadTextFileReportsEveryFailureWithThePath) {
  EXPECT_THROW(read_text_file("/nonexistent/x.json", "scene file"), InputError);
  try {
    read_text_file("/", "scene file");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/: is a directory, not a scene file");
  }
}

TEST(JsonReader, IntervalsTooNarrowForDoublePrecisionAreRejected) {
  // A periodic domain of width 5e-324 gave null parameters; 1e-10 relative keeps samples distinct.
  const std::string surface = R"({"surfaces": {"s": {"parametric": ["u", "v", "0"], "u": [0, 5e-324], "v": [0, 1],
                                                     "periodic": ["u"]}}})";
  EXPECT_THAT(scene_error_of(surface), AllOf(HasSubstr("surfaces.s.u: interval [0, 4.94"), HasSubstr("is too narrow for double precision")));
  EXPECT_THAT(scene_error_of(R"({"surfaces": {"s": {"parametric": ["u", "v", "0"], "u": [1e6, 1.0000000000001e6], "v": [0, 1]}}})"),
              HasSubstr("at least 1e-10 times its largest endpoint"));
  EXPECT_THAT(scene_error_of(R"({"surfaces": {"s": {"parametric": ["u", "v", "0"], "u": [0, 1e-9], "v": [0, 1]}}})"),
              Not(HasSubstr("too narrow")));
}

TEST(JsonReader, ReadTextFileStopsAtItsSizeLimit) {
  // A device is refused before a byte is read (issue 29): /dev/zero has no end.
  try {
    read_text_file("/dev/zero", "scene file", 1 << 20);
    FAIL() << "/dev/zero was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("/dev/zero: is a device or socket, not a scene file"));
  }
  // A file larger than the limit stops the reader at the limit, naming the flag that raises it.
  const auto path = std::filesystem::temp_directory_path() / "ssimarch_json_reader_limit.json";
  { std::ofstream(path) << std::string(2000, ' ') << "{}"; }
  try {
    read_text_file(path, "scene file", 1000);
    FAIL() << "the file was read past the limit";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("larger than 1000 bytes, the limit for a scene file"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--max-input-mb"));
  }
  EXPECT_EQ(read_text_file(path, "scene file", 4096).size(), 2002u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ssimarch
