// Messages joined by a stream: GCC 12 warns falsely (-Wrestrict) on chains of std::string +
// at -O3 (GCC bug 105651), which the ci preset turns into errors.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace ssimarch::internal {

template <class... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream o;
  (o << ... << parts);
  return o.str();
}

/// "a, b, c": the names a message lists.
inline std::string join_names(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

}  // namespace ssimarch::internal
