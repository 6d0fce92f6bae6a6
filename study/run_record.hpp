#pragma once
// results/<campaign>/run.json: what ran, where, with which code, and how it ended.
#include <nlohmann/json.hpp>
#include <string>

namespace capsule::study {

std::string host_name();
std::string utc_now_iso8601();

// Base record: campaign name and file, code and physics version, host, start time.
nlohmann::json run_record_start(const std::string& campaign_name, const std::string& campaign_file);

}  // namespace capsule::study
