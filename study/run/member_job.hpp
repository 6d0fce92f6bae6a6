#pragma once
// `study run-member MEMBER_DIR THREADS`: the job of one member, as every engine runs it (GNU Parallel here
// or over SSH, a Slurm array task; the generated run_member.sh execs it):
//   0. reads the member's id from its scene.json (never from the spelling of the folder's name:
//      "DIR/" and DIR are one member) and refuses a folder whose name does not end in it;
//   1. takes the member's lock (member_lock.hpp); a member another live process runs is left
//      alone (exit 0), so a duplicate or stale submission never runs one member twice at once;
//   2. exits 0 at once when member.h5 is complete with this member's id, or cannot be read:
//      a complete member file is never rewritten;
//   3. with --code-version V (the wrapper passes the version the run or export began with),
//      exits 3 without touching the member when the capsule binary now reports another: a
//      binary rebuilt mid-campaign would record a second code version in one campaign;
//   4. clears the previous attempt's exit_status and .partial, runs capsule with its output
//      appended to capsule.log, passes SIGTERM, SIGINT, SIGUSR1 and SIGHUP on to it (capsule then
//      writes a restart point and stops, exit 4: the next run continues there), keeps the lock's
//      heartbeat, and records capsule's exit status in exit_status (not after a stop by signal:
//      the member is interrupted, not ended);
//      When the lock is taken over while the run was stopped, the run (and capsule, which checks
//      the lock before each write) ends without touching the member's files or exit_status;
//   5. in a Slurm task (SLURM_JOB_ID set), appends a record of the task to the campaign's
//      runs.jsonl.
// Its exit status is 0 whatever the member's end (study reads that from the member's files), so
// GNU Parallel's --retries repeats only what failed to start: ssh's 255, or 126/127 when the
// capsule binary cannot be run on that host.
#include <filesystem>
#include <ostream>
#include <string>

namespace capsule::study {

// run-member's exit status when the capsule binary's code version is not the run's (step 3).
inline constexpr int kExitBinaryChanged = 3;

struct MemberJobRequest {
  std::filesystem::path member_dir;
  int threads = 1;
  std::filesystem::path capsule_binary;
  double checkpoint_seconds = 300;  // capsule --checkpoint-seconds
  std::string expected_code_version;  // when set, a capsule binary reporting another is not run
};

// The member folder as an absolute path without "." or ".." parts or a trailing slash: one
// spelling per folder.
std::filesystem::path normal_member_dir(const std::filesystem::path& dir);
// The member id of the folder's scene.json (member_id.hpp); throws when the folder's name does
// not end in it (a folder spelled or renamed into another member's).
std::string member_id_from_scene(const std::filesystem::path& member_dir);

// Runs the member as above; returns run-member's exit status.
int run_member_job(const MemberJobRequest& request, std::ostream& log);

}  // namespace capsule::study
