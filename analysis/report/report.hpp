#pragma once
// A campaign's report: per-member fits, characteristic-time tables, the bilinear
// model (95)-(96) and artificial viscosities (97)-(98), fits.json and figures,
// written under results/<campaign>/report/ (layout in analysis/README.md).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/report/analysis_block.hpp"  // validate_analysis_block

namespace capsule::analysis {

struct MemberRef {
  std::string id, slug, path;  // path = member.h5 (may be missing or not complete)
  std::string case_name;
  nlohmann::json scene;        // canonical scene; when null, the member file's is used
};

struct ReportRequest {
  std::string campaign_name, campaign_file, out_dir;
  nlohmann::json analysis;     // the campaign's "analysis" block (null: defaults)
  std::vector<MemberRef> members;
  std::string no_figures;      // non-empty: draw no figures, and this says why
  // The dissertation's figures this report's figures stand for: [{"file": "tt_times_vs_Ca.png",
  // "number": "25", "shows": "..."}, ...]; an entry with "together": [{"label": "power law", "members": [slugs]}, ...] is a
  // figure of its own drawing those members on one plot, a line style per group, their series "left"
  // (["D_xy"] when absent; ["theta"]) against kt, and "otherwise": what the text draws that it does not
  // (figure_declarations.hpp).
  nlohmann::json text_figures = nlohmann::json::array();
};

struct ReportSummary {
  std::vector<std::string> files;  // every file written
  bool figures_skipped = false;
  std::string figures_note;
  std::vector<std::string> unreadable;  // "<member slug>: reason" for each member file that could not be read
};

// Throws std::invalid_argument for a bad analysis block; a member that is missing,
// unreadable or not complete is reported with its reason, never skipped silently.
ReportSummary write_report(const ReportRequest& request);

void validate_analysis_block(const nlohmann::json& block, const std::string& where);

}  // namespace capsule::analysis
