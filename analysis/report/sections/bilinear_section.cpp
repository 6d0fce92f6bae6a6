// The bilinear model (95)-(96), k tau = a eta + b V + c per case and target (Table 2):
// bilinear.md/.csv/.tex and fits.json "bilinear", with b/a and a/b (delta-method errors).
// With bilinear.ladder, one fit per level and bilinear_ladder.md/.csv/.tex with each
// coefficient extrapolated over the levels (fits.json "bilinear_ladder").
#include <cmath>
#include <filesystem>

#include "analysis/fit/artificial_viscosity.hpp"
#include "analysis/report/bilinear_cases.hpp"
#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

class BilinearSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    outputs.fits["bilinear"] = nlohmann::json::array();
    if (!context.block.bilinear) return;
    const bool laddered = !context.block.bilinear->ladder.empty();
    Table bt;
    bt.title = "Bilinear model (95)-(96): k tau = a eta + b V + c per case (95 % intervals, Student's t)";
    bt.header = {"case", "target", "Ca", "E_b", "a", "a ±95%", "b", "b ±95%", "c", "c ±95%", "R2", "N", "b/a",
                 "b/a std_error", "reason"};
    if (laddered) bt.header.insert(bt.header.begin() + 1, "level");
    std::vector<std::string> unplaced;
    const std::vector<CaseBilinear> fits = bilinear_per_case(context, &unplaced);
    for (const CaseBilinear& b : fits) {
      const FitResult& fit = b.fit;
      const double Ca = common_value(b.group, "Ca"), Eb = common_value(b.group, "E_b");
      nlohmann::json bj{{"case", b.case_name}, {"target", b.target}, {"Ca", json_number(Ca)},
                        {"E_b", json_number(Eb)},  {"fit", to_json(fit)},   {"members", b.used},
                        {"excluded", b.excluded}};
      if (laddered) bj["level"] = {{"key", b.level_key}, {"value", json_number(b.level)}};
      std::vector<std::string> row{case_label(b.case_name), b.target, format_number(Ca), format_number(Eb)};
      if (laddered) row.insert(row.begin() + 1, level_label(b));
      if (!fit.ok) {
        row.insert(row.end(), {"", "", "", "", "", "", "", std::to_string(b.k_tau.size()), "", "", fit.reason});
      } else {
        const Ratio ba = ratio_b_over_a(fit), ab = ratio_a_over_b(fit);
        bj["b_over_a"] = {{"value", json_number(ba.value)}, {"std_error", json_number(ba.std_error)}};
        bj["a_over_b"] = {{"value", json_number(ab.value)}, {"std_error", json_number(ab.std_error)}};
        for (const auto& p : fit.parameters) {
          row.push_back(format_number(p.value));
          row.push_back(format_number(p.half_width()));
        }
        row.insert(row.end(), {format_number(fit.r_squared), std::to_string(fit.n_points), format_number(ba.value),
                               format_number(ba.std_error), fit.converged ? "" : "Ceres did not report convergence"});
      }
      bt.rows.push_back(row);
      outputs.fits["bilinear"].push_back(bj);
    }
    if (context.members.empty())
      for (const auto& target : context.block.bilinear->targets) {
        bt.rows.push_back({case_label(""), target, "", "", "", "", "", "", "", "", "", "0", "", "",
                           "no members to fit"});
        if (laddered) bt.rows.back().insert(bt.rows.back().begin() + 1, "");
      }
    for (const std::string& u : unplaced)  // members on no level of the ladder: fitted nowhere, said so
      bt.rows.push_back({"", "no level", "", "", "", "", "", "", "", "", "", "", "", "", "", "not fitted: " + u});
    if (laddered) outputs.fits["bilinear_unplaced"] = unplaced;
    outputs.write_table(bt, out_dir, "bilinear");
    if (laddered) write_ladder(context, fits, out_dir, outputs);
  }

 private:
  // Each coefficient over the levels: Richardson with the observed order from the three
  // finest levels, or the assumed order from two (richardson.hpp); the error estimate is
  // what the finest level's coefficient carries from the resolution.
  static void write_ladder(const ReportContext& context, const std::vector<CaseBilinear>& fits,
                           const fs::path& out_dir, ReportOutputs& outputs) {
    const BilinearSpec& spec = *context.block.bilinear;
    Table lt;
    lt.title = "Bilinear coefficients over the resolution ladder " + spec.ladder +
               " (Richardson; error = |finest - extrapolated|, two levels: order " +
               format_number(spec.assumed_order) + " assumed)";
    lt.header = {"case", "target", "coefficient", "levels (" + spec.ladder + ": value)", "finest", "extrapolated",
                 "order", "error estimate", "relative error", "note"};
    outputs.fits["bilinear_ladder"] = nlohmann::json::array();
    for (const CoefficientLadder& cl : bilinear_ladders(context, fits)) {
      std::string levels;
      for (const auto& [x, q] : cl.levels)
        levels += (levels.empty() ? "" : "; ") + format_number(x) + ": " + format_number(q);
      std::string note = cl.result.reason;
      for (const auto& s : cl.skipped) note += (note.empty() ? "" : "; ") + ("left out " + s);
      const RichardsonResult& r = cl.result;
      nlohmann::json j{{"case", cl.case_name}, {"target", cl.target}, {"coefficient", cl.coefficient},
                       {"key", spec.ladder},   {"ok", r.ok},          {"note", note}};
      j["levels"] = nlohmann::json::array();
      for (const auto& [x, q] : cl.levels) j["levels"].push_back({{"value", json_number(x)}, {"coefficient", json_number(q)}});
      std::vector<std::string> row{case_label(cl.case_name), cl.target, cl.coefficient, levels,
                                   r.levels ? format_number(r.finest) : ""};
      if (r.ok) {
        const double rel = r.extrapolated != 0.0 ? r.error_estimate / std::abs(r.extrapolated) : k_nan;
        j["finest"] = json_number(r.finest);
        j["extrapolated"] = json_number(r.extrapolated);
        j["order"] = json_number(r.order);
        j["order_observed"] = r.order_observed;
        j["error_estimate"] = json_number(r.error_estimate);
        j["relative_error"] = json_number(rel);
        row.insert(row.end(), {format_number(r.extrapolated),
                               format_number(r.order) + (r.order_observed ? " (observed)" : " (assumed)"),
                               format_number(r.error_estimate), format_number(rel), note});
      } else {
        row.insert(row.end(), {"", "", "", "", "n/a: " + note});
      }
      lt.rows.push_back(row);
      outputs.fits["bilinear_ladder"].push_back(j);
    }
    outputs.write_table(lt, out_dir, "bilinear_ladder");
  }
};

}  // namespace

std::unique_ptr<ReportSection> bilinear_section() { return std::make_unique<BilinearSection>(); }

}  // namespace capsule::analysis
