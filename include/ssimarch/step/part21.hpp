// The clear-text encoding of STEP exchange files (ISO 10303-21 "Part 21"): the syntax only, no
// schema. A file is HEADER and DATA sections of entity instances
//   #12=CARTESIAN_POINT('',(0.,1.5,-2.E-3));                          simple instance
//   #13=(BOUNDED_SURFACE()B_SPLINE_SURFACE(2,2,(...),...)SURFACE());  complex instance
// whose parameters are: $ (unset), * (derived), integers, reals, 'strings' (quote doubled),
// .ENUMS. (booleans .T./.F./.U. too), #references, "binary", (lists) and typed parameters
// such as LENGTH_MEASURE(2.5) (ISO 10303-21 §6-§10).
//
// Reading is bounded so that any input ends in a value or an InputError naming file:line: the
// file size (InputLimits::max_step_bytes), the nesting of lists and typed parameters
// (kMaxStepNesting) and instance ids (< 2^53). References are not resolved here; the semantic
// reader (step/reader.hpp) resolves them with `at`, which names the referring instance.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "ssimarch/core/input_limits.hpp"

namespace ssimarch {

/// Deepest nesting of lists and typed parameters in one instance (a B-spline surface's control
/// net is 3 deep; the limit only stops hostile input from exhausting the stack).
inline constexpr int kMaxStepNesting = 64;

struct StepValue {
  enum class Kind { kUnset, kDerived, kInteger, kReal, kString, kEnum, kRef, kBinary, kList, kTyped };
  Kind kind = Kind::kUnset;
  double number = 0;             // kInteger, kReal
  std::int64_t ref = 0;          // kRef: the instance id
  std::string text;              // kString (quotes undoubled), kEnum (without dots), kBinary, kTyped (type name)
  std::vector<StepValue> items;  // kList; kTyped: its parameters

  bool is_number() const { return kind == Kind::kInteger || kind == Kind::kReal; }
};

/// One entity of an instance: its type name (upper case as written) and its parameters.
struct StepRecord {
  std::string type;
  std::vector<StepValue> params;
};

/// An entity instance: one record (simple) or several (complex, in the file's order).
struct StepInstance {
  std::int64_t id = 0;
  int line = 0;  // line of '#id=' in the file (1-based)
  std::vector<StepRecord> records;

  /// The record of this type, or nullptr.
  const StepRecord* record(const std::string& type) const;
  /// The first record's type for a simple instance; "(A B C)" for a complex one.
  std::string type_text() const;
};

class StepFile {
 public:
  std::string source;                // file name used in messages
  std::vector<std::string> schemas;  // FILE_SCHEMA of the header
  std::vector<std::int64_t> order;   // instance ids in file order

  /// "file:line: #id" of an instance, the prefix of every message about it.
  std::string where(const StepInstance& inst) const;
  const StepInstance* find(std::int64_t id) const;
  /// The instance `id`; throws InputError naming `from` (the referring instance) when absent.
  const StepInstance& at(std::int64_t id, const StepInstance& from) const;
  std::size_t size() const { return instances_.size(); }

  /// Adds an instance; throws InputError on a duplicate id.
  void add(StepInstance inst);

 private:
  std::unordered_map<std::int64_t, StepInstance> instances_;
};

/// Parses Part 21 text. Throws InputError("source:line", ...) on a syntax error, a duplicate
/// instance id, nesting deeper than kMaxStepNesting or an id of 2^53 or more.
StepFile parse_step(const std::string& text, const std::string& source);

/// Reads and parses a file; also throws InputError for a missing file or one larger than
/// limits.max_step_bytes.
StepFile read_step_file(const std::filesystem::path& path, const InputLimits& limits = {});

}  // namespace ssimarch
