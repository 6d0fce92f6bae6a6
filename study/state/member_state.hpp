#pragma once
// What a member's own files say about it. Completion is decided here, per member, from
// its member file (status "complete" and the expected member_id) -- never from GNU
// Parallel's joblog.
#include <filesystem>
#include <string>

#include "study/state/results_layout.hpp"

namespace capsule::study {

enum class MemberState {
  fresh,        // nothing run yet
  interrupted,  // a .partial or restart point and no live owner (killed), or capsule's exit 5 (disk full, no memory)
  running,      // member.h5.partial of a live capsule (its progress file names a live pid, or is fresh)
  complete,     // member.h5 with status "complete" and this member's id
  unstable,     // member.h5 with status "unstable at kt = X: reason"
  stopped,      // member.h5 with status "stopped: reason" (the solver threw; capsule exit 1)
  failed,       // the capsule exited non-zero without a member file, or the file is foreign (another id)
  unreadable,   // member.h5 exists but cannot be read (locked, no permission, damaged): kept, never rerun over
  queued,       // not run yet, and its Slurm array task waits in the queue (slurm_queue.hpp): not run here too
};

// Every state, in the order the summaries list them.
inline constexpr MemberState kAllMemberStates[] = {MemberState::complete, MemberState::fresh, MemberState::running,
                                                   MemberState::interrupted, MemberState::unstable,
                                                   MemberState::stopped, MemberState::failed, MemberState::unreadable,
                                                   MemberState::queued};

// What a running capsule last said about itself (member.h5.progress, solver/run/progress.hpp).
struct MemberProgress {
  bool present = false;
  long pid = 0;
  std::string host, phase;
  double kt = 0, member_end_kt = 0, steps_per_second = 0;
  double eta_member_seconds = -1;  // < 0: unknown
  bool member_end_is_cap = false;
  double age_seconds = 0;          // since the file was written
};
MemberProgress read_progress(const std::filesystem::path& progress_file);

struct MemberCondition {
  MemberCondition() = default;
  MemberCondition(MemberState s, std::string why) : state(s), reason(std::move(why)) {}
  MemberState state = MemberState::fresh;
  std::string reason;  // for unstable / stopped / failed / interrupted / running
  MemberProgress progress;  // for running (and interrupted members that left one)
};

// A member whose files have not changed for this long is not taken for running unless its
// progress file names a live process on this host.
inline constexpr double kStaleSeconds = 90;

const char* state_name(MemberState state);  // "new", "interrupted", "complete", ...

// Reads member.h5 (status and member_id only), else exit_status and the end of capsule.log.
MemberCondition inspect_member(const MemberPaths& paths, const std::string& expected_id);

// True when `study run` must (re)run the member: everything except complete; unstable
// only with rerun_unstable (same id = same scene and physics = same blow-up) and stopped
// only with rerun_stopped (the solver refused the configuration: rerunning it gives the
// same stop). A failed member (no member file: killed, crashed, foreign file) is retried.
// An unreadable member file is never run over: it may be complete (held open with HDF5's
// file lock by another process, or not readable to this user); the user decides.
bool needs_run(const MemberCondition& condition, bool rerun_unstable, bool rerun_stopped);

}  // namespace capsule::study
