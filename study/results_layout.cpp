#include "study/results_layout.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

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

std::string read_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, path);
}

}  // namespace capsule::study
