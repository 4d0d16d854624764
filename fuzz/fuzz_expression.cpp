// libFuzzer target: the expression compiler and evaluator (docs/expressions.md). Any input must
// compile or fail with a ParseError, and a compiled program must evaluate in double and in jets
// without a sanitizer report. docs/reliability.md, "Fuzzing".
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/expr/program.hpp"
#include "ssimarch/expr/referenced_names.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view source(reinterpret_cast<const char*>(data), size);
  static const std::vector<std::string> variables = {"u", "v", "x", "y", "z"};
  static const ssimarch::Constants constants = {{"R", 2.0}, {"r", 0.5}, {"tiny", 1e-300}};
  (void)ssimarch::referenced_names(source);
  ssimarch::Program p;
  ssimarch::ParseError error;
  if (!ssimarch::Program::compile(source, variables, constants, &p, &error)) {
    (void)error.format(source);
    return 0;
  }
  for (const std::array<double, 5>& at : {std::array<double, 5>{0, 0, 0, 0, 0}, std::array<double, 5>{0.3, -1.7, 1e300, -2, 5e-324}})
    (void)p.eval(at);
  using J = ssimarch::Jet<2, 3>;
  const std::array<J, 5> jets = {J::variable(0, 0.25), J::variable(1, -0.5), J(1.0), J(-1.0), J(0.0)};
  (void)p.eval(jets);
  (void)p.disassemble();
  return 0;
}
