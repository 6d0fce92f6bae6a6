#include "analysis/table2_compare.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/table.hpp"

namespace capsule::analysis {

namespace {
double number_or_nan(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
}
bool same(double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(y)); }  // parsed decimals
}  // namespace

std::vector<BilinearEntry> read_bilinear_entries(const std::string& campaign, const nlohmann::json& fits) {
  std::vector<BilinearEntry> out;
  for (const auto& b : fits.value("bilinear", nlohmann::json::array())) {
    BilinearEntry be;
    be.campaign = campaign;
    be.case_name = b.value("case", "");
    be.target = b.value("target", "");
    be.Ca = number_or_nan(b, "Ca");
    be.E_b = number_or_nan(b, "E_b");
    be.fit = fit_result_from_json(b.at("fit"));
    if (b.contains("level") && b["level"].is_object()) {
      be.level_key = b["level"].value("key", "");
      be.level = number_or_nan(b["level"], "value");
    }
    out.push_back(be);
  }
  // The ladder's estimates belong to the finest level, the first entry of each case and target.
  for (const auto& l : fits.value("bilinear_ladder", nlohmann::json::array())) {
    const std::string case_name = l.value("case", ""), target = l.value("target", ""), coef = l.value("coefficient", "");
    for (auto& be : out) {
      if (be.case_name != case_name || be.target != target) continue;
      if (l.value("ok", false)) be.ladder_error[coef] = number_or_nan(l, "error_estimate");
      be.ladder_note[coef] = l.value("note", "");
      break;
    }
  }
  return out;
}

std::string bare_time(const std::string& target) {
  const auto dot = target.find('.');
  return dot == std::string::npos ? target : target.substr(dot + 1);
}

const Table2Row* table2_row_for(const BilinearEntry& entry) {
  for (const auto& r : table2_dissertation())
    if (r.target == bare_time(entry.target) && same(entry.Ca, r.Ca) && same(entry.E_b, r.E_b)) return &r;
  return nullptr;
}

bool intervals_overlap(double lo1, double hi1, double lo2, double hi2) { return lo1 <= hi2 && lo2 <= hi1; }

std::vector<CoefficientComparison> compare_with_table2(const FitResult& fit, const Table2Row& ref) {
  const std::pair<double, double> refs[] = {{ref.a, ref.a_half_width}, {ref.b, ref.b_half_width}, {ref.c, ref.c_half_width}};
  const char* names[] = {"a", "b", "c"};
  std::vector<CoefficientComparison> out;
  for (int i = 0; i < 3; ++i) {
    CoefficientComparison c;
    c.name = names[i];
    c.reference = refs[i].first;
    c.reference_half_width = refs[i].second;
    const FitParameter* p = fit.ok ? fit.parameter(names[i]) : nullptr;
    if (!p) {
      c.reason = fit.ok ? std::string("fit has no ") + names[i] : fit.reason;
    } else {
      c.measured = true;
      c.value = p->value;
      c.half_width = p->half_width();
      c.difference = p->value - c.reference;
      c.overlap = intervals_overlap(p->ci_low, p->ci_high, c.reference - c.reference_half_width,
                                    c.reference + c.reference_half_width);
    }
    out.push_back(c);
  }
  return out;
}

std::string plus_minus(double value, double half_width) {
  return format_number(value) + " ± " + format_number(half_width);
}

}  // namespace capsule::analysis
