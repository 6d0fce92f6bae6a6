#include "study/member_state.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include "solver/io/member_file.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

// The last non-empty line of a text file ("" when there is none).
std::string last_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

std::string exit_meaning(int code) {
  switch (code) {
    case 1: return "solver failure";
    case 2: return "bad scene or usage";
    case 3: return "unstable";
    case 126: return "capsule binary not executable";
    case 127: return "capsule binary not found";
    default: return code > 128 ? "killed by signal " + std::to_string(code - 128) : "exit status " + std::to_string(code);
  }
}

}  // namespace

const char* state_name(MemberState state) {
  switch (state) {
    case MemberState::fresh: return "new";
    case MemberState::interrupted: return "interrupted";
    case MemberState::complete: return "complete";
    case MemberState::unstable: return "unstable";
    case MemberState::stopped: return "stopped";
    case MemberState::failed: return "failed";
  }
  return "?";
}

MemberCondition inspect_member(const MemberPaths& paths, const std::string& expected_id) {
  std::error_code ec;
  if (fs::exists(paths.h5, ec)) {
    io::MemberStatus s;
    try {
      s = io::read_member_status(paths.h5.string());
    } catch (const std::exception& e) {
      return {MemberState::failed, std::string("unreadable member file: ") + e.what()};
    }
    if (s.member_id != expected_id)
      return {MemberState::failed, "member file belongs to member \"" + s.member_id + "\", not " + expected_id};
    if (s.status == "complete") return {MemberState::complete, ""};
    if (s.status.rfind("unstable", 0) == 0) return {MemberState::unstable, s.status};
    if (s.status.rfind("stopped", 0) == 0) return {MemberState::stopped, s.status};
    return {MemberState::failed, "member file has status \"" + s.status + "\""};
  }
  if (fs::exists(paths.exit_status, ec)) {
    std::ifstream in(paths.exit_status);
    int code = -1;
    in >> code;
    if (code != 0) {
      std::string reason = exit_meaning(code);
      const std::string tail = last_line(paths.log);
      if (!tail.empty()) reason += ": " + tail;
      return {MemberState::failed, reason};
    }
    return {MemberState::failed, "capsule exited 0 but wrote no member file"};
  }
  if (fs::exists(paths.partial, ec)) return {MemberState::interrupted, "killed while running (only member.h5.partial)"};
  return {MemberState::fresh, ""};
}

bool needs_run(const MemberCondition& condition, bool rerun_unstable, bool rerun_stopped) {
  switch (condition.state) {
    case MemberState::complete: return false;
    case MemberState::unstable: return rerun_unstable;
    case MemberState::stopped: return rerun_stopped;
    default: return true;
  }
}

}  // namespace capsule::study
