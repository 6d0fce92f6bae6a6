#pragma once
// Durations for people: "2h05m", "5m12s", "42s".
#include <string>

namespace capsule::study {
std::string format_duration(double seconds);
}  // namespace capsule::study
