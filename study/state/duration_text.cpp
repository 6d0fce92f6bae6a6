#include "study/state/duration_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace capsule::study {

std::string format_duration(double s) {
  if (!std::isfinite(s)) return "?";
  char text[32];
  const long t = std::lround(std::max(0.0, s));
  if (t >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  else if (t >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", t / 60, t % 60);
  else std::snprintf(text, sizeof text, "%lds", t);
  return text;
}

}  // namespace capsule::study
