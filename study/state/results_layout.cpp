#include "study/state/results_layout.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace capsule::study {

namespace fs = std::filesystem;

ResultsLayout::ResultsLayout(const fs::path& results_dir, const std::string& campaign_name)
    : root(fs::absolute(results_dir).lexically_normal() / campaign_name) {}

MemberPaths member_paths_in(const fs::path& dir) {
  MemberPaths p;
  p.dir = dir;
  p.scene = p.dir / "scene.json";
  p.h5 = p.dir / "member.h5";
  p.partial = p.dir / "member.h5.partial";
  p.log = p.dir / "capsule.log";
  p.exit_status = p.dir / "exit_status";
  p.restart = p.dir / "member.h5.restart";
  p.progress = p.dir / "member.h5.progress";
  return p;
}

MemberPaths ResultsLayout::member(const Member& m) const { return member_paths_in(members_dir() / m.dir_name()); }

namespace {
std::string link_text(const fs::path& link) {
  std::error_code ec;
  const fs::path to = fs::read_symlink(link, ec);
  return link.string() + " is a symbolic link" + (ec ? std::string() : " (to " + to.string() + ")");
}
}  // namespace

std::string linked_member_folder(const fs::path& member_dir) {
  std::error_code ec;
  for (const fs::path& p : {member_dir.parent_path(), member_dir})
    if (fs::is_symlink(p, ec))
      return link_text(p) + ": study runs, clears and deletes nothing through links inside a campaign's folder "
                            "(replace it with a real folder; a link may stand for the whole results folder)";
  return "";
}

void require_no_linked_members_folder(const ResultsLayout& layout) {
  std::error_code ec;
  if (fs::is_symlink(layout.members_dir(), ec))
    throw std::runtime_error(link_text(layout.members_dir()) +
                             ": refused, study writes nothing through links inside a campaign's folder (the wrapper "
                             "and scene.json would land elsewhere); make the whole results folder the link, or pass "
                             "--results with the other disk's folder");
}

std::string read_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace capsule::study
