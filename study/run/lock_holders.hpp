#pragma once
// The processes of this host that hold a file open (from /proc/<pid>/fd): after `kill -9` of
// GNU Parallel, the campaign's run lock stays held by the members it had started (study
// run-member and capsule inherit the lock's descriptor); a second run names them.
#include <filesystem>
#include <string>
#include <vector>

namespace capsule::study {

struct LockHolder {
  long pid = 0;
  std::string program;  // the file name of argv[0]
  std::string member;   // the member folder its command line names ("" when none)
};

// Every process whose open descriptors include file (none when /proc cannot be read).
std::vector<LockHolder> lock_holders(const std::filesystem::path& file);

// "; held by pid 123 (study, member m-1), pid 124 (capsule, member m-1)", or "" when no
// holder is found.
std::string describe_lock_holders(const std::filesystem::path& file);

}  // namespace capsule::study
