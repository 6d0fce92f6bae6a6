#include "analysis/compare/bilinear_entries.hpp"

#include <cmath>
#include <limits>

#include "analysis/report/table.hpp"

namespace capsule::analysis {

namespace {
double number_or_nan(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
}
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
      if (l.value("ok", false)) {
        be.ladder_error[coef] = number_or_nan(l, "error_estimate");
        be.ladder_extrapolated[coef] = number_or_nan(l, "extrapolated");
      }
      // The next coarser level: of the other levels, the value nearest this entry's.
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& lv : l.value("levels", nlohmann::json::array())) {
        const double value = number_or_nan(lv, "value"), distance = std::abs(value - be.level);
        if (!(distance > 1e-12) || !(distance < nearest)) continue;
        nearest = distance;
        be.ladder_coarser[coef] = number_or_nan(lv, "coefficient");
      }
      be.ladder_note[coef] = l.value("note", "");
      break;
    }
  }
  return out;
}

bool intervals_overlap(double lo1, double hi1, double lo2, double hi2) { return lo1 <= hi2 && lo2 <= hi1; }

std::string plus_minus(double value, double half_width) {
  return format_number(value) + " ± " + format_number(half_width);
}

}  // namespace capsule::analysis
