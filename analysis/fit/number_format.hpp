#pragma once
// Number formatting shared by every table and by the fits' messages: 6 significant digits.
#include <string>

namespace capsule::analysis {

// "%.6g" of x; "" for NaN and infinities.
std::string format_number(double x);

}  // namespace capsule::analysis
