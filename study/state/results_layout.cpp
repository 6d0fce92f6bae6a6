#include "study/state/results_layout.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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

void write_file_atomically(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.string() + ".tmp." + std::to_string(::getpid());
  // POSIX calls, so a failure names errno's reason (disk full, read-only, no permission) and
  // the temporary file never stays behind.
  const auto failed = [&](const char* what) {
    const int err = errno;
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write " + path.string() + " (" + what + " " + temporary.filename().string() +
                             "): " + std::strerror(err));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int err = errno;
    throw std::runtime_error("cannot write " + path.string() + " (creating " + temporary.filename().string() +
                             "): " + std::strerror(err));
  }
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      errno = err;
      failed("writing");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) failed("closing");
  if (::rename(temporary.c_str(), path.c_str()) != 0) failed("renaming");
}

}  // namespace capsule::study
