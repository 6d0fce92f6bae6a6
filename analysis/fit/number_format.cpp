#include "analysis/fit/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace capsule::analysis {

std::string format_number(double x) {
  if (!std::isfinite(x)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace capsule::analysis
