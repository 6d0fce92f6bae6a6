#pragma once
// Folders under <results>/<campaign>/members/ that no member of today's campaign names: left
// by a run before a swept value, the resolution or the physics version changed (a member's
// folder name carries its id). study never reads them; `study plan` names them so that a
// user sees what is stale before shipping or deleting it.
#include <set>
#include <string>

#include "study/state/results_layout.hpp"

namespace capsule::study {

// Every folder name under layout.members_dir() (empty when there is none).
std::set<std::string> member_folder_names(const ResultsLayout& layout);

// "N folders under members/ belong to no member ..." with up to `shown` names; "" when none.
std::string describe_stray_folders(const std::set<std::string>& strays, std::size_t shown = 6);

}  // namespace capsule::study
