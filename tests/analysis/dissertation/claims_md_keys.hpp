#pragma once
// Test helper: the claim keys of the source tree's analysis/dissertation/claims.md (its "## "
// headings), in the file's order, read from disk rather than from the embedded copy.
#include <fstream>
#include <string>
#include <vector>

namespace capsule::analysis::testing {

inline std::vector<std::string> claims_md_keys() {
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/analysis/dissertation/claims.md");
  std::vector<std::string> keys;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("## ", 0) == 0) keys.push_back(line.substr(3));
  return keys;
}

}  // namespace capsule::analysis::testing
