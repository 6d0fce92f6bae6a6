#include "study/state/member_reuse.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "solver/common/atomic_write.hpp"
#include "solver/io/member_file.hpp"
#include "study/state/member_state.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

ReusableMembers::ReusableMembers(const fs::path& results_root, const fs::path& own_root) {
  std::error_code ec;
  if (!fs::is_directory(results_root, ec)) return;
  std::vector<fs::path> campaigns;
  for (const auto& entry : fs::directory_iterator(results_root, ec))
    if (entry.is_directory(ec) && !fs::equivalent(entry.path(), own_root, ec)) campaigns.push_back(entry.path());
  std::sort(campaigns.begin(), campaigns.end());
  for (const auto& campaign : campaigns) {
    const fs::path members = campaign / "members";
    if (!fs::is_directory(members, ec)) continue;
    std::vector<fs::path> dirs;
    for (const auto& entry : fs::directory_iterator(members, ec))
      if (entry.is_directory(ec)) dirs.push_back(entry.path());
    std::sort(dirs.begin(), dirs.end());
    for (const auto& dir : dirs) {
      const std::string name = dir.filename().string();
      const auto dash = name.rfind('-');
      if (dash == std::string::npos) continue;
      by_id_[name.substr(dash + 1)].push_back({dir, campaign.filename().string()});
    }
  }
}

std::string reuse_refusal(const fs::path& h5) {
  try {
    return io::missing_series(io::read_member(h5.string()));  // read_member checks checksums and content hash
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::optional<FinishedMember> ReusableMembers::find(const Member& m, std::ostream* notes) const {
  const auto it = by_id_.find(m.id);
  if (it == by_id_.end()) return std::nullopt;
  for (const auto& candidate : it->second) {
    const MemberPaths p = member_paths_in(candidate.dir);
    // A file marked complete that does not read whole is unreadable: named below, never copied.
    const MemberCondition condition = inspect_member(p, m.id);
    if (condition.state != MemberState::complete && !(condition.state == MemberState::unreadable && fs::exists(p.h5)))
      continue;
    // The id is a 64-bit hash: the scene itself must match as well.
    const nlohmann::json scene = nlohmann::json::parse(read_file_text(p.scene), nullptr, /*allow_exceptions=*/false);
    if (scene.is_discarded() || scene != m.scene) continue;
    if (const std::string why = condition.state == MemberState::unreadable ? condition.reason : reuse_refusal(p.h5);
        !why.empty()) {
      if (notes) *notes << "not copied from " << candidate.campaign << "/members/" << candidate.dir.filename().string()
                        << ": " << why << "\n";
      continue;
    }
    return candidate;
  }
  return std::nullopt;
}

void copy_finished_member(const FinishedMember& source, const MemberPaths& target) {
  const MemberPaths from = member_paths_in(source.dir);
  fs::create_directories(target.dir);
  replace_atomically(target.h5.string(), [&](const std::string& temporary) {
    fs::copy_file(from.h5, temporary, fs::copy_options::overwrite_existing);
    if (const std::string why = reuse_refusal(temporary); !why.empty())
      throw std::runtime_error("the copy of " + from.h5.string() + " does not read whole: " + why);
  });
  std::string log = read_file_text(from.log);
  if (!log.empty() && log.back() != '\n') log += "\n";
  log += "study: copied from " + source.campaign + "/members/" + source.dir.filename().string() +
         ", where this member (same id: same scene and physics version) had finished\n";
  write_file_atomically(target.log, log);
  write_file_atomically(target.exit_status, "0\n");
  for (const auto& leftover : {target.partial, target.restart, target.progress}) fs::remove(leftover);
}

std::vector<std::size_t> copy_reusable_members(const std::vector<Member>& members,
                                                         const std::vector<std::size_t>& candidates,
                                                         const ResultsLayout& layout, std::ostream& out) {
  std::vector<std::size_t> copied;
  if (candidates.empty()) return copied;
  const ReusableMembers elsewhere(layout.root.parent_path(), layout.root);
  for (std::size_t i : candidates) {
    const auto source = elsewhere.find(members[i], &out);
    if (!source) continue;
    try {
      copy_finished_member(*source, layout.member(members[i]));
    } catch (const std::runtime_error& e) {
      out << "not copied: " << e.what() << "\n";
      continue;
    }
    out << "copied " << members[i].dir_name() << " from " << source->campaign
        << " (finished there; same scene and physics version)\n";
    copied.push_back(i);
  }
  return copied;
}

}  // namespace capsule::study
