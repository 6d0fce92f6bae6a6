#pragma once
// `study export FILE --slurm`: a job list (member i on line i+1) and an sbatch script
// whose array task i runs member i through the same wrapper `study run` uses. Assumes the
// results folder is on a filesystem shared by the cluster's nodes.
#include <filesystem>
#include <string>
#include <vector>

#include "study/campaign_survey.hpp"

namespace capsule::study {

struct SlurmExport {
  std::filesystem::path job_list, script;
  std::vector<std::size_t> pending;  // member indices in the --array spec
};

// "0-3,5,7-8" from sorted indices.
std::string array_spec(const std::vector<std::size_t>& indices);

// Writes member directories, the wrapper, slurm/jobs and slurm/capsule.sbatch.
// threads: cpus per task (0 -> 1 for a 2D-only campaign, else the cores of this machine).
SlurmExport export_slurm(const CampaignSurvey& survey, int threads, bool rerun_unstable);

}  // namespace capsule::study
