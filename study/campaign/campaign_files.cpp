#include "study/campaign/campaign_files.hpp"

#include <algorithm>
#include <filesystem>

#include "study/campaign/campaign_error.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

std::vector<std::string> campaign_files_of(const std::vector<std::string>& names) {
  std::vector<std::string> files;
  for (const auto& name : names) {
    std::error_code ec;
    if (!fs::is_directory(name, ec)) {
      files.push_back(name);  // a file, or a name load_campaign refuses with its reason
      continue;
    }
    std::vector<std::string> found;
    for (fs::recursive_directory_iterator it(name, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_regular_file(ec) && it->path().extension() == ".json") found.push_back(it->path().string());
    if (found.empty()) throw campaign_error(name, "", "a folder with no campaign file (*.json) in it", "a campaign file or a folder of them");
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

}  // namespace capsule::study
