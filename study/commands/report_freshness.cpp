#include "study/commands/report_freshness.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

std::optional<std::string> stale_report_warning(const CampaignSurvey& survey) {
  const fs::path fits = survey.layout.report_dir() / "fits.json";
  std::error_code ec;
  if (!fs::exists(fits, ec))
    return "warning: campaign " + survey.campaign.name + " has no report yet (" + fits.string() +
           "); run `study report " + survey.campaign.source + "`";
  const auto report_time = fs::last_write_time(fits, ec);
  std::optional<fs::file_time_type> newest;
  std::string newest_member;
  for (const auto& m : survey.members) {
    const fs::path h5 = survey.layout.member(m).h5;
    if (!fs::exists(h5, ec)) continue;
    const auto t = fs::last_write_time(h5, ec);
    if (ec) continue;
    if (!newest || t > *newest) {
      newest = t;
      newest_member = m.dir_name();
    }
  }
  if (!newest || *newest <= report_time) return std::nullopt;
  return "warning: the report of campaign " + survey.campaign.name + " (" + fits.string() +
         ") is older than its member " + newest_member + "; run `study report " + survey.campaign.source +
         "` again for current fits";
}

}  // namespace capsule::study
