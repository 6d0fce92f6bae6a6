#include "study/commands/analysis_commands.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>

#include "study/state/exit_status.hpp"
#include "study/commands/report_freshness.hpp"
#include "study/commands/thesis_inputs.hpp"
#include "study/state/member_leftovers.hpp"
#include "study/slurm/slurm_queue.hpp"

#include "analysis/compare/campaign_compare.hpp"
#include "analysis/dissertation/figure_axes.hpp"
#include "analysis/dissertation/table2_compare.hpp"
#include "analysis/report/report.hpp"
#include "analysis/dissertation/report.hpp"

namespace capsule::study {

namespace fs = std::filesystem;


namespace {

// Puts the finished staging folder where the report lives: one atomic exchange where the
// filesystem has it (renameat2), else two renames; the previous report is removed after.
void swap_in(const fs::path& staging, const fs::path& report) {
  if (!fs::exists(report)) {
    fs::rename(staging, report);
    return;
  }
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, report.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(staging);  // now holds the previous report
    return;
  }
  const fs::path previous = report.string() + ".previous." + std::to_string(::getpid());
  fs::rename(report, previous);
  fs::rename(staging, report);
  fs::remove_all(previous);
}

// The members a report reads, and those it lists without reading.
struct ReportMembers {
  std::vector<analysis::MemberRef> refs;  // one per member file and case (a shared member once per case)
  std::vector<std::string> not_run;       // "member: state", members without a final file yet
  std::vector<std::string> unreadable;    // "member: reason"
};

ReportMembers report_members(const CampaignSurvey& survey, std::ostream& out) {
  ReportMembers r;
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    const Member& m = survey.members[i];
    const MemberPaths p = survey.layout.member(m);
    std::error_code ec;
    if (survey.conditions[i].state == MemberState::unreadable) {  // a member file or a folder it cannot read
      r.unreadable.push_back(m.dir_name() + ": " + survey.conditions[i].reason);
      continue;
    } else if (!fs::exists(p.h5, ec)) {
      // Never run, running, or killed: no file to analyse, but the report lists it (as "member
      // file missing") so that a table of a campaign still under way says what it lacks.
      r.not_run.push_back(m.dir_name() + ": " + state_name(survey.conditions[i].state));
    } else if (survey.conditions[i].state == MemberState::failed) {
      // The member's own file only: inspect_member checks its member_id (a file copied from
      // another campaign, or made by older physics, is "failed", as in `study status`).
      out << "skipped " << m.dir_name() << ": " << survey.conditions[i].reason << "\n";
      continue;
    }
    // A member shared by several cases is analysed once per case.
    r.refs.push_back(analysis::MemberRef{m.id, m.slug, p.h5.string(), m.case_name, m.scene});
    for (const auto& other : m.other_cases)
      r.refs.push_back(analysis::MemberRef{m.id, m.slug, p.h5.string(), other, m.scene});
  }
  return r;
}

// analysis::write_report into the staging folder, removed again when it throws.
analysis::ReportSummary write_staged_report(const analysis::ReportRequest& request, const fs::path& staging) {
  fs::remove_all(staging);
  try {
    return analysis::write_report(request);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(staging, ec);
    throw;
  }
}

// A note in the staging folder (PARTIAL.md, INCOMPLETE.md): its text, then one line per item.
void write_note(const fs::path& staging, const std::string& name, std::string text,
                const std::vector<std::string>& items, analysis::ReportSummary& summary) {
  for (const auto& item : items) text += "- " + item + "\n";
  write_file_atomically(staging / name, text);
  summary.files.push_back((staging / name).string());
}

// The files written and the figures' note, with the staging folder's name replaced by the report's.
void print_written(const analysis::ReportSummary& summary, const fs::path& staging, const fs::path& report_dir,
                   std::ostream& out) {
  for (auto f : summary.files) {
    if (f.rfind(staging.string(), 0) == 0) f = report_dir.string() + f.substr(staging.string().size());
    out << "wrote " << f << "\n";
  }
  if (summary.figures_skipped) {
    std::string note = summary.figures_note;
    if (const auto at = note.find(staging.string()); at != std::string::npos)
      note.replace(at, staging.string().size(), report_dir.string());
    out << "figures skipped: " << note << "\n";
  }
}

}  // namespace

int report_campaign(const CampaignSurvey& survey, const ReportOptions& options, std::ostream& out) {
  const fs::path report_dir = survey.layout.report_dir();
  // Written into a staging folder and swapped in whole: a report is never half of one, and a
  // run that refuses leaves the previous report as it was.
  remove_dead_report_stagings(report_dir);  // of reports killed before their swap
  const fs::path staging = report_staging_dir(report_dir);
  analysis::ReportRequest request;
  request.campaign_name = survey.campaign.name;
  request.campaign_file = survey.campaign.source;
  request.out_dir = staging.string();
  request.analysis = survey.campaign.analysis;
  request.text_figures = analysis::text_figures_of_campaign(survey.campaign.name);  // titles "Fig. N: ..."
  ReportMembers members = report_members(survey, out);
  request.members = members.refs;
  std::vector<std::string>& unreadable = members.unreadable;
  if (!members.not_run.empty())
    out << members.not_run.size() << " of " << survey.members.size()
        << " members have no member file yet: the report says so in INCOMPLETE.md (see `study status`)\n";
  // Figures of a campaign that has not run would be empty axes.
  if (std::none_of(request.members.begin(), request.members.end(),
                   [](const analysis::MemberRef& r) { return fs::exists(r.path); }))
    request.no_figures = "no member of this campaign has a member file yet (run it first: study run " +
                         survey.campaign.source + ")";
  analysis::ReportSummary summary = write_staged_report(request, staging);
  for (const auto& u : summary.unreadable)
    if (std::find(unreadable.begin(), unreadable.end(), u) == unreadable.end()) unreadable.push_back(u);
  if (!unreadable.empty()) {
    for (const auto& u : unreadable) out << "cannot read " << u << "\n";
    if (!options.partial) {
      fs::remove_all(staging);
      out << "report not written: " << unreadable.size() << " member file" << (unreadable.size() == 1 ? "" : "s")
          << " cannot be read; " << (fs::exists(report_dir) ? "the previous report is kept" : "there is no report")
          << " (--partial writes one without them and says so in it)\n";
      return exit_members_failed;
    }
    write_note(staging, "PARTIAL.md",
               "# This report is partial\n\nWritten with `study report --partial`: these member files could "
               "not be read and are not in it.\n\n",
               unreadable, summary);
  }
  if (!members.not_run.empty())
    write_note(staging, "INCOMPLETE.md",
               "# This campaign is not complete\n\n" + std::to_string(members.not_run.size()) + " of " +
                   std::to_string(survey.members.size()) +
                   " members have no member file yet. The report's tables list them as \"member file missing\" "
                   "and every fit, model or ladder that needs them is missing or rests on the others; "
                   "`study run` completes them and `study report` then writes the whole report.\n\n",
               members.not_run, summary);
  write_fits_hash(staging);  // `study thesis` reads fits.json only as written here
  swap_in(staging, report_dir);
  print_written(summary, staging, report_dir, out);
  return unreadable.empty() ? members_exit_code(survey) : exit_members_failed;
}

int compare_campaign_files(const std::vector<std::string>& campaign_files, bool against_table2,
                           const fs::path& results_dir, std::ostream& out) {
  std::vector<analysis::CompareEntry> entries;
  std::string joined;
  for (const auto& file : campaign_files) {
    const CampaignSurvey survey = survey_campaign(file, results_dir, slurm_queue);
    if (const auto warning = stale_report_warning(survey)) out << *warning << "\n";
    const Campaign& c = survey.campaign;
    entries.push_back({c.name, survey.layout.report_dir().string()});
    joined += (joined.empty() ? "" : "_vs_") + c.name;
  }
  const fs::path out_dir = fs::absolute(results_dir) / "compare" / joined;
  fs::create_directories(out_dir);
  return analysis::compare_campaigns(entries, out, out_dir.string(),
                                     against_table2 ? analysis::CompareSection(analysis::table2_comparison)
                                                    : analysis::CompareSection());
}

int write_dissertation_comparison(const fs::path& results_dir, const fs::path& out_file, std::ostream& out) {
  for (const auto& warning : thesis_input_warnings(results_dir)) out << warning << "\n";
  const analysis::DissertationSummary s = analysis::write_dissertation(results_dir.string(), out_file.string());
  out << "wrote " << s.file << "\nclaims: " << s.claims_agree << " agree, " << s.claims_differ << " differ, "
      << s.claims_in_part << " hold in part, " << s.claims_cannot_tell << " cannot tell (rows: " << s.agrees << " / "
      << s.differs << " / " << s.cannot_tell << ")\nTable 2 coefficients: " << s.coefficients_overlap << " overlap, " << s.coefficients_disjoint
      << " do not, " << s.coefficients_unknown << " cannot tell (statistical intervals); extrapolated over the ladder: "
      << s.coefficients_extrapolated_pass << " pass the difference test, " << s.coefficients_extrapolated_fail << " do not\n"
      << "claims that differ, at the text's settings: " << s.emulation_text_numerics << " the text's numerics, "
      << s.emulation_model << " the model, " << s.emulation_cannot_tell << " cannot tell, " << s.emulation_not_run
      << " not run\n";
  return 0;
}


}  // namespace capsule::study
