#include "study/run/member_job.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "build_info.hpp"
#include "study/run/capsule_binary.hpp"
#include "solver/run/run_member.hpp"
#include "solver/scene/scene.hpp"
#include "study/campaign/member_id.hpp"
#include "study/state/member_lock.hpp"
#include "study/state/member_state.hpp"
#include "study/state/results_layout.hpp"
#include "study/state/run_record.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// A Slurm task's record in the campaign's runs.jsonl (<campaign>/members/<member>/../../).
void record_slurm_task(const fs::path& member_dir, const std::string& started, double wall, int status) {
  const char* job = std::getenv("SLURM_JOB_ID");
  if (job == nullptr || *job == '\0') return;
  const auto env = [](const char* name) {
    const char* v = std::getenv(name);
    return std::string(v ? v : "");
  };
  nlohmann::json r = {{"engine", "slurm"},
                      {"slurm_job_id", env("SLURM_JOB_ID")},
                      {"slurm_array_job_id", env("SLURM_ARRAY_JOB_ID")},
                      {"slurm_array_task_id", env("SLURM_ARRAY_TASK_ID")},
                      {"member", member_dir.filename().string()},
                      {"host", host_name()},
                      {"code_version", build::code_version},
                      {"started", started},
                      {"finished", utc_now_iso8601()},
                      {"wall_seconds", wall},
                      {"capsule_exit_status", status}};
  if (status == kExitStoppedBySignal) r["ended"] = "stopped by a signal after a restart point (resumable)";
  append_run_history(member_dir.parent_path().parent_path() / "runs.jsonl", r);
}

// Temporary files a run left behind (<file>.tmp, <file>.tmp.<pid>): under the member's lock no
// other run writes them.
void remove_leftover_temporaries(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string n = entry.path().filename().string();
    if (n.rfind("member.h5", 0) == 0 && n.find(".tmp") != std::string::npos && !entry.is_symlink(ec))
      fs::remove(entry.path(), ec);
  }
}

}  // namespace

fs::path normal_member_dir(const fs::path& dir) {
  fs::path p = fs::absolute(dir).lexically_normal();
  while (!p.has_filename() && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();  // "DIR/" is DIR
  return p;
}

std::string member_id_from_scene(const fs::path& member_dir) {
  const fs::path scene = member_dir / "scene.json";
  const std::string name = member_dir.filename().string();
  const std::string id = member_id(Scene::load(scene.string()).to_json());
  if (name.size() <= id.size() || name.compare(name.size() - id.size() - 1, std::string::npos, "-" + id) != 0)
    throw std::runtime_error("the member folder " + member_dir.string() + " does not end in \"-" + id +
                             "\", the id of its scene.json: not the folder study made for that scene");
  return id;
}

namespace {

// Why the member is left alone before anything of it is touched: another live process runs it,
// it is complete or unreadable (exit 0), or the capsule binary now reports another code version
// than the run began with (exit kExitBinaryChanged). nullopt when it runs.
std::optional<int> left_alone(const MemberJobRequest& request, const MemberPaths& paths, const std::string& id,
                              const MemberLock& lock, std::ostream& log) {
  const std::string name = paths.dir.filename().string();
  if (!lock.held()) {
    log << "study run-member: " << name << " is running on " << lock.owner().host << " (pid " << lock.owner().pid
        << ", since " << lock.owner().started << "): left alone\n";
    return 0;
  }
  const MemberCondition before = inspect_member(paths, id);
  if (before.state == MemberState::complete || before.state == MemberState::unreadable) {
    log << "study run-member: " << name << " is " << state_name(before.state) << ": nothing run"
        << (before.reason.empty() ? "" : " (" + before.reason + ")") << "\n";
    return 0;
  }
  // The binary may have been rebuilt since the run began: its members would record another
  // code version than the campaign's others (or a -dirty one). Nothing of the member is touched.
  if (request.expected_code_version.empty()) return std::nullopt;
  std::string now;
  try {
    now = capsule_code_version(request.capsule_binary);
  } catch (const std::exception& e) {
    now = std::string("unknown (") + e.what() + ")";
  }
  if (now == request.expected_code_version) return std::nullopt;
  const std::string why = "study run-member: " + name + " not started: the capsule binary " +
                          request.capsule_binary.string() + " now reports code version " + now +
                          ", the run began with " + request.expected_code_version +
                          " (rebuilt meanwhile?); run `study run` again to start it with this binary\n";
  log << why;
  std::ofstream(paths.log, std::ios::app) << why;
  return kExitBinaryChanged;
}

// capsule's command line for the member: its scene, member file, id, threads and restart points.
std::vector<std::string> capsule_arguments(const MemberJobRequest& request, const MemberPaths& paths,
                                           const std::string& id) {
  return {request.capsule_binary.string(), paths.scene.string(), "-o", paths.h5.string(),
          "--id", id, "--threads", std::to_string(request.threads), "--progress-seconds", "10",
          "--checkpoint-seconds", std::to_string(request.checkpoint_seconds)};
}

// Starts capsule with its output appended to log_fd and the member lock's token in its
// environment, the signal mask old_mask restored in the child; returns its pid.
pid_t start_capsule(std::vector<std::string> words, int log_fd, const fs::path& member_dir, const MemberLock& lock,
                    const sigset_t& old_mask) {
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    const int err = errno;
    sigprocmask(SIG_SETMASK, &old_mask, nullptr);
    ::close(log_fd);
    throw std::runtime_error(std::string("cannot start capsule: ") + std::strerror(err));
  }
  if (child == 0) {
    sigprocmask(SIG_SETMASK, &old_mask, nullptr);
    // capsule checks before each write that the lock still holds this token (write_guard.hpp).
    ::setenv("CAPSULE_MEMBER_LOCK", member_lock_file(member_dir).c_str(), 1);
    ::setenv("CAPSULE_MEMBER_LOCK_TOKEN", lock.owner().token.c_str(), 1);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    std::fprintf(stderr, "study run-member: cannot run %s: %s\n", argv[0], std::strerror(errno));
    ::_exit(errno == ENOENT ? 127 : 126);
  }
  return child;
}

struct CapsuleEnd {
  int status = 0;     // waitpid's status
  bool lost = false;  // the lock was taken over while this run was stopped
};

// Waits for capsule, passing the signals of wanted (blocked) on to it and keeping the lock's
// heartbeat; a lock taken over meanwhile ends capsule.
CapsuleEnd wait_passing_signals(pid_t child, const sigset_t& wanted, const MemberLock& lock) {
  CapsuleEnd end;
  for (;;) {
    const timespec heartbeat{static_cast<time_t>(kLockHeartbeatSeconds), 0};
    siginfo_t info{};
    const int s = sigtimedwait(&wanted, &info, &heartbeat);
    if (s == SIGCHLD || s < 0) {
      if (s < 0 && errno != EAGAIN && errno != EINTR) {
        ::waitpid(child, &end.status, 0);
        break;
      }
      if (s < 0 && !end.lost && !lock.refresh()) {
        end.lost = true;
        ::kill(child, SIGTERM);  // capsule finds the lock gone before its next write and ends
      }
      const pid_t r = ::waitpid(child, &end.status, WNOHANG);
      if (r == child) break;
      continue;
    }
    ::kill(child, s);  // capsule writes a restart point at its next step and stops
  }
  return end;
}

// Runs capsule on the member under its lock; returns capsule's exit status, nothing when the
// lock was taken over meanwhile (then nothing of the member may be touched).
std::optional<int> run_capsule(const MemberJobRequest& request, const MemberPaths& paths, const std::string& id,
                const MemberLock& lock, std::ostream& log) {
  const int log_fd = ::open(paths.log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0) throw std::runtime_error("cannot open " + paths.log.string() + ": " + std::strerror(errno));
  // The signals to pass on wait, blocked, in sigtimedwait (with SIGCHLD), so none is lost
  // between the fork and the wait.
  sigset_t wanted, old_mask;
  sigemptyset(&wanted);
  for (int s : {SIGCHLD, SIGTERM, SIGINT, SIGUSR1, SIGHUP}) sigaddset(&wanted, s);
  sigprocmask(SIG_BLOCK, &wanted, &old_mask);
  const pid_t child = start_capsule(capsule_arguments(request, paths, id), log_fd, paths.dir, lock, old_mask);
  ::close(log_fd);
  const CapsuleEnd end = wait_passing_signals(child, wanted, lock);
  sigprocmask(SIG_SETMASK, &old_mask, nullptr);
  const int code = WIFEXITED(end.status) ? WEXITSTATUS(end.status) : WIFSIGNALED(end.status) ? 128 + WTERMSIG(end.status) : 1;
  if (end.lost || code == kExitOwnershipLost || !lock.still_held()) {
    log << "study run-member: " << paths.dir.filename().string() << ": its lock was taken over while this run was stopped (now "
        << read_file_text(member_lock_file(paths.dir)) << "); this run ended without touching the member's files\n";
    return std::nullopt;
  }
  return code;
}

}  // namespace

int run_member_job(const MemberJobRequest& request, std::ostream& log) {
  const fs::path member_dir = normal_member_dir(request.member_dir);
  const MemberPaths paths = member_paths_in(member_dir);
  if (const std::string link = linked_member_folder(member_dir); !link.empty())
    throw std::runtime_error("study run-member: " + link);
  const std::string id = member_id_from_scene(member_dir);
  const MemberLock lock(member_dir);
  if (const std::optional<int> code = left_alone(request, paths, id, lock, log)) return *code;
  std::error_code ec;
  fs::remove(paths.exit_status, ec);
  fs::remove(paths.partial, ec);
  remove_leftover_temporaries(member_dir);

  const std::string started = utc_now_iso8601();
  const double t0 = now_seconds();
  const std::optional<int> ended = run_capsule(request, paths, id, lock, log);
  if (!ended) return 0;
  const int code = *ended;
  if (code != kExitStoppedBySignal) write_file_atomically(paths.exit_status, std::to_string(code) + "\n");
  record_slurm_task(member_dir, started, now_seconds() - t0, code);
  return code == 126 || code == 127 ? code : 0;
}

}  // namespace capsule::study
