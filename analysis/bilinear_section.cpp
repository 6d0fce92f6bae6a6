// The bilinear model (95)-(96), k tau = a eta + b V + c per case and target (Table 2):
// bilinear.md/.csv/.tex and fits.json "bilinear", with b/a and a/b (delta-method errors).
#include <filesystem>

#include "analysis/artificial_viscosity.hpp"
#include "analysis/bilinear_cases.hpp"
#include "analysis/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

class BilinearSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    outputs.fits["bilinear"] = nlohmann::json::array();
    if (!context.block.bilinear) return;
    Table bt;
    bt.title = "Bilinear model (95)-(96): k tau = a eta + b V + c per case (95 % intervals, Student's t)";
    bt.header = {"case", "target", "Ca", "E_b", "a", "a ±95%", "b", "b ±95%", "c", "c ±95%", "R2", "N", "b/a",
                 "b/a std_error", "reason"};
    for (const CaseBilinear& b : bilinear_per_case(context)) {
      const FitResult& fit = b.fit;
      const double Ca = common_value(b.group, "Ca"), Eb = common_value(b.group, "E_b");
      nlohmann::json bj{{"case", b.case_name}, {"target", b.target}, {"Ca", json_number(Ca)},
                        {"E_b", json_number(Eb)},  {"fit", to_json(fit)},   {"members", b.used},
                        {"excluded", b.excluded}};
      std::vector<std::string> row{case_label(b.case_name), b.target, format_number(Ca), format_number(Eb)};
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
      for (const auto& target : context.block.bilinear->targets)
        bt.rows.push_back({case_label(""), target, "", "", "", "", "", "", "", "", "", "0", "", "",
                           "no members to fit"});
    outputs.write_table(bt, out_dir, "bilinear");
  }
};

}  // namespace

std::unique_ptr<ReportSection> bilinear_section() { return std::make_unique<BilinearSection>(); }

}  // namespace capsule::analysis
