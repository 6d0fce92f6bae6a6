#include "study/state/member_leftovers.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <vector>

#include "study/state/member_lock.hpp"
#include "study/state/member_state.hpp"
#include "study/state/process_alive.hpp"
#include "study/state/run_record.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> leftovers(const MemberPaths& paths) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const auto& p : {paths.restart, paths.progress, paths.partial})
    if (fs::exists(fs::symlink_status(p, ec))) found.push_back(p);
  for (fs::directory_iterator it(paths.dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    if (n.rfind("member.h5", 0) == 0 && n.find(".tmp") != std::string::npos) found.push_back(it->path());
  }
  return found;
}

}  // namespace

bool remove_complete_member_leftovers(const MemberPaths& paths, const std::string& member_id) {
  if (leftovers(paths).empty()) return false;
  const MemberLock lock(paths.dir);
  if (!lock.held() || inspect_member(paths, member_id).state != MemberState::complete) return false;
  std::error_code ec;
  for (const auto& p : leftovers(paths)) fs::remove(p, ec);
  return true;
}

fs::path report_staging_dir(const fs::path& report_dir) {
  return report_dir.string() + ".staging." + host_name() + "." + std::to_string(::getpid());
}

void remove_dead_report_stagings(const fs::path& report_dir) {
  const std::string prefix = report_dir.filename().string() + ".staging.";
  const std::string here = prefix + host_name() + ".";
  std::error_code ec;
  std::vector<fs::path> dead;
  for (fs::directory_iterator it(report_dir.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    if (n.rfind(prefix, 0) != 0 || it->is_symlink(ec)) continue;
    if (n.rfind(here, 0) == 0) {
      const std::string pid = n.substr(here.size());
      if (!pid.empty() && pid.find_first_not_of("0123456789") == std::string::npos && !process_alive(std::atol(pid.c_str())))
        dead.push_back(it->path());
      continue;
    }
    // Another host's report, or one of an older study (no host in the name): dead after a day.
    std::error_code time_ec;
    const auto age = fs::file_time_type::clock::now() - fs::last_write_time(it->path(), time_ec);
    if (!time_ec && age > std::chrono::hours(24)) dead.push_back(it->path());
  }
  for (const auto& p : dead) fs::remove_all(p, ec);
}

}  // namespace capsule::study
