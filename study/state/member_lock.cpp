#include "study/state/member_lock.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <chrono>
#include <cstdio>
#include <random>
#include <nlohmann/json.hpp>

#include "study/state/member_state.hpp"
#include "study/state/process_alive.hpp"
#include "study/state/results_layout.hpp"
#include "study/state/run_record.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

// The owner a lock file names, with the age of its last heartbeat; nothing when there is no
// such file. A file that does not parse names no one (host "", pid 0): stale once old.
std::optional<LockOwner> read_owner(const fs::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return std::nullopt;
  LockOwner o;
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  o.age_seconds = now - (static_cast<double>(st.st_mtim.tv_sec) + 1e-9 * static_cast<double>(st.st_mtim.tv_nsec));
  const nlohmann::json j = nlohmann::json::parse(read_file_text(file), nullptr, /*allow_exceptions=*/false);
  if (j.is_object()) {
    o.host = j.value("host", std::string());
    o.pid = j.value("pid", 0L);
    o.started = j.value("started", std::string());
    o.token = j.value("token", std::string());
    o.process_start = j.value("process_start", -1LL);
  }
  return o;
}

bool owner_alive(const LockOwner& o) {
  if (o.age_seconds >= kStaleSeconds) return false;  // silent: dead or stopped, on any host
  if (!o.host.empty() && o.host == host_name()) {
    if (!process_alive(o.pid)) return false;
    // The pid of a process that started at another time: reused by another process.
    if (o.process_start >= 0 && process_start_ticks(o.pid) != o.process_start) return false;
  }
  return true;
}

std::string new_token() {
  std::random_device device;
  char text[33];
  std::snprintf(text, sizeof text, "%08x%08x%08x%08x", device(), device(), device(), device());
  return text;
}

}  // namespace

fs::path member_lock_file(const fs::path& member_dir) { return member_dir / "member.lock"; }

std::optional<LockOwner> live_lock_owner(const fs::path& member_dir) {
  const auto o = read_owner(member_lock_file(member_dir));
  if (!o || !owner_alive(*o)) return std::nullopt;
  return o;
}

MemberLock::MemberLock(const fs::path& member_dir) : file_(member_lock_file(member_dir)) {
  const std::string me = host_name();
  const nlohmann::json record = {{"host", me},
                                 {"pid", static_cast<long>(::getpid())},
                                 {"started", utc_now_iso8601()},
                                 {"token", new_token()},
                                 {"process_start", process_start_ticks(::getpid())}};
  // Written whole under a name of our own, then linked to the lock's name: link() fails with
  // EEXIST when the lock exists, so exactly one process gets it.
  const fs::path mine = file_.string() + "." + me + "." + std::to_string(::getpid());
  write_file_atomically(mine, record.dump() + "\n");
  for (int attempt = 0; attempt < 2 && !held_; ++attempt) {
    if (::link(mine.c_str(), file_.c_str()) == 0) {
      held_ = true;
      break;
    }
    const int err = errno;
    if (err != EEXIST) {
      ::unlink(mine.c_str());
      throw std::runtime_error("cannot take the member lock " + file_.string() + ": " + std::strerror(err));
    }
    const auto o = read_owner(file_);
    if (!o) continue;  // released meanwhile: try again
    if (owner_alive(*o)) {
      owner_ = *o;
      break;
    }
    // Stale. Only the process that makes <lock>.takeover (link again: one wins) may remove it,
    // after reading it once more; a takeover file left by a process that died is stale too.
    const fs::path takeover = file_.string() + ".takeover";
    if (::link(mine.c_str(), takeover.c_str()) != 0) {
      const auto t = read_owner(takeover);
      if (t && t->age_seconds > kStaleSeconds) {
        ::unlink(takeover.c_str());
        continue;
      }
      owner_ = *o;  // another process is taking it over
      break;
    }
    const auto again = read_owner(file_);
    if (!again || !owner_alive(*again)) {
      ::unlink(file_.c_str());
      held_ = ::link(mine.c_str(), file_.c_str()) == 0;
    }
    if (!held_ && again) owner_ = *again;
    ::unlink(takeover.c_str());
    break;
  }
  ::unlink(mine.c_str());
  if (held_)
    owner_ = LockOwner{me, static_cast<long>(::getpid()), record["started"], record["token"], record["process_start"], 0};
}

MemberLock::~MemberLock() {
  // Only our own: a lock another process took over (after we were silent too long) stays.
  if (still_held()) ::unlink(file_.c_str());
}

bool MemberLock::still_held() const {
  if (!held_) return false;
  const auto o = read_owner(file_);
  return o && o->token == owner_.token;
}

bool MemberLock::refresh() const {
  if (!still_held()) return false;
  ::utimensat(AT_FDCWD, file_.c_str(), nullptr, 0);
  return true;
}

}  // namespace capsule::study
