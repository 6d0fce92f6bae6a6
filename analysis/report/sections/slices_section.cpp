// Central slices of 3D members' stored shapes (Figs. 41-53): slices_<slug>.csv beside the
// member table, the member's fits.json entry naming it, and the figure data.
#include <filesystem>

#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

class SlicesSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    outputs.figure_data["slices"] = nlohmann::json::array();
    for (std::size_t i = 0; i < context.members.size(); ++i) {
      const MemberAnalysis& m = context.members[i];
      nlohmann::json& entry = outputs.fits["members"][i];  // written by the member-fits section
      if (!m.slices_note.empty()) entry["slices_note"] = m.slices_note;
      if (m.slices.empty()) continue;
      const std::string file = "slices_" + file_slug(m.ref.slug) + ".csv";
      entry["slices"] = {{"file", file}, {"unit", m.slices.unit}};
      outputs.write_text(out_dir / file, slices_csv(m.slices));
      nlohmann::json sj = slices_figure_json(m.slices);
      sj["slug"] = file_slug(m.ref.slug);
      sj["title"] = case_label(m.ref.case_name) + " / " + m.ref.slug + ": central slices at theta = 0";
      outputs.figure_data["slices"].push_back(sj);
    }
  }
};

}  // namespace

std::unique_ptr<ReportSection> slices_section() { return std::make_unique<SlicesSection>(); }

}  // namespace capsule::analysis
