#pragma once
// Which members of a campaign wait in Slurm's queue: `study export --slurm` records its jobs'
// names in slurm/export.json; where squeue is on the PATH, it lists their array tasks still
// pending (held, waiting for resources or a throttle), and each task's id names a member (the
// script's offset + the task id, a line of the job list). Running tasks need no squeue: their
// member's lock says so (member_lock.hpp).
#include "study/state/campaign_survey.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

// The queued members (note: why squeue could not be asked); the QueueReader that the commands
// and `study run` pass to survey_campaign.
QueuedMembers slurm_queue(const ResultsLayout& layout);

}  // namespace capsule::study
