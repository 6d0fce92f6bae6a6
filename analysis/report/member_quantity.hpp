#pragma once
// One number of a member for the ladder and accuracy analyses: a fitted time
// ("response.k_tau_s") or a marker ("D_stop": the steady D_xy of a shear to steady state).
#include <string>

#include "analysis/report/report_context.hpp"

namespace capsule::analysis {

struct QuantityValue {
  bool found = false;
  double value = 0.0;
  std::string reason;  // why there is no number
};

QuantityValue member_quantity(const MemberAnalysis& m, const std::string& quantity);

}  // namespace capsule::analysis
