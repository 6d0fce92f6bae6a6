#include "solver/common/atomic_write.hpp"
#include "analysis/dissertation/table2_compare.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "analysis/report/table.hpp"

namespace capsule::analysis {

namespace {
bool same(double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(y)); }  // parsed decimals
}  // namespace

std::string bare_time(const std::string& target) {
  const auto dot = target.find('.');
  return dot == std::string::npos ? target : target.substr(dot + 1);
}

const Table2Row* table2_row_for(const BilinearEntry& entry) {
  for (const auto& r : table2_dissertation())
    if (r.target == bare_time(entry.target) && same(entry.Ca, r.Ca) && same(entry.E_b, r.E_b)) return &r;
  return nullptr;
}

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

std::string table2_comparison(const std::vector<std::vector<BilinearEntry>>& all, int& status,
                              const std::string& out_dir, std::ostream& out) {
  Table t2;
  t2.title = "Against the dissertation's Table 2 (Sec. 5.1.1; ± = 95 % half-width)";
  t2.header = {"campaign", "case", "target", "Ca", "E_b", "coefficient", "this work", "Table 2", "difference",
               "95% overlap"};
  for (const auto& campaign : all)
    for (const auto& b : campaign) {
      const Table2Row* ref = table2_row_for(b);
      if (!ref) {
        t2.rows.push_back({b.campaign, b.case_name, b.target, format_number(b.Ca), format_number(b.E_b), "",
                           "", "no Table 2 row for this target, Ca and E_b", "", ""});
        continue;
      }
      for (const CoefficientComparison& c : compare_with_table2(b.fit, *ref)) {
        std::vector<std::string> row{b.campaign, b.case_name, b.target, format_number(b.Ca), format_number(b.E_b),
                                     c.name};
        if (!c.measured) {
          row.insert(row.end(), {"n/a: " + c.reason, plus_minus(c.reference, c.reference_half_width), "", ""});
        } else {
          if (!c.overlap) status = 1;
          row.insert(row.end(), {plus_minus(c.value, c.half_width), plus_minus(c.reference, c.reference_half_width),
                                 format_number(c.difference), c.overlap ? "yes" : "NO"});
        }
        t2.rows.push_back(row);
      }
    }
  capsule::write_file_atomically(std::filesystem::path(out_dir) / "compare_table2.csv", t2.to_csv());
  out << "\n" << t2.to_markdown();
  return "\n" + t2.to_markdown();
}

}  // namespace capsule::analysis
