#pragma once
// Short texts the solver writes into messages and member files: a number as a message quotes it
// (six significant digits, no trailing zeros), and the current UTC time as ISO 8601.
#include <ctime>
#include <sstream>
#include <string>

namespace capsule {

inline std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

inline std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace capsule
