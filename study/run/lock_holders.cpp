#include "study/run/lock_holders.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

// The arguments of a process (/proc/<pid>/cmdline, NUL-separated).
std::vector<std::string> command_line(const fs::path& proc_dir) {
  std::ifstream in(proc_dir / "cmdline", std::ios::binary);
  std::vector<std::string> args;
  for (std::string arg; std::getline(in, arg, '\0');) args.push_back(arg);
  return args;
}

// The member folder an argument names: <...>/members/<member>[/...].
std::string member_named(const std::vector<std::string>& args) {
  for (const auto& a : args) {
    const auto at = a.find("/members/");
    if (at == std::string::npos) continue;
    std::string rest = a.substr(at + 9);
    rest = rest.substr(0, rest.find('/'));
    if (!rest.empty()) return rest;
  }
  return "";
}

}  // namespace

std::vector<LockHolder> lock_holders(const fs::path& file) {
  std::vector<LockHolder> holders;
  std::error_code ec;
  const fs::path target = fs::canonical(file, ec);
  if (ec) return holders;
  for (fs::directory_iterator proc("/proc", ec), end; !ec && proc != end; proc.increment(ec)) {
    const std::string name = proc->path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::atol(name.c_str());
    if (pid == static_cast<long>(::getpid())) continue;
    std::error_code fd_ec;
    bool holds = false;
    for (fs::directory_iterator fd(proc->path() / "fd", fd_ec), fd_end; !fd_ec && fd != fd_end && !holds;
         fd.increment(fd_ec)) {
      std::error_code link_ec;
      holds = fs::read_symlink(fd->path(), link_ec) == target && !link_ec;
    }
    if (!holds) continue;
    const std::vector<std::string> args = command_line(proc->path());
    holders.push_back({pid, args.empty() ? "?" : fs::path(args.front()).filename().string(), member_named(args)});
  }
  return holders;
}

std::string describe_lock_holders(const fs::path& file) {
  const std::vector<LockHolder> holders = lock_holders(file);
  if (holders.empty()) return "";
  std::ostringstream m;
  m << "; held by " << holders.size() << " process" << (holders.size() == 1 ? "" : "es") << " of this host: ";
  for (std::size_t i = 0; i < holders.size() && i < 12; ++i) {
    const LockHolder& h = holders[i];
    m << (i == 0 ? "" : ", ") << "pid " << h.pid << " (" << h.program;
    if (!h.member.empty()) m << ", member " << h.member;
    m << ")";
  }
  if (holders.size() > 12) m << ", ...";
  m << " (a member a killed GNU Parallel left behind ends on its own, or stop it with `kill PID`)";
  return m.str();
}

}  // namespace capsule::study
