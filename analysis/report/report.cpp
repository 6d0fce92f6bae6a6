#include "analysis/report/report.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "analysis/report/figure_declarations.hpp"
#include "analysis/report/plot_script.hpp"
#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

// Draws figure_data.json with the embedded matplotlib script, or says why not.
void draw_figures(const fs::path& out, const nlohmann::json& figure_data, ReportOutputs& outputs,
                  ReportSummary& summary) {
  const fs::path fig_dir = out / "figures";
  fs::create_directories(fig_dir);
  const fs::path data_path = fig_dir / "figure_data.json";
  // The script is the toolkit's (analysis/report/plot_report.py): run from a temporary copy and
  // not kept, so the reports hold no copies of it; `python3 analysis/report/plot_report.py
  // figures/figure_data.json figures` redraws a report's figures.
  const fs::path script_path = fig_dir / ".plot_report.py.tmp";
  outputs.write_text(data_path, figure_data.dump() + "\n");
  {
    std::ofstream script(script_path, std::ios::binary | std::ios::trunc);
    script << plot_script_text();
  }
  const std::string note = run_plot_script(script_path.string(), data_path.string(), fig_dir.string());
  std::error_code ec;
  fs::remove(script_path, ec);
  if (!note.empty()) {
    summary.figures_skipped = true;
    summary.figures_note = note;
    return;
  }
  for (const auto& e : fs::directory_iterator(fig_dir))
    if (e.path().extension() == ".png") outputs.files.push_back(e.path().string());
  summary.figures_note = "figures written to " + fig_dir.string();
}

}  // namespace

ReportSummary write_report(const ReportRequest& request) {
  const std::string where = request.campaign_file.empty() ? request.campaign_name : request.campaign_file;
  const AnalysisBlock block = parse_analysis_block(request.analysis, where);
  if (request.out_dir.empty()) throw std::invalid_argument("write_report: empty out_dir");
  const fs::path out(request.out_dir);
  fs::create_directories(out);

  std::set<std::string> wanted{"Ca", "E_b", "V", "eta"};
  for (const auto& t : block.tables) wanted.insert(t.x);
  if (block.stability) wanted.insert(block.stability->parameters.begin(), block.stability->parameters.end());
  if (block.bilinear && !block.bilinear->ladder.empty()) wanted.insert(block.bilinear->ladder);
  for (const auto& p : block.published)
    for (const auto& [name, value] : p.where) wanted.insert(name);
  for (const auto& e : block.experiments) {
    wanted.insert(e.parameter);
    if (!e.group.empty()) wanted.insert(e.group);
  }
  for (const auto& l : block.ladders) wanted.insert(l.key);  // study thesis judges a ladder's finest level by it
  std::vector<MemberAnalysis> members = analyse_members(request, block, wanted);
  std::vector<std::string> unreadable;
  for (const auto& m : members)
    if (m.status.rfind("unreadable", 0) == 0) {
      const std::string entry = m.ref.slug + "-" + m.ref.id + ": " + m.status;
      if (std::find(unreadable.begin(), unreadable.end(), entry) == unreadable.end()) unreadable.push_back(entry);
    }
  record_varying_parameters(members);
  const ReportContext context{request, block, std::move(members)};

  ReportOutputs outputs;
  outputs.fits["campaign"] = request.campaign_name;
  outputs.fits["campaign_file"] = request.campaign_file;
  outputs.fits["analysis"] = request.analysis;
  std::vector<std::unique_ptr<ReportSection>> sections;
  sections.push_back(member_fits_section());
  sections.push_back(slices_section());
  sections.push_back(time_tables_section());
  sections.push_back(bilinear_section());
  sections.push_back(artificial_viscosity_section());
  sections.push_back(ladder_section());
  sections.push_back(accuracy_section());
  sections.push_back(stability_section());
  sections.push_back(published_section());
  sections.push_back(experiment_section());
  for (const auto& section : sections) section->write(context, out, outputs);
  outputs.write_text(out / "fits.json", outputs.fits.dump(2) + "\n");

  ReportSummary summary;
  if (!block.figures) {
    summary.figures_skipped = true;
    summary.figures_note = "figures off in the analysis block";
  } else if (!request.no_figures.empty()) {
    summary.figures_skipped = true;
    summary.figures_note = request.no_figures;
  } else {
    declare_figures(outputs.figure_data, request.text_figures);
    draw_figures(out, outputs.figure_data, outputs, summary);
  }
  summary.files = std::move(outputs.files);
  summary.unreadable = std::move(unreadable);
  return summary;
}

}  // namespace capsule::analysis
