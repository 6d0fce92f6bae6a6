#include "analysis/bilinear_cases.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/bilinear_fit.hpp"

namespace capsule::analysis {

std::vector<std::string> case_names(const std::vector<MemberAnalysis>& members) {
  std::vector<std::string> cases;
  for (const auto& m : members)
    if (std::find(cases.begin(), cases.end(), m.ref.case_name) == cases.end()) cases.push_back(m.ref.case_name);
  return cases;
}

std::vector<CaseBilinear> bilinear_per_case(const ReportContext& context) {
  std::vector<CaseBilinear> out;
  if (!context.block.bilinear) return out;
  for (const auto& c : case_names(context.members)) {
    std::vector<const MemberAnalysis*> group;
    for (const auto& m : context.members)
      if (m.ref.case_name == c) group.push_back(&m);
    for (const auto& target : context.block.bilinear->targets) {
      CaseBilinear b;
      b.case_name = c;
      b.target = target;
      b.group = group;
      for (const auto* m : group) {
        const ColumnValue v = column_value(m->fits, target);
        const double e = parameter(*m, "eta"), vv = parameter(*m, "V");
        if (!v.parameter || std::isnan(e) || std::isnan(vv)) {
          b.excluded.push_back(m->ref.slug + ": " +
                               (!v.parameter ? v.reason : std::string("eta or V not found in the scene")));
          continue;
        }
        b.eta.push_back(e);
        b.V.push_back(vv);
        b.k_tau.push_back(v.parameter->value);
        b.used.push_back(m->ref.slug);
      }
      b.fit = fit_bilinear(b.eta, b.V, b.k_tau);
      out.push_back(std::move(b));
    }
  }
  return out;
}

}  // namespace capsule::analysis
