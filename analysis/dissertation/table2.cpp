#include "analysis/dissertation/table2.hpp"

#include <cmath>

#include "analysis/fit/artificial_viscosity.hpp"
#include "analysis/dissertation/rules.hpp"
#include "analysis/fit/fit_statistics.hpp"

namespace capsule::analysis {

const std::vector<Table2Ensemble>& table2_ensembles() {
  // Sec. 5.1.1: "R^2 ~ 0.91 for Ca = 0.05 and E_b = 0, R^2 ~ 0.96 for Ca = 0.05 and E_b =
  // 0.025, and R^2 ~ 0.95 for Ca = 0.2 and E_b = 0"; "b_s/a_s ~ 2.8 ... increases to ~ 3.5
  // ... b_r/a_r ~ 5 ... decreases to ~ 4.6 ... falls to ~ 4.1".
  static const std::vector<Table2Ensemble> e = {
      {0.05, 0.0, "ch5_bilinear_ca005", "0.91", 2.8, 5.0},
      {0.05, 0.025, "ch5_bilinear_ca005_eb", "0.96", 3.5, 4.6},
      {0.2, 0.0, "ch5_bilinear_ca02", "0.95", 3.5, 4.1},
  };
  return e;
}

std::vector<Table2RowComparison> compare_table2_rows(const DissertationResults& results) {
  std::vector<Table2RowComparison> out;
  for (const Table2Row& ref : table2_dissertation()) {
    Table2RowComparison row;
    row.reference = &ref;
    for (const auto& e : table2_ensembles())
      if (std::abs(e.Ca - ref.Ca) < 1e-12 && std::abs(e.E_b - ref.E_b) < 1e-12) row.ensemble = &e;
    if (!row.ensemble) {
      row.why = "no campaign regenerates this row";
      out.push_back(row);
      continue;
    }
    const DissertationCampaign& c = results.campaign(row.ensemble->campaign);
    if (!c.found) {
      row.why = c.missing;
      out.push_back(row);
      continue;
    }
    // The finest level first; while a ladder's finest level is still too small to fit (it is
    // being run), the finest level whose fit succeeded stands in, and its label says which.
    const std::vector<BilinearEntry> entries = read_bilinear_entries(c.name, c.fits);
    const BilinearEntry* finest = nullptr;
    const BilinearEntry* chosen = nullptr;
    for (const BilinearEntry& b : entries)
      if (table2_row_for(b) == &ref) {
        if (!finest) finest = &b;
        if (b.fit.ok) {
          chosen = &b;
          break;
        }
      }
    if (!chosen) chosen = finest;
    if (chosen) {
      row.found = true;
      row.entry = *chosen;
      if (finest != chosen)  // a stand-in: its own ladder estimates belong to the finest level
        for (const char* k : {"a", "b", "c"}) {
          row.entry.ladder_error.erase(k);
          row.entry.ladder_note[k] = "the finest level, " + finest->level_key + " = " + format_number(finest->level) +
                                     ", not fitted yet (" + finest->fit.reason + ")";
        }
      row.coefficients = compare_with_table2(chosen->fit, ref);
    }
    if (!row.found)
      row.why = c.name + " has no bilinear fit of " + ref.target + " with Ca " + format_number(ref.Ca) + ", E_b " +
                format_number(ref.E_b) + " in its fits.json";
    out.push_back(row);
  }
  return out;
}

RatioInterval ratio_from_half_widths(double a, double a_hw, double b, double b_hw) {
  RatioInterval r;
  if (a == 0.0 || b == 0.0) {
    r.why = "a or b is zero";
    return r;
  }
  r.ok = true;
  r.value = b / a;
  r.half_width = std::abs(r.value) * std::sqrt((a_hw / a) * (a_hw / a) + (b_hw / b) * (b_hw / b));
  r.method = "delta method from the 95 % half-widths (a, b independent)";
  return r;
}

RatioInterval ratio_b_over_a_interval(const FitResult& fit) {
  RatioInterval r;
  const FitParameter* a = fit.ok ? fit.parameter("a") : nullptr;
  const FitParameter* b = fit.ok ? fit.parameter("b") : nullptr;
  if (!a || !b) {
    r.why = fit.ok ? "fit has no a or b" : fit.reason;
    return r;
  }
  const bool have_covariance = fit.covariance.size() >= 2 && fit.covariance[0].size() >= 2 &&
                               fit.covariance[1].size() >= 2 && std::isfinite(fit.covariance[0][1]) &&
                               fit.n_points > 3;
  if (!have_covariance || a->value == 0.0) return ratio_from_half_widths(a->value, a->half_width(), b->value, b->half_width());
  const Ratio ratio = ratio_b_over_a(fit);
  r.ok = true;
  r.value = ratio.value;
  r.half_width = student_t_975(fit.n_points - 3) * ratio.std_error;
  r.method = "delta method with the fit's covariance, t(" + std::to_string(fit.n_points - 3) + ")";
  return r;
}

namespace {
std::string row_label(const Table2Row& r) {
  return r.target + " (Ca " + format_number(r.Ca) + ", E_b " + format_number(r.E_b) + ")";
}
std::string text_r2(const Table2RowComparison& row) {
  if (!row.ensemble) return "";
  return row.reference->target == "k_tau_r" ? std::string("> 0.99") : "~ " + row.ensemble->text_r2_response;
}
}  // namespace

std::optional<ExtrapolatedComparison> extrapolated_difference_test(const Table2RowComparison& row, const CoefficientComparison& c) {
  if (!row.found || !c.measured) return std::nullopt;
  const auto x = row.entry.ladder_extrapolated.find(c.name);
  const auto e = row.entry.ladder_error.find(c.name);
  if (x == row.entry.ladder_extrapolated.end() || e == row.entry.ladder_error.end() || !std::isfinite(x->second) ||
      !std::isfinite(e->second))
    return std::nullopt;
  ExtrapolatedComparison out;
  out.extrapolated = x->second;
  out.error = std::abs(e->second);
  out.difference = out.extrapolated - c.reference;
  const double z = 1.96;
  out.sigma = std::sqrt(std::pow(c.reference_half_width / z, 2) + std::pow(c.half_width / z, 2) + out.error * out.error);
  out.passes = std::abs(out.difference) <= z * out.sigma;
  if (const auto coarse = row.entry.ladder_coarser.find(c.name); coarse != row.entry.ladder_coarser.end() && std::isfinite(coarse->second))
    out.moves = std::abs(c.value - c.reference) < std::abs(coarse->second - c.reference) ? 1 : -1;
  return out;
}

Table table2_side_by_side(const std::vector<Table2RowComparison>& rows) {
  Table t;
  t.title = "Table 2 (Sec. 5.1.1): k tau = a eta + b V + c, dissertation against this toolkit (± = 95 % half-width)";
  t.header = {"row", "campaign", "coefficient", "dissertation", "toolkit", "difference", "95 % overlap",
              "R^2 dissertation", "R^2 toolkit", "N", "next coarser level", "extrapolated ± Richardson error",
              "difference test"};
  for (const auto& row : rows) {
    const Table2Row& ref = *row.reference;
    const std::string campaign = row.ensemble ? row.ensemble->campaign : "";
    if (!row.found) {
      const std::pair<double, double> refs[] = {{ref.a, ref.a_half_width}, {ref.b, ref.b_half_width}, {ref.c, ref.c_half_width}};
      const char* names[] = {"a", "b", "c"};
      for (int i = 0; i < 3; ++i)
        t.rows.push_back({row_label(ref), campaign, names[i], plus_minus(refs[i].first, refs[i].second),
                          "cannot tell (" + row.why + ")", "", "", i == 0 ? text_r2(row) : "", "", "", "", "", ""});
      continue;
    }
    std::string where = campaign;
    if (!row.entry.level_key.empty())
      where += " (" + row.entry.level_key.substr(row.entry.level_key.rfind('.') + 1) + " = " +
               format_number(row.entry.level) + ")";
    for (std::size_t i = 0; i < row.coefficients.size(); ++i) {
      const CoefficientComparison& c = row.coefficients[i];
      std::vector<std::string> cells{row_label(ref), where, c.name, plus_minus(c.reference, c.reference_half_width)};
      if (!c.measured) cells.insert(cells.end(), {"cannot tell (fit failed: " + c.reason + ")", "", ""});
      else cells.insert(cells.end(), {short_plus_minus(c.value, c.half_width), short_number(c.difference), c.overlap ? "yes" : "NO"});
      cells.push_back(i == 0 ? text_r2(row) : "");
      cells.push_back(i == 0 && row.entry.fit.ok ? short_number(row.entry.fit.r_squared) : "");
      cells.push_back(i == 0 && row.entry.fit.ok ? std::to_string(row.entry.fit.n_points) : "");
      // the coefficient at the next coarser level, whether the finest moved toward the text, and the
      // extrapolation's difference test (bilinear.ladder), else blank or why not
      const auto x = extrapolated_difference_test(row, c);
      const auto coarse = row.entry.ladder_coarser.find(c.name);
      cells.push_back(coarse == row.entry.ladder_coarser.end() || !c.measured
                          ? ""
                          : short_number(coarse->second) + (x && x->moves > 0 ? " (finest: toward the text)"
                                                            : x && x->moves < 0 ? " (finest: away from the text)" : ""));
      if (x) {
        cells.push_back(short_plus_minus(x->extrapolated, x->error));
        cells.push_back(std::string(x->passes ? "yes" : "NO") + ": |" + short_number(x->difference) + "| vs 1.96 x " +
                        short_number(x->sigma));
      } else {
        const auto n = row.entry.ladder_note.find(c.name);
        cells.push_back(n != row.entry.ladder_note.end() && c.measured ? "n/a: " + n->second : "");
        cells.push_back("");
      }
      t.rows.push_back(cells);
    }
  }
  return t;
}

Table table2_ratios(const std::vector<Table2RowComparison>& rows) {
  Table t;
  t.title = "Ratios b/a (Sec. 5.1.1), 95 % intervals";
  t.header = {"ratio", "Ca", "E_b", "text says", "from Table 2", "toolkit", "difference", "95 % overlap", "toolkit interval from"};
  for (const auto& row : rows) {
    if (!row.ensemble) continue;
    const Table2Row& ref = *row.reference;
    const bool response = ref.target == "k_tau_s";
    const RatioInterval text = ratio_from_half_widths(ref.a, ref.a_half_width, ref.b, ref.b_half_width);
    std::vector<std::string> cells{response ? "b_s/a_s" : "b_r/a_r", format_number(ref.Ca), format_number(ref.E_b),
                                   "~ " + format_number(response ? row.ensemble->text_ratio_response
                                                                 : row.ensemble->text_ratio_recovery),
                                   short_plus_minus(text.value, text.half_width)};
    if (!row.found) {
      cells.insert(cells.end(), {"cannot tell (" + row.why + ")", "", "", ""});
    } else {
      const RatioInterval mine = ratio_b_over_a_interval(row.entry.fit);
      if (!mine.ok) {
        cells.insert(cells.end(), {"cannot tell (" + mine.why + ")", "", "", ""});
      } else {
        const bool ov = intervals_overlap(mine.value - mine.half_width, mine.value + mine.half_width,
                                          text.value - text.half_width, text.value + text.half_width);
        cells.insert(cells.end(), {short_plus_minus(mine.value, mine.half_width), short_number(mine.value - text.value),
                                   ov ? "yes" : "NO", mine.method});
      }
    }
    t.rows.push_back(cells);
  }
  return t;
}

}  // namespace capsule::analysis
