#include "study/analysis_bridge.hpp"

#include <stdexcept>

#include "study/exit_status.hpp"
#include "study/report_freshness.hpp"

#if __has_include("analysis/report.hpp") && __has_include("analysis/compare.hpp")
#include "analysis/compare.hpp"
#include "analysis/report.hpp"
#include "analysis/thesis_report.hpp"
#define CAPSULE_STUDY_HAS_REPORT 1
#endif

namespace capsule::study {

namespace fs = std::filesystem;

#ifdef CAPSULE_STUDY_HAS_REPORT

int report_campaign(const CampaignSurvey& survey, std::ostream& out) {
  analysis::ReportRequest request;
  request.campaign_name = survey.campaign.name;
  request.campaign_file = survey.campaign.source;
  request.out_dir = survey.layout.report_dir().string();
  request.analysis = survey.campaign.analysis;
  std::size_t missing = 0;
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    const Member& m = survey.members[i];
    const MemberPaths p = survey.layout.member(m);
    if (!fs::exists(p.h5)) {
      ++missing;
      continue;  // never run, or failed without a file: nothing to analyse
    }
    // The member's own file only: inspect_member checks its member_id (a file copied from
    // another campaign, or made by older physics, is "failed", as in `study status`).
    if (survey.conditions[i].state == MemberState::failed) {
      out << "skipped " << m.dir_name() << ": " << survey.conditions[i].reason << "\n";
      continue;
    }
    // A member shared by several cases is analysed once per case.
    request.members.push_back(analysis::MemberRef{m.id, m.slug, p.h5.string(), m.case_name, m.scene});
    for (const auto& other : m.other_cases)
      request.members.push_back(analysis::MemberRef{m.id, m.slug, p.h5.string(), other, m.scene});
  }
  if (missing > 0)
    out << missing << " of " << survey.members.size() << " members have no member file yet (see `study status`)\n";
  const analysis::ReportSummary summary = analysis::write_report(request);
  for (const auto& f : summary.files) out << "wrote " << f << "\n";
  if (summary.figures_skipped) out << "figures skipped: " << summary.figures_note << "\n";
  return members_exit_code(survey);
}

int compare_campaign_files(const std::vector<std::string>& campaign_files, bool against_table2,
                           const fs::path& results_dir, std::ostream& out) {
  std::vector<analysis::CompareEntry> entries;
  std::string joined;
  for (const auto& file : campaign_files) {
    const CampaignSurvey survey = survey_campaign(file, results_dir);
    if (const auto warning = stale_report_warning(survey)) out << *warning << "\n";
    const Campaign& c = survey.campaign;
    entries.push_back({c.name, survey.layout.report_dir().string()});
    joined += (joined.empty() ? "" : "_vs_") + c.name;
  }
  const fs::path out_dir = fs::absolute(results_dir) / "compare" / joined;
  fs::create_directories(out_dir);
  return analysis::compare_campaigns(entries, against_table2, out, out_dir.string());
}

int write_thesis_comparison(const fs::path& results_dir, const fs::path& out_file, std::ostream& out) {
  const analysis::ThesisSummary s = analysis::write_thesis(results_dir.string(), out_file.string());
  out << "wrote " << s.file << "\nclaims: " << s.agrees << " agree, " << s.differs << " differ, " << s.cannot_tell
      << " cannot tell\nTable 2 coefficients: " << s.coefficients_overlap << " overlap, " << s.coefficients_disjoint
      << " do not, " << s.coefficients_unknown << " cannot tell\n";
  return 0;
}

#else

int report_campaign(const CampaignSurvey&, std::ostream&) {
  throw std::runtime_error("this build has no analysis report (analysis/report.hpp missing)");
}

int compare_campaign_files(const std::vector<std::string>&, bool, const fs::path&, std::ostream&) {
  throw std::runtime_error("this build has no campaign comparison (analysis/compare.hpp missing)");
}

int write_thesis_comparison(const fs::path&, const fs::path&, std::ostream&) {
  throw std::runtime_error("this build has no dissertation comparison (analysis/thesis_report.hpp missing)");
}

#endif

}  // namespace capsule::study
