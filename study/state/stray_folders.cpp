#include "study/state/stray_folders.hpp"

#include <sstream>

namespace capsule::study {

namespace fs = std::filesystem;

std::set<std::string> member_folder_names(const ResultsLayout& layout) {
  std::set<std::string> names;
  std::error_code ec;
  if (!fs::is_directory(layout.members_dir(), ec)) return names;
  for (const auto& entry : fs::directory_iterator(layout.members_dir(), ec))
    if (entry.is_directory(ec)) names.insert(entry.path().filename().string());
  return names;
}

std::string describe_stray_folders(const std::set<std::string>& strays, std::size_t shown) {
  if (strays.empty()) return "";
  std::ostringstream out;
  out << strays.size() << " folder" << (strays.size() > 1 ? "s" : "")
      << " under members/ belong" << (strays.size() > 1 ? "" : "s")
      << " to no member of this campaign (run before a swept value, the resolution or the physics version "
         "changed); study ignores "
      << (strays.size() > 1 ? "them" : "it") << ", delete when not needed:";
  std::size_t n = 0;
  for (const auto& name : strays) {
    if (n++ == shown) {
      out << "\n  ... and " << strays.size() - shown << " more";
      break;
    }
    out << "\n  " << name;
  }
  out << "\n";
  return out.str();
}

}  // namespace capsule::study
