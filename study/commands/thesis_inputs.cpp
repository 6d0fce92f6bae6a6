#include "study/commands/thesis_inputs.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "study/campaign/member_id.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

std::string fits_hash_text(const std::string& bytes) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a_64(bytes)));
  return hex;
}

void write_fits_hash(const fs::path& report_dir) {
  const fs::path fits = report_dir / "fits.json";
  std::error_code ec;
  if (fs::exists(fits, ec)) write_file_atomically(report_dir / "fits.json.hash", fits_hash_text(read_file_text(fits)) + "\n");
}

namespace {

// The warning of one campaign folder, "" when its report is current.
std::string campaign_warning(const fs::path& campaign_dir) {
  const fs::path fits = campaign_dir / "report" / "fits.json";
  const fs::path hash = campaign_dir / "report" / "fits.json.hash";
  std::error_code ec;
  const std::string bytes = read_file_text(fits);
  const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, /*allow_exceptions=*/false);
  const std::string campaign_file = doc.is_object() && doc.value("campaign_file", nlohmann::json()).is_string()
                                        ? doc["campaign_file"].get<std::string>()
                                        : "CAMPAIGN";
  const std::string rerun = "; run `study report " + campaign_file + "` again before `study thesis`";
  const std::string name = campaign_dir.filename().string();
  if (fs::exists(hash, ec)) {
    std::string recorded = read_file_text(hash);
    while (!recorded.empty() && (recorded.back() == '\n' || recorded.back() == '\r')) recorded.pop_back();
    if (recorded != fits_hash_text(bytes))
      return "warning: campaign " + name + ": " + fits.string() + " was changed after `study report` wrote it (its hash "
             "is not the one in " + hash.filename().string() + ")" + rerun;
  }
  if (!doc.is_object() || !doc.contains("members") || !doc["members"].is_array()) return "";
  const auto report_time = fs::last_write_time(fits, ec);
  if (ec) return "";
  std::size_t newer = 0;
  std::string first;
  for (const auto& m : doc["members"]) {
    if (!m.is_object() || !m.value("path", nlohmann::json()).is_string()) continue;
    const fs::path h5 = campaign_dir / m["path"].get<std::string>();
    std::error_code time_ec;
    const auto t = fs::last_write_time(h5, time_ec);
    if (time_ec || t <= report_time) continue;
    if (newer++ == 0) first = h5.string();
  }
  if (newer == 0) return "";
  return "warning: campaign " + name + ": " + std::to_string(newer) + " member file" + (newer == 1 ? " is" : "s are") +
         " newer than its report " + fits.string() + " (" + first + (newer > 1 ? ", ..." : "") +
         "): its fits do not read them" + rerun;
}

}  // namespace

std::vector<std::string> thesis_input_warnings(const fs::path& results_dir) {
  std::vector<std::string> warnings;
  std::error_code ec;
  std::vector<fs::path> campaigns;
  for (fs::directory_iterator it(results_dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code e;
    if (fs::is_regular_file(it->path() / "report" / "fits.json", e)) campaigns.push_back(it->path());
  }
  std::sort(campaigns.begin(), campaigns.end());
  for (const auto& c : campaigns)
    if (std::string w = campaign_warning(c); !w.empty()) warnings.push_back(std::move(w));
  return warnings;
}

}  // namespace capsule::study
