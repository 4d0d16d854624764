// libFuzzer target: the scene reader (docs/scene-format.md). Any input must be read or rejected
// with an InputError; no other exception, crash or sanitizer report. docs/reliability.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)ssimarch::parse_scene(text, "fuzz.json");
  } catch (const ssimarch::InputError&) {
  }
  return 0;
}
