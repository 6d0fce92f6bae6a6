#pragma once
// results/<campaign>/run.json: what ran, where, with which code, and how it ended.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace capsule::study {

std::string host_name();
std::string utc_now_iso8601();

// Base record: campaign name and file, code and physics version, host, start time.
nlohmann::json run_record_start(const std::string& campaign_name, const std::string& campaign_file);

// Appends one record as one line to the history file (runs.jsonl): the file is rewritten
// under a temporary name and renamed, so a reader never sees half a line.
void append_run_history(const std::filesystem::path& history, const nlohmann::json& record);

}  // namespace capsule::study
