#include "study/state/member_state.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vector>

#include "common/json_text.hpp"
#include "solver/io/member_file.hpp"
#include "study/state/duration_text.hpp"
#include "study/state/member_lock.hpp"
#include "study/state/member_verification.hpp"
#include "study/state/process_alive.hpp"
#include "study/state/run_record.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

// The last non-empty line of a text file ("" when there is none).
std::string last_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return escape_controls(last);  // a log's line, shown in status: no terminal escapes
}

std::string exit_meaning(int code) {
  switch (code) {
    case 1: return "solver failure";
    case 2: return "bad scene or usage";
    case 3: return "unstable";
    case 4: return "stopped by a signal after its restart point";
    case 5: return "interrupted by a full disk or a lack of memory";
    case 126: return "capsule binary not executable";
    case 127: return "capsule binary not found";
    default: return code > 128 ? "killed by signal " + std::to_string(code - 128) : "exit status " + std::to_string(code);
  }
}

// Ended by a signal someone sent (kill, kill -9, the OOM killer, a hang-up, Ctrl-C), not one
// the solver raised itself (SIGSEGV, SIGABRT, SIGFPE, SIGBUS stay failures).
bool killed_from_outside(int code) {
  const int signal = code - 128;
  return signal == SIGHUP || signal == SIGINT || signal == SIGKILL || signal == SIGTERM;
}

double age_seconds(const fs::path& file) {
  std::error_code ec;
  const auto t = fs::last_write_time(file, ec);
  if (ec) return 1e300;
  return std::chrono::duration<double>(fs::file_time_type::clock::now() - t).count();
}

// A member folder study may not look into or run over: a symbolic link, a folder that cannot be
// read, a file where the folder should be (nothing when it is a folder, or not there yet).
std::optional<MemberCondition> folder_refusal(const MemberPaths& paths) {
  std::error_code ec;
  // A member folder that is a symbolic link may lead anywhere, onto another member too: study
  // runs, clears and deletes nothing through it (results_layout.hpp).
  if (const std::string link = linked_member_folder(paths.dir); !link.empty()) return MemberCondition{MemberState::unreadable, link};
  // A folder that cannot be looked into (no permission, a file where a folder should be) is not
  // a member that never ran: say so, and never run over it.
  const fs::file_status dir = fs::status(paths.dir, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    return MemberCondition{MemberState::unreadable, "cannot look into the member folder " + paths.dir.string() + ": " + ec.message()};
  if (!ec && dir.type() != fs::file_type::directory)
    return MemberCondition{MemberState::unreadable, paths.dir.string() + " is not a folder"};
  if (fs::symlink_status(paths.h5, ec).type() == fs::file_type::none || (ec && ec != std::errc::no_such_file_or_directory))
    return MemberCondition{MemberState::unreadable, "cannot look at " + paths.h5.string() + ": " + ec.message()};
  return std::nullopt;
}

// The state a member file says: complete (only when it reads whole), unstable, stopped, or failed.
MemberCondition member_file_condition(const MemberPaths& paths, const std::string& expected_id) {
  io::MemberStatus s;
  try {
    s = io::read_member_status(paths.h5.string());
  } catch (const std::exception& e) {
    return {MemberState::unreadable, std::string("member file cannot be read, left as it is (move it aside to "
                                                 "run the member again): ") + e.what()};
  }
  if (s.member_id != expected_id)
    return {MemberState::failed, "member file belongs to member " + message_value(s.member_id) + ", not " + expected_id};
  if (s.status == "complete") {
    // Said only of a file that reads whole: its root attributes alone can be edited or sit on a
    // damaged dataset (verified once per version of the file, member_verification.hpp).
    if (const std::string why = verify_member_file(paths.h5, s.content_hash); !why.empty())
      return {MemberState::unreadable, "member file marked complete is damaged or changed, left as it is (move it "
                                       "aside to run the member again): " + why};
    return {MemberState::complete, ""};
  }
  if (s.status.rfind("unstable", 0) == 0) return {MemberState::unstable, escape_controls(s.status)};
  if (s.status.rfind("stopped", 0) == 0) return {MemberState::stopped, escape_controls(s.status)};
  return {MemberState::failed, "member file has status " + message_value(s.status)};
}

// The state the wrapper's exit_status file says of a member without a member file: interrupted
// (resumable) or failed, with the end of capsule.log.
MemberCondition exit_status_condition(const MemberPaths& paths) {
  std::error_code ec;
  std::ifstream in(paths.exit_status);
  int code = -1;
  if (!(in >> code))  // the wrapper could not write it whole: a full or read-only disk, most likely
    return {MemberState::failed, "its exit_status file is empty or damaged (a full or read-only disk?); " +
                                     (last_line(paths.log).empty() ? std::string("capsule.log is empty")
                                                                   : "capsule.log ends: " + last_line(paths.log))};
  if (code == 5) {  // capsule's kExitResourcesExhausted: resumable, not an end
    const std::string tail = last_line(paths.log);
    return {MemberState::interrupted,
            exit_meaning(code) + (tail.empty() ? std::string() : ": " + tail) + "; `study run` continues it " +
                (fs::exists(paths.restart, ec) ? "from its restart point" : "(no restart point yet: from the start)") +
                " once there is room"};
  }
  if (code > 128 && fs::exists(paths.restart, ec))  // killed (SIGKILL, the OOM killer): resumable
    return {MemberState::interrupted, exit_meaning(code) + "; `study run` continues it from its restart point"};
  if (killed_from_outside(code))  // not the member's failure: it runs again, from the start
    return {MemberState::interrupted, exit_meaning(code) + " before its first restart point; `study run` runs it "
                                                           "again from the start"};
  if (code != 0) {
    std::string reason = exit_meaning(code);
    const std::string tail = last_line(paths.log);
    if (!tail.empty()) reason += ": " + tail;
    return {MemberState::failed, reason};
  }
  return {MemberState::failed, "capsule exited 0 but wrote no member file"};
}

// Whether a member with a partial file or a restart point runs now. Live: the member's lock has
// a live owner; else (a capsule run by hand, or by an older study) a progress file naming a live
// process on this host; on another host (or before the first progress line) files written
// within kStaleSeconds.
bool runs_now(const MemberPaths& paths, const MemberProgress& progress, bool locked) {
  if (locked) return true;
  if (progress.present && progress.host == host_name()) {
    // The writer started before it last wrote the file: a younger process has reused its pid.
    const double process_age = process_age_seconds(progress.pid);
    return process_alive(progress.pid) && (process_age < 0 || process_age + 2 >= progress.age_seconds);
  }
  std::error_code ec;
  double age = progress.present ? progress.age_seconds : 1e300;
  if (fs::exists(paths.partial, ec)) age = std::min(age, age_seconds(paths.partial));
  return age < kStaleSeconds;
}

// A member with a partial file or a restart point: running (its phase, kt and ETA) or
// interrupted (killed while running).
MemberCondition partial_condition(const MemberPaths& paths, bool locked) {
  std::error_code ec;
  MemberCondition c;
  c.progress = read_progress(paths.progress);
  std::ostringstream s;
  if (runs_now(paths, c.progress, locked)) {
    c.state = MemberState::running;
    if (c.progress.present && c.progress.phase != "starting") {
      s << c.progress.phase << ", kt " << c.progress.kt << " of " << (c.progress.member_end_is_cap ? "<= " : "")
        << c.progress.member_end_kt;
      if (c.progress.eta_member_seconds >= 0)
        s << ", ETA " << (c.progress.member_end_is_cap ? "<= " : "") << format_duration(c.progress.eta_member_seconds);
    } else {
      s << "starting";
    }
    c.reason = s.str();
    return c;
  }
  c.state = MemberState::interrupted;
  c.reason = fs::exists(paths.restart, ec) ? "killed while running; `study run` continues it from its restart point"
                                           : "killed while running (only member.h5.partial)";
  if (c.progress.present) {
    s << " at kt " << c.progress.kt;
    c.reason += s.str();
  }
  return c;
}

}  // namespace


const char* state_name(MemberState state) {
  switch (state) {
    case MemberState::fresh: return "new";
    case MemberState::interrupted: return "interrupted";
    case MemberState::running: return "running";
    case MemberState::complete: return "complete";
    case MemberState::unstable: return "unstable";
    case MemberState::stopped: return "stopped";
    case MemberState::failed: return "failed";
    case MemberState::unreadable: return "unreadable";
    case MemberState::queued: return "queued";
  }
  return "?";
}

MemberCondition inspect_member(const MemberPaths& paths, const std::string& expected_id) {
  if (std::optional<MemberCondition> refusal = folder_refusal(paths)) return *refusal;
  std::error_code ec;
  if (fs::exists(paths.h5, ec)) return member_file_condition(paths, expected_id);
  // A live owner of the member's lock (study run-member: a local run, an SSH host, a Slurm task)
  // runs it now, whatever an earlier attempt left.
  const auto owner = live_lock_owner(paths.dir);
  if (owner && !fs::exists(paths.partial, ec) && !fs::exists(paths.restart, ec))
    return {MemberState::running, "starting on " + owner->host + " (pid " + std::to_string(owner->pid) + ")"};
  if (!owner && fs::exists(paths.exit_status, ec)) return exit_status_condition(paths);
  if (fs::exists(paths.partial, ec) || fs::exists(paths.restart, ec)) return partial_condition(paths, owner.has_value());
  return {MemberState::fresh, ""};
}

MemberProgress read_progress(const fs::path& file) {
  MemberProgress p;
  std::error_code ec;
  if (!fs::exists(file, ec)) return p;
  try {
    std::ifstream in(file);
    const nlohmann::json j = nlohmann::json::parse(in);
    p.pid = j.at("pid").get<long>();
    p.host = j.at("host").get<std::string>();
    p.phase = j.at("phase").get<std::string>();
    p.kt = j.at("kt").get<double>();
    p.member_end_kt = j.at("member_end_kt").get<double>();
    p.member_end_is_cap = j.at("member_end_is_cap").get<bool>();
    p.steps_per_second = j.at("steps_per_second").get<double>();
    if (j.at("eta_member_seconds").is_number()) p.eta_member_seconds = j.at("eta_member_seconds").get<double>();
    p.age_seconds = age_seconds(file);
    p.present = true;
  } catch (const std::exception&) {
    p = {};  // a file being replaced or damaged: as if absent
  }
  return p;
}

bool needs_run(const MemberCondition& condition, bool rerun_unstable, bool rerun_stopped) {
  switch (condition.state) {
    case MemberState::complete: return false;
    case MemberState::running: return false;  // a live capsule (another run, a Slurm task) owns it
    case MemberState::unreadable: return false;  // never run over a file that may be complete
    case MemberState::queued: return false;      // a Slurm task will run it
    case MemberState::unstable: return rerun_unstable;
    case MemberState::stopped: return rerun_stopped;
    default: return true;
  }
}

}  // namespace capsule::study
