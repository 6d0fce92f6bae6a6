#pragma once
// The command line `study run` hands GNU Parallel: one job per line of the job list, each the
// member wrapper (run_member.sh) on one member folder, with the run's concurrency, hosts and
// stop sequence. No user string is in the command template: every path arrives as data.
#include <string>
#include <vector>

#include "study/plan/concurrency.hpp"
#include "study/run/campaign_runner.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

// argv of `parallel` (no shell reads it) for the job list and wrapper of the layout.
std::vector<std::string> parallel_arguments(const ResultsLayout& layout, const RunRequest& request,
                                            const Concurrency& concurrency);

}  // namespace capsule::study
