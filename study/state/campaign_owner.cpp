#include "study/state/campaign_owner.hpp"

#include <nlohmann/json.hpp>

#include "study/campaign/campaign_error.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

std::string absolute_source(const Campaign& campaign) {
  return fs::absolute(campaign.source).lexically_normal().string();
}

// The same campaign: the same text, or the same JSON document spelled with other spaces.
bool same_campaign_text(const std::string& a, const std::string& b) {
  if (a == b) return true;
  const nlohmann::json x = nlohmann::json::parse(a, nullptr, false), y = nlohmann::json::parse(b, nullptr, false);
  return !x.is_discarded() && !y.is_discarded() && x == y;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  const bool same = fs::equivalent(a, b, ec);
  return !ec && same;
}

bool is_other_campaign_file(const fs::directory_entry& e, const fs::path& self, const std::string& recorded) {
  std::error_code ec;
  const fs::path& p = e.path();
  if (p.extension() != ".json" || !e.is_regular_file(ec) || same_file(p, self)) return false;
  if (e.file_size(ec) > (1u << 20)) return false;  // campaign files are a few kB
  return same_campaign_text(read_file_text(p), recorded);
}

// A campaign file other than `self` that holds `recorded` (the campaign as last run): in the
// folder of `self`, or anywhere under `campaigns` but inside `results` (whose campaign.json files
// are records, not campaign files); "" when there is none.
std::string other_file_holding(const std::string& recorded, const fs::path& self, const fs::path& campaigns,
                               const fs::path& results) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(self.parent_path(), fs::directory_options::skip_permission_denied, ec))
    if (is_other_campaign_file(e, self, recorded)) return fs::absolute(e.path()).lexically_normal().string();
  if (!fs::is_directory(campaigns, ec)) return "";
  for (auto it = fs::recursive_directory_iterator(campaigns, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_directory(ec) && same_file(it->path(), results)) {
      it.disable_recursion_pending();
      continue;
    }
    if (is_other_campaign_file(*it, self, recorded)) return fs::absolute(it->path()).lexically_normal().string();
  }
  return "";
}

}  // namespace

void require_same_campaign(const Campaign& campaign, const ResultsLayout& layout) {
  std::error_code ec;
  if (!fs::exists(layout.campaign_json(), ec)) return;
  const std::string recorded_text = read_file_text(layout.campaign_json());
  if (same_campaign_text(recorded_text, campaign.text)) return;
  const std::string here = absolute_source(campaign);
  const auto refuse = [&](const std::string& owner) {
    throw campaign_error(campaign.source, "name",
                         "campaign \"" + campaign.name + "\" in " + layout.root.string() + " was made by " + owner +
                             ", a different file with the same name (this one is " + here + ")",
                         "a name of its own, or another --results folder");
  };
  // The file recorded as the maker, where this checkout has the record and that file still exists.
  std::string recorded = read_file_text(layout.campaign_source());
  while (!recorded.empty() && (recorded.back() == '\n' || recorded.back() == '\r')) recorded.pop_back();
  if (!recorded.empty() && recorded != here && fs::exists(recorded, ec) && !same_file(recorded, here)) refuse(recorded);
  // Another file that holds the campaign as last run: the maker, whatever its path.
  const fs::path results_dir = layout.root.parent_path();
  const std::string owner = other_file_holding(recorded_text, here, results_dir.parent_path() / "campaigns", results_dir);
  if (!owner.empty()) refuse(owner);
}

void record_campaign(const Campaign& campaign, const ResultsLayout& layout) {
  if (read_file_text(layout.campaign_json()) != campaign.text) write_file_atomically(layout.campaign_json(), campaign.text);
  const std::string source = absolute_source(campaign) + "\n";
  if (read_file_text(layout.campaign_source()) != source) write_file_atomically(layout.campaign_source(), source);
}

}  // namespace capsule::study
