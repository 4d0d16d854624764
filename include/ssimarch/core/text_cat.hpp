// Messages joined by a stream: GCC 12 warns falsely (-Wrestrict) on chains of std::string +
// at -O3 (GCC bug 105651), which the ci preset turns into errors.
#pragma once

#include <sstream>
#include <string>

namespace ssimarch::internal {

template <class... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream o;
  (o << ... << parts);
  return o.str();
}

}  // namespace ssimarch::internal
