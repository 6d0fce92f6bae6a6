#pragma once
// What a killed run leaves beside a member that completed after all (a kill between the final
// rename and the cleanup, or a restart point, progress file or temporary of an earlier attempt):
// removed under the member's lock once its member file verifies complete, so they never pile
// up and are never read as the member's state. A killed report's staging folder likewise.
#include <filesystem>
#include <string>

#include "study/state/results_layout.hpp"

namespace capsule::study {

// Removes member.h5.restart, .progress, .partial and member.h5*.tmp* of a member whose member
// file is complete (checked again under its lock); false when there was nothing to remove or
// the member is not complete or its lock is held.
bool remove_complete_member_leftovers(const MemberPaths& paths, const std::string& member_id);

// Removes the staging folders (<report>.staging.<host>.<pid>) of reports killed on this host
// (the pid is no longer running), and any other <report>.staging.* untouched for a day.
void remove_dead_report_stagings(const std::filesystem::path& report_dir);

// The staging folder of this process: <report>.staging.<host>.<pid>.
std::filesystem::path report_staging_dir(const std::filesystem::path& report_dir);

}  // namespace capsule::study
