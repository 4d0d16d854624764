// Programmer errors, kept apart from the user's: a broken precondition of the library's own code
// (a caller passed what the function documents it never takes) is a ContractViolation, thrown by
// SSIMARCH_EXPECTS; bad user input is an InputError (core/error.hpp) naming where it is. The CLI
// reports a violation as an internal error (exit status 3) and the batch job as its unit's
// "internal error"; tests can provoke one. Numeric outcomes are neither: they are status values.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace ssimarch {

/// A precondition of the library's code that its caller broke: a bug, never the user's input.
class ContractViolation : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace internal {
[[noreturn]] inline void contract_violated(const char* condition, std::string_view message, const char* file,
                                           int line) {
  std::string what(file);
  what += ':';
  what += std::to_string(line);
  what += ": ";
  what += message;
  what += " (expected ";
  what += condition;
  what += ')';
  throw ContractViolation(what);
}
}  // namespace internal

}  // namespace ssimarch

/// Checks a precondition of the library's own code; throws ssimarch::ContractViolation naming the
/// file, line, message and condition when it does not hold. Always on (also in release builds):
/// the checks guard cheap, rare entry points, never inner loops.
#define SSIMARCH_EXPECTS(condition, message) \
  ((condition) ? void(0) : ::ssimarch::internal::contract_violated(#condition, (message), __FILE__, __LINE__))

/// A branch the library's own code never takes (a surface asked for a form it does not have);
/// throws ssimarch::ContractViolation naming the file, line and message.
#define SSIMARCH_CONTRACT_FAILURE(message) \
  ::ssimarch::internal::contract_violated("this branch is never taken", (message), __FILE__, __LINE__)
