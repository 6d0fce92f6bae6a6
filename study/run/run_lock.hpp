#pragma once
// One `study run` of a campaign at a time. An exclusive flock on results/<campaign>/.lock
// is inherited by GNU Parallel and every member it starts, so it stays held while any
// member of a run is alive, even after `kill -9` of `study` itself. Beside it,
// results/<campaign>/.running (written under a temporary name, then renamed) records who
// holds it: the study and GNU Parallel pids, the host and the start time. A second run
// that finds the lock held says which processes are still going and which members run.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace capsule::study {

// Thrown when another run holds the lock; `study` exits 5 (docs/guide/campaigns.md "Exit status").
struct RunStillGoing : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RunLock {
 public:
  // running_members: the member folders that have a .partial and no member file (under a
  // held lock, these are the ones running). Throws RunStillGoing naming them.
  RunLock(const std::filesystem::path& lock_file, const std::filesystem::path& info_file,
          const std::vector<std::string>& running_members);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  // Records this process and, once started, GNU Parallel's pid (0: not started yet).
  void record(long parallel_pid) const;

 private:
  int fd_ = -1;
  std::filesystem::path info_file_;
  std::string started_;
};

// The message of a held lock, from the .running record (pids checked with kill(pid, 0)).
std::string describe_running(const std::filesystem::path& info_file, const std::vector<std::string>& running_members);

}  // namespace capsule::study
