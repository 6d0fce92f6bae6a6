#pragma once
// The complete shipped members under the repository's results/ with their phase ends: what the
// planner's estimates are validated on (phase_lengths_test, estimate_accuracy_test).
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "solver/io/member_file.hpp"

namespace capsule::study::testing {

struct ShippedMember {
  std::string campaign;
  capsule::io::MemberStatus status;
};

inline std::vector<ShippedMember> shipped_complete_members() {
  namespace fs = std::filesystem;
  std::vector<ShippedMember> all;
  for (const auto& campaign : fs::directory_iterator(fs::path(CAPSULE_SOURCE_DIR) / "results")) {
    if (!fs::is_directory(campaign.path() / "members")) continue;
    for (const auto& member : fs::directory_iterator(campaign.path() / "members")) {
      const fs::path h5 = member.path() / "member.h5";
      if (!fs::exists(h5)) continue;
      capsule::io::MemberStatus s = capsule::io::read_member_status(h5.string());
      if (s.status != "complete" || !s.scene.is_object() || !std::isfinite(s.t_stop) || !std::isfinite(s.t_end)) continue;
      all.push_back({campaign.path().filename().string(), std::move(s)});
    }
  }
  return all;
}

}  // namespace capsule::study::testing
