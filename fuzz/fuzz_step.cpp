// libFuzzer target: the STEP reader (docs/cad.md). Any input must be read or rejected with an
// InputError; no other exception, crash or sanitizer report. Every face's surface and the
// first instances as surfaces and B-spline curves are built too. docs/reliability.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/step/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const ssimarch::StepModel model(ssimarch::parse_step(text, "fuzz.step"));
    for (const auto& face : model.faces()) {
      try {
        (void)model.surface(face.entity);
      } catch (const ssimarch::InputError&) {
      }
    }
    std::size_t tried = 0;
    for (std::int64_t id : model.file().order) {
      if (++tried > 64) break;
      try {
        (void)model.surface(id);
      } catch (const ssimarch::InputError&) {
      }
      try {
        (void)model.bspline_curve(id);
      } catch (const ssimarch::InputError&) {
      }
    }
  } catch (const ssimarch::InputError&) {
  }
  return 0;
}
