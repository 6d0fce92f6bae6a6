#include "study/run/parallel_arguments.hpp"

#include <filesystem>

namespace capsule::study {

namespace fs = std::filesystem;

std::vector<std::string> parallel_arguments(const ResultsLayout& layout, const RunRequest& request,
                                            const Concurrency& concurrency) {
  // No --halt: a failed member never stops the others. The command template holds no user
  // string: GNU Parallel reads replacement strings ({}, {/}, {= perl =}) in the template, so
  // the wrapper is named relative to the member folder that {} stands for
  // (<root>/members/<member>/../../run_member.sh) and every path arrives only as data from
  // the job list. -q quotes the words, so nothing reaches a shell unquoted either.
  // "+joblog" appends: the joblog keeps every run's rows.
  std::string joblog = "+";  // append(): GCC 12 -O3 reports a false -Wrestrict on "literal" + string
  joblog.append(layout.joblog().string());
  std::vector<std::string> argv{"parallel", "--will-cite", "--joblog", joblog};
  // On a stop (SIGTERM, Ctrl-C) GNU Parallel passes TERM on to each running member, then by
  // default TERM again after 200 ms, 100 ms and KILL after 50 ms: too soon for a 3D capsule to
  // finish the restart point the signal asked for (a = 10 writes 150-300 MB), which the KILL
  // then leaves as a .tmp, losing up to --checkpoint-seconds of work. One TERM, then the
  // member's own time to write and exit, then KILL only for a member that never ends.
  argv.insert(argv.end(), {"--termseq", "TERM," + std::to_string(kStopGraceMilliseconds) + ",KILL,25"});
  // With a hosts file, each line's "N/host" says how many members that host takes (GNU
  // Parallel asks a host without N for its cores): no global --jobs unless the user gave -j.
  if (request.hosts_file.empty() || request.jobs > 0)
    argv.insert(argv.end(), {"--jobs", std::to_string(concurrency.jobs)});
  if (!request.hosts_file.empty()) {
    argv.insert(argv.end(), {"--sshloginfile", fs::absolute(request.hosts_file).string()});
    if (!request.ssh_command.empty()) argv.insert(argv.end(), {"--ssh", request.ssh_command});
    // A member whose start failed (ssh's 255 from a host that cannot be reached; the wrapper
    // itself returns 0 whatever the member's end) is tried again on another host.
    argv.insert(argv.end(), {"--retries", std::to_string(request.retries)});
  }
  argv.insert(argv.end(), {"--arg-file", layout.jobs_file().string(), "-q",
                           "{}/../../" + layout.wrapper().filename().string(), "{}",
                           std::to_string(concurrency.threads)});
  return argv;
}

}  // namespace capsule::study
