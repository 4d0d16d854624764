#include "ssimarch/march/model_size.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace ssimarch {

double resolved_tolerance(const TraceOptions& options, double scale) {
  return options.tolerance == 0 ? kAutomaticToleranceRatio * scale : options.tolerance;
}

double step_floor(double scale, double tolerance) {
  return std::max(8 * tolerance, 64 * std::numeric_limits<double>::epsilon() * scale);
}

bool fits_model(const TraceOptions& o, double scale, std::string* key, std::string* error) {
  auto text = [](double x) {
    std::ostringstream os;
    os.precision(3);
    os << x;
    return os.str();
  };
  auto fail = [&](const char* k, const std::string& m) {
    if (key) *key = k;
    if (error) *error = m;
    return false;
  };
  const std::string model = "the model size (diagonal of its region) " + text(scale);
  if (!(scale >= kMinModelSize && scale <= kMaxModelSize))
    return fail("model size", model + " is outside [" + text(kMinModelSize) + ", " + text(kMaxModelSize) +
                                  "], the sizes whose products double precision represents; scale the scene");
  const double eps = std::numeric_limits<double>::epsilon();
  const double tol_lo = eps * scale, tol_hi = kMaxToleranceRatio * scale;
  const double tolerance = resolved_tolerance(o, scale);
  if (!(tolerance >= tol_lo && tolerance <= tol_hi))
    return fail("tolerance", text(tolerance) + " is outside [" + text(tol_lo) + ", " + text(tol_hi) +
                                 "], the usable range for " + model +
                                 " in double precision (from the rounding of the coordinates to a thousandth of the " +
                                 "model); 0 = automatic, " + text(kAutomaticToleranceRatio) + " times the size");
  const double floor = step_floor(scale, tolerance);
  const std::pair<const char*, double> lengths[] = {
      {"step_length", o.step_length}, {"min_step_length", o.min_step_length}, {"min_step", o.min_step}, {"max_length", o.max_length}};
  for (const auto& [k, v] : lengths)
    if (v != 0 && v < floor)
      return fail(k, text(v) + " is below " + text(floor) + ", the shortest step for " + model + " and tolerance " +
                         text(tolerance) + " (max(8 tolerance, 64 eps size)); usable: >= " + text(floor) +
                         " (or 0 = automatic)");
  return true;
}

}  // namespace ssimarch
