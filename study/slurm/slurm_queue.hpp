#pragma once
// Which members of a campaign wait in Slurm's queue: `study export --slurm` records its jobs'
// names in slurm/export.json; where squeue is on the PATH, it lists their array tasks still
// pending (held, waiting for resources or a throttle), and each task's id names a member (the
// script's offset + the task id, a line of the job list). Running tasks need no squeue: their
// member's lock says so (member_lock.hpp).
#include <map>
#include <string>

#include "study/state/results_layout.hpp"

namespace capsule::study {

struct SlurmQueue {
  std::map<std::string, std::string> queued;  // member folder name -> "job NAME task T (STATE)"
  std::string note;                            // why squeue could not be asked ("" when it was, or no export)
};

SlurmQueue slurm_queue(const ResultsLayout& layout);

}  // namespace capsule::study
