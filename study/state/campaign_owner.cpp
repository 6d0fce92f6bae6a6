#include "study/state/campaign_owner.hpp"

#include <fstream>
#include <sstream>

#include "study/campaign/campaign_error.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

std::string absolute_source(const Campaign& campaign) {
  return fs::absolute(campaign.source).lexically_normal().string();
}

}  // namespace

void require_same_campaign(const Campaign& campaign, const ResultsLayout& layout) {
  std::error_code ec;
  if (!fs::exists(layout.campaign_json(), ec) || !fs::exists(layout.campaign_source(), ec)) return;
  if (read_file_text(layout.campaign_json()) == campaign.text) return;
  std::string recorded = read_file_text(layout.campaign_source());
  while (!recorded.empty() && (recorded.back() == '\n' || recorded.back() == '\r')) recorded.pop_back();
  const std::string here = absolute_source(campaign);
  if (recorded.empty() || recorded == here) return;  // the same file, edited
  throw campaign_error(campaign.source, "name",
                       "campaign \"" + campaign.name + "\" in " + layout.root.string() + " was made by " + recorded +
                           ", a different file with the same name (this one is " + here + ")",
                       "a name of its own, or another --results folder");
}

void record_campaign(const Campaign& campaign, const ResultsLayout& layout) {
  write_file_atomically(layout.campaign_json(), campaign.text);
  write_file_atomically(layout.campaign_source(), absolute_source(campaign) + "\n");
}

}  // namespace capsule::study
