#pragma once
// `study run`: prepares member directories, hands every member that is not complete to
// GNU Parallel (one job per member directory, from a generated job file), waits, and
// summarises from the members' own files. Resumable: rerun it after an interruption and
// only incomplete members run again, each from its last restart point (docs/guide/running.md "Checkpoints").
// While they run, one line shows done / running / left and an ETA (campaign_progress.hpp).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "study/state/campaign_survey.hpp"

namespace capsule::study {

struct RunRequest {
  std::string campaign_file;
  std::filesystem::path results_dir = "results";
  int jobs = 0;                  // 0: chosen (concurrency.hpp)
  int threads = 0;               // 0: chosen
  std::string hosts_file;        // GNU Parallel --sshloginfile (shared filesystem assumed)
  std::string ssh_command;       // GNU Parallel --ssh (default: ssh)
  int retries = 3;               // GNU Parallel --retries with --hosts: a member that failed to start goes to another host
  double checkpoint_seconds = 300;  // capsule --checkpoint-seconds: wall seconds between restart points
  bool allow_dirty = false;      // run from a build whose sources differ from every commit (provenance.hpp)
  bool rerun_unstable = false;   // also rerun members whose file says unstable
  bool rerun_stopped = false;    // also rerun members whose file says stopped (a configuration the solver refused)
  bool reuse_finished = true;    // copy a member another campaign under results_dir finished (member_reuse.hpp)
  bool progress_bar = false;     // redraw the campaign's progress line in place (the app sets it on a terminal)
  std::vector<std::string> cases;  // run only the members of these cases (empty: every member)
  std::vector<std::string> where;  // run only the members whose scene has KEY=VALUE (member_filter.hpp)
};

struct RunOutcome {
  int exit_code = 0;            // members_exit_code (exit_status.hpp): 0 when every member is complete
  std::size_t ran = 0;          // members handed to GNU Parallel
  double wall_seconds = 0;      // GNU Parallel's wall time
  double member_seconds = 0;    // sum of the joblog's JobRuntime over the members run
  bool tool_failed = false;     // GNU Parallel failed itself, or a host could not be reached: exit 1
};

// queue: which members wait in a batch queue (slurm_queue in `study run`); those are not run.
RunOutcome run_campaign(const RunRequest& request, const QueueReader& queue, std::ostream& out);

// How long a stopped run (SIGTERM, Ctrl-C) lets each running member write its restart point and
// exit before GNU Parallel kills it (its --termseq): a 3D member at a = 10 writes 150-300 MB.
inline constexpr int kStopGraceMilliseconds = 120000;

// The SIGTERM or SIGINT that stopped a run of members (passed on to GNU Parallel), 0 if none:
// `study run A.json B.json` starts no further campaign after it.
int stop_signal_received();

// Prints counts per state and every member that is not complete, with its reason.
void print_status(const CampaignSurvey& survey, std::ostream& out);

}  // namespace capsule::study
