#include "analysis/report/member_quantity.hpp"

#include <algorithm>
#include <cmath>

namespace capsule::analysis {

QuantityValue member_quantity(const MemberAnalysis& m, const std::string& quantity) {
  QuantityValue q;
  const auto& markers = marker_quantities();
  if (std::find(markers.begin(), markers.end(), quantity) != markers.end()) {
    if (m.status != "complete") {
      q.reason = incomplete_reason(m);
      return q;
    }
    const auto it = m.markers.find(quantity);
    if (it == m.markers.end() || !std::isfinite(it->second)) {
      q.reason = "marker " + quantity + " not reached";
      return q;
    }
    q.found = true;
    q.value = it->second;
    return q;
  }
  const ColumnValue v = column_value(m.fits, quantity);
  if (!v.parameter) {
    q.reason = v.reason;
    return q;
  }
  q.found = true;
  q.value = v.parameter->value;
  return q;
}

}  // namespace capsule::analysis
