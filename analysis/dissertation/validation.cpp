#include "analysis/dissertation/validation.hpp"

#include <cmath>

#include "analysis/dissertation/rules.hpp"

namespace capsule::analysis {

namespace {

double number(const nlohmann::json& e, const char* key) {
  return e.contains(key) && e[key].is_number() ? e[key].get<double>() : std::nan("");
}

std::string percent(double x) {
  if (!std::isfinite(x)) return "";
  return (x >= 0 ? "+" : "") + format_number(std::round(1000.0 * x) / 10.0) + " %";
}

}  // namespace

const std::vector<std::string>& validation_campaigns() {
  static const std::vector<std::string> c = {"ch2_3d_ca"};
  return c;
}

Table validation_table(const DissertationResults& results) {
  Table t;
  t.title = "Members against published curves during the shear (report section \"published\")";
  t.header = {"campaign", "curve", "member", "points", "bias D_xy", "max |dD_xy|", "max |dD_extent|",
              "D curve (last point)", "D_xy there", "D_xy / curve - 1", "within digitising error", "note"};
  for (const auto& name : validation_campaigns()) {
    const DissertationCampaign& c = results.campaign(name);
    if (!c.found) {
      t.rows.push_back({name, "", "", "", "", "", "", "", "", "", "cannot tell", c.missing});
      continue;
    }
    if (!c.fits.contains("published") || !c.fits["published"].is_array() || c.fits["published"].empty()) {
      t.rows.push_back({name, "", "", "", "", "", "", "", "", "", "cannot tell",
                        "its report has no \"published\" section (analysis block without \"published\")"});
      continue;
    }
    for (const auto& e : c.fits["published"]) {
      const std::string curve = e.value("curve", "");
      const std::string member = e.value("member", "");
      if (e.contains("reason")) {
        t.rows.push_back({name, curve, member, "", "", "", "", "", "", "", "cannot tell", e["reason"].get<std::string>()});
        continue;
      }
      const double d_curve = number(e, "D_curve_last"), d_xy = number(e, "D_xy_last");
      t.rows.push_back({name, curve, member, std::to_string(e.value("points", 0)), short_number(number(e, "bias_D_xy")),
                        short_number(number(e, "max_abs_D_xy")), short_number(number(e, "max_abs_D_extent")),
                        short_number(d_curve), short_number(d_xy), percent(d_xy / d_curve - 1.0),
                        e.value("within_digitising_error", ""), e.value("note", "")});
    }
  }
  return t;
}

}  // namespace capsule::analysis
