#pragma once
// One run of a member at a time, whichever engine started it (GNU Parallel here or over SSH, a
// Slurm array task, a user by hand): <member>/member.lock, made atomically with link(2) (atomic
// on NFS as well), holds the owner's host, pid, start, the process's start time and a token of
// its own. A lock is held while its owner keeps the file's modification time fresh (it touches it
// every kLockHeartbeatSeconds; silent for kStaleSeconds means dead), on this host also only while
// its pid is a live process that started when the owner did (a pid reused by another process
// holds nothing). A stale lock is taken over; a held one is left alone. An owner that was stopped
// (SIGSTOP, a frozen node) may find its lock taken over when it wakes: it checks its token at
// each heartbeat and before writing (solver/io/write_guard.hpp) and backs off.
#include <filesystem>
#include <optional>
#include <string>

namespace capsule::study {

inline constexpr double kLockHeartbeatSeconds = 20;

struct LockOwner {
  std::string host;
  long pid = 0;
  std::string started;
  std::string token;              // unique to one taking of the lock
  long long process_start = -1;   // process_start_ticks(pid) on the owner's host, -1 unknown
  double age_seconds = 0;         // since the owner last touched the lock
};

// The live owner of a member's lock, or nothing (no lock, or a stale one).
std::optional<LockOwner> live_lock_owner(const std::filesystem::path& member_dir);

class MemberLock {
 public:
  // Takes the lock of member_dir, taking over a stale one; held() says whether it got it, and
  // owner() who holds it when not.
  explicit MemberLock(const std::filesystem::path& member_dir);
  ~MemberLock();  // releases the lock if this process holds it
  MemberLock(const MemberLock&) = delete;
  MemberLock& operator=(const MemberLock&) = delete;

  bool held() const { return held_; }
  const LockOwner& owner() const { return owner_; }
  // Whether the lock file still holds this taking's token (false once another run took it over).
  bool still_held() const;
  // The heartbeat: touches the lock while it is still ours; false (touching nothing) when not.
  bool refresh() const;

 private:
  std::filesystem::path file_;
  bool held_ = false;
  LockOwner owner_;
};

std::filesystem::path member_lock_file(const std::filesystem::path& member_dir);

}  // namespace capsule::study
