#include "study/run/provenance.hpp"

#include <cstdlib>

namespace capsule::study {

bool is_uncommitted_version(const std::string& code_version) {
  return code_version.empty() || code_version == "unknown" || code_version.find("-dirty") != std::string::npos;
}

bool allow_dirty_from_environment() {
  const char* v = std::getenv("STUDY_ALLOW_DIRTY");
  return v != nullptr && std::string(v) == "1";
}

void require_committed_build(const std::string& code_version, bool allow_dirty, const std::string& what) {
  if (allow_dirty || !is_uncommitted_version(code_version)) return;
  throw DirtyBuild(what + ": this build's code version is \"" + code_version +
                   "\": its sources (solver/, study/, analysis/, cmake/, CMakeLists.txt) differ from every commit "
                   "or git could not tell, so the member files it writes could not be reproduced from any commit. "
                   "Commit and rebuild, or pass --allow-dirty (or set STUDY_ALLOW_DIRTY=1; recorded in run.json)");
}

}  // namespace capsule::study
