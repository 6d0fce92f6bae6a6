// Artificial viscosity maps of Sec. 5.1.2 per member, from its case's bilinear fit:
// V* = V + (a/b) eta (98) and, with bilinear.V_base, eta* = (b/a)(V - V_base) (97) for
// the members with eta = 0 (Figs. 57-58). artificial_viscosity.md/.csv/.tex.
#include <filesystem>

#include "analysis/fit/artificial_viscosity.hpp"
#include "analysis/report/bilinear_cases.hpp"
#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

class ArtificialViscositySection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    if (!context.block.bilinear) return;
    Table at;
    at.title = "Artificial viscosity: V* = V + (a/b) eta (98) and eta* = (b/a)(V - V_base) (97)";
    at.header = {"case", "target", "member", "V", "eta", "k tau", "a/b", "V* (98)", "eta* (97)"};
    const bool laddered = !context.block.bilinear->ladder.empty();  // each level with its own fit
    if (laddered) at.header.insert(at.header.begin() + 1, "level");
    const auto& V_base = context.block.bilinear->V_base;
    for (const CaseBilinear& b : bilinear_per_case(context)) {
      if (!b.fit.ok) continue;
      const Ratio ba = ratio_b_over_a(b.fit), ab = ratio_a_over_b(b.fit);
      for (std::size_t i = 0; i < b.used.size(); ++i) {
        const double V_star = artificial_V(ab.value, b.V[i], b.eta[i]);
        std::string eta_star;
        if (V_base && b.eta[i] == 0.0) eta_star = format_number(artificial_eta(ba.value, b.V[i], *V_base));
        at.rows.push_back({case_label(b.case_name), b.target, b.used[i], format_number(b.V[i]),
                           format_number(b.eta[i]), format_number(b.k_tau[i]), format_number(ab.value),
                           format_number(V_star), eta_star});
        if (laddered) at.rows.back().insert(at.rows.back().begin() + 1, level_label(b));
      }
    }
    outputs.write_table(at, out_dir, "artificial_viscosity");
  }
};

}  // namespace

std::unique_ptr<ReportSection> artificial_viscosity_section() {
  return std::make_unique<ArtificialViscositySection>();
}

}  // namespace capsule::analysis
