#pragma once
// Runs one scene from start to end and writes its member file.
#include <string>

#include "solver/run/checkpoint.hpp"

namespace capsule {

struct RunOptions {
  std::string scene_path;
  std::string output_path;
  int threads = 0;        // 0: leave OpenMP's default
  std::string member_id;  // recorded in the member file; study passes the hash
  bool quiet = false;     // no progress lines (the progress file is still written)
  double progress_seconds = 5;
  CheckpointPolicy checkpoint;  // restart points (docs/guide/running.md "Checkpoints")
};

// Exit codes: 0 complete, 3 unstable, 2 bad scene or usage, 1 other failure, 4 stopped by a
// signal (SIGTERM, SIGINT, SIGUSR1) after writing a restart point: not an end, the same command
// continues the member.
inline constexpr int kExitStoppedBySignal = 4;
// 5: interrupted by a full disk (ENOSPC, EDQUOT) or a lack of memory (std::bad_alloc, ENOMEM),
// the cause on stderr: no member file is written, the .partial and the last whole restart point
// stay, and the same command continues once there is room.
inline constexpr int kExitResourcesExhausted = 5;
// 6: the member's lock was taken over by another run (solver/io/write_guard.hpp): this run
// stopped without touching the member's files.
inline constexpr int kExitOwnershipLost = 6;
// With a restart point beside the output (<output>.restart) of the same scene, physics and
// build, the run continues from it; one of another identity is refused and removed.
int run_member(const RunOptions& options);

}  // namespace capsule
