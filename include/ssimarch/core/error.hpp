// Errors for invalid input (files, expressions, options). Numeric outcomes are never exceptions:
// they are status values (style.md 3.9). InputError says what is wrong and where: `where` is a
// location a user can find (a file:line:column, a JSON path such as surfaces.cyl.radius, or an
// option name). It is a runtime error, not a logic error: the library's own broken preconditions
// are ContractViolation (core/contract.hpp), which front ends report as internal errors.
#pragma once

#include <stdexcept>
#include <string>

namespace ssimarch {

class InputError : public std::runtime_error {
 public:
  InputError(std::string where, const std::string& message)
      : std::runtime_error(where.empty() ? message : where + ": " + message),
        where_(std::move(where)),
        message_(message) {}
  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string where_;
  std::string message_;
};

}  // namespace ssimarch
