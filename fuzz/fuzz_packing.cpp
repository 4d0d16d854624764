// libFuzzer target: the packing readers (CSV and LAMMPS dump, docs/porosity.md). The first byte
// chooses the reader; any input must be read or rejected with an InputError. Readers run with
// small limits so that the fuzzer also reaches the size checks. docs/reliability.md.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/porosity/overlaps.hpp"
#include "ssimarch/porosity/packing.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  ssimarch::InputLimits limits;
  limits.max_packing_bytes = 1 << 20;
  limits.max_line_bytes = 1 << 10;
  try {
    const ssimarch::Packing p = (data[0] & 1) ? ssimarch::read_lammps_dump(in, "fuzz.dump", limits)
                                              : ssimarch::read_packing_csv(in, "fuzz.csv", limits);
    (void)ssimarch::find_overlaps(p.particles);
  } catch (const ssimarch::InputError&) {
  }
  return 0;
}
