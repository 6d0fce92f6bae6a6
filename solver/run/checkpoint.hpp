#pragma once
// Restart points inside a member (docs/guide/running.md "Checkpoints"). While `capsule SCENE -o OUT` runs it
// writes OUT.restart (HDF5, solver/io/state_archive.hpp) every `--checkpoint-seconds` of wall
// time, under a temporary name and then renamed, holding everything the rest of the run
// reads: the fluid (Fluid::export_state), the membrane and its memories, the protocol, the
// rows and shapes so far, the step counter. Running the same command again continues from
// it, and the rows, markers and shapes come out bitwise those of an uninterrupted run with
// the same thread count. The restart point is removed when the member ends.
//
// A restart point carries its identity: the canonical scene, the physics version, the code
// version, a fingerprint of the running binary and the member id. One whose identity differs
// from the run's is refused (with a message naming what differs) and the member starts afresh.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "solver/io/state_archive.hpp"

namespace capsule {

// When restart points are written.
struct CheckpointPolicy {
  double every_seconds = 300;   // wall seconds between restart points; 0: none
  long at_step = -1;            // hidden test option: also one when the step counter reaches this
  long stop_after_step = -1;    // hidden test option: end the run as if killed at this step
};

// Thrown by the output loop at --stop-after-step: the run ends without finishing the member
// file, leaving the .partial and the restart point as a kill would.
struct SimulatedKill {
  long step;
};

// A stop asked by a signal: SIGTERM (a job's time limit, scancel, GNU Parallel stopping), SIGINT
// (Ctrl-C) or SIGUSR1 (Slurm's --signal warning before the time limit). The handlers only set a
// flag; the output loop then writes a restart point at the next step and throws StoppedBySignal,
// so the member ends as a kill would, except that the same command continues from that step.
void install_stop_signals();
int stop_signal();  // the signal that asked for the stop, 0 while none has
struct StoppedBySignal {
  long step;
  int signal;
};

// Thrown when a restart point whose identity matched still does not fit the rebuilt run (a
// field of the wrong size, another reference shape): the member then starts afresh.
struct RestartRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string restart_path_for(const std::string& member_path);  // <member>.restart

// The identity of a run; written into every restart point and compared on resume.
struct RestartIdentity {
  std::string scene;  // canonical JSON text
  std::string physics_version, code_version, build, member_id;
};
RestartIdentity current_identity(const std::string& canonical_scene, const std::string& member_id);
void put_identity(io::StateArchive& archive, const RestartIdentity& id);
// "" when the archive was written by a run of this identity, else what differs.
std::string identity_mismatch(const io::StateArchive& archive, const RestartIdentity& id);

// Fingerprint of the running binary (FNV-1a 64 of /proc/self/exe, hex), computed once.
const std::string& binary_fingerprint();

// Reads the restart point at `path` when there is one. Returns it when its identity matches;
// otherwise prints why it is refused (to `log`), removes it and returns nothing.
std::unique_ptr<io::StateArchive> load_restart_point(const std::string& path, const RestartIdentity& id,
                                                     std::ostream& log);

// Decides when the next restart point is due (wall clock or the test step).
class CheckpointClock {
 public:
  explicit CheckpointClock(const CheckpointPolicy& policy);
  bool due(long step) const;
  void written();  // restarts the wall-clock interval
  const CheckpointPolicy& policy() const { return policy_; }

 private:
  CheckpointPolicy policy_;
  double last_ = 0;  // seconds on the steady clock
};

double steady_seconds();  // seconds on std::chrono::steady_clock

}  // namespace capsule
