// Library input errors reported in the CLI's terms: a job field that a flag sets (the error's
// location, e.g. "container_radius") is named by that flag ("--container-radius: must be ...").
#pragma once

#include <map>
#include <string>

#include "commands.hpp"
#include "ssimarch/core/error.hpp"

namespace ssimarch::cli {

/// `flag_of` maps job field names to the flags that set them; other errors keep their location.
inline CliError flag_error(const InputError& e, const std::map<std::string, std::string>& flag_of) {
  const auto flag = flag_of.find(e.where());
  if (flag != flag_of.end()) return CliError(flag->second + ": " + e.message());
  return CliError(e.what());
}

}  // namespace ssimarch::cli
