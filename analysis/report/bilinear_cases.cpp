#include "analysis/report/bilinear_cases.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/fit/bilinear_fit.hpp"
#include "analysis/report/resolution_ladder.hpp"
#include "analysis/report/table.hpp"

namespace capsule::analysis {

std::vector<std::string> case_names(const std::vector<MemberAnalysis>& members) {
  std::vector<std::string> cases;
  for (const auto& m : members)
    if (std::find(cases.begin(), cases.end(), m.ref.case_name) == cases.end()) cases.push_back(m.ref.case_name);
  return cases;
}

namespace {

std::string short_key(const std::string& dotted) { return dotted.substr(dotted.rfind('.') + 1); }

CaseBilinear fit_group(const std::string& case_name, const std::string& target,
                       const std::vector<const MemberAnalysis*>& group) {
  CaseBilinear b;
  b.case_name = case_name;
  b.target = target;
  b.group = group;
  for (const auto* m : group) {
    const ColumnValue v = column_value(m->fits, target);
    const double e = parameter(*m, "eta"), vv = parameter(*m, "V");
    if (!v.parameter || std::isnan(e) || std::isnan(vv)) {
      b.excluded.push_back(m->ref.slug + ": " + (!v.parameter ? v.reason : std::string("eta or V not found in the scene")));
      continue;
    }
    b.eta.push_back(e);
    b.V.push_back(vv);
    b.k_tau.push_back(v.parameter->value);
    b.used.push_back(m->ref.slug);
  }
  b.fit = fit_bilinear(b.eta, b.V, b.k_tau);
  return b;
}

}  // namespace

std::string level_label(const CaseBilinear& b) {
  return b.level_key.empty() ? std::string() : short_key(b.level_key) + " = " + format_number(b.level);
}

std::vector<CaseBilinear> bilinear_per_case(const ReportContext& context, std::vector<std::string>* unplaced) {
  std::vector<CaseBilinear> out;
  if (!context.block.bilinear) return out;
  const BilinearSpec& spec = *context.block.bilinear;
  for (const auto& c : case_names(context.members)) {
    std::vector<const MemberAnalysis*> group;
    for (const auto& m : context.members)
      if (m.ref.case_name == c) group.push_back(&m);
    if (spec.ladder.empty()) {
      for (const auto& target : spec.targets) out.push_back(fit_group(c, target, group));
      continue;
    }
    // Split the case by the ladder key's value, finest level (smallest h) first.
    std::vector<double> levels;
    for (const auto* m : group) {
      const double x = parameter(*m, spec.ladder);
      if (std::isnan(x) || std::isnan(ladder_spacing(spec.spacing, x))) {
        if (unplaced) unplaced->push_back(m->ref.slug + ": no level (" + spec.ladder + " not a number giving h > 0)");
        continue;
      }
      if (std::find(levels.begin(), levels.end(), x) == levels.end()) levels.push_back(x);
    }
    std::sort(levels.begin(), levels.end(), [&](double p, double q) {
      return ladder_spacing(spec.spacing, p) < ladder_spacing(spec.spacing, q);
    });
    for (const double x : levels) {
      std::vector<const MemberAnalysis*> at_level;
      for (const auto* m : group)
        if (parameter(*m, spec.ladder) == x) at_level.push_back(m);
      for (const auto& target : spec.targets) {
        CaseBilinear b = fit_group(c, target, at_level);
        b.level_key = spec.ladder;
        b.level = x;
        out.push_back(std::move(b));
      }
    }
  }
  return out;
}

std::vector<CoefficientLadder> bilinear_ladders(const ReportContext& context, const std::vector<CaseBilinear>& fits) {
  std::vector<CoefficientLadder> out;
  if (!context.block.bilinear || context.block.bilinear->ladder.empty()) return out;
  const BilinearSpec& spec = *context.block.bilinear;
  for (const auto& c : case_names(context.members)) {
    for (const auto& target : spec.targets) {
      for (const char* name : {"a", "b", "c"}) {
        CoefficientLadder cl;
        cl.case_name = c;
        cl.target = target;
        cl.coefficient = name;
        std::vector<LadderLevel> levels;
        for (const CaseBilinear& b : fits) {  // finest first, as bilinear_per_case orders them
          if (b.case_name != c || b.target != target || b.level_key.empty()) continue;
          const FitParameter* p = b.fit.ok ? b.fit.parameter(name) : nullptr;
          if (!p) {
            cl.skipped.push_back(level_label(b) + ": " + (b.fit.ok ? "no coefficient " + std::string(name) : b.fit.reason));
            continue;
          }
          cl.levels.emplace_back(b.level, p->value);
          levels.push_back({ladder_spacing(spec.spacing, b.level), p->value});
        }
        if (levels.empty()) {
          cl.result.reason = "no level with a bilinear fit";
        } else {
          cl.result = richardson(levels, spec.assumed_order);
        }
        out.push_back(std::move(cl));
      }
    }
  }
  return out;
}

}  // namespace capsule::analysis
