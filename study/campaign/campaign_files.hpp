#pragma once
// The campaign files a command line names: files as given, and every *.json below a folder
// (sorted by path, so campaigns/accuracy/ runs in the same order everywhere). Throws
// CampaignError for a name that is neither, or a folder that holds none.
#include <string>
#include <vector>

namespace capsule::study {

std::vector<std::string> campaign_files_of(const std::vector<std::string>& names);

}  // namespace capsule::study
