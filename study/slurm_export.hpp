#pragma once
// `study export FILE --slurm`: a job list (member i on line i+1) and an sbatch script
// whose array task i runs member i through the same wrapper `study run` uses. Assumes the
// results folder is on a filesystem shared by the cluster's nodes.
#include <filesystem>
#include <string>
#include <vector>

#include "study/campaign_survey.hpp"
#include "study/slurm_resources.hpp"

namespace capsule::study {

struct SlurmOptions {
  int threads = 0;            // --cpus-per-task; 0: 1 for 2D, default_3d_cpus for 3D (slurm_resources.hpp)
  std::string time, mem;      // "" : from the cost estimate
  bool rerun_unstable = false;
  bool rerun_stopped = false;
  bool reuse_finished = true;  // copy a member another campaign finished instead of exporting it (finished_elsewhere.hpp)
  bool allow_dirty = false;    // export from a build whose sources differ from every commit (provenance.hpp)
};

struct SlurmExport {
  std::filesystem::path job_list, script;
  std::vector<std::size_t> pending;  // member indices in the --array spec (none: no --array line)
  std::string copied;                // "copied ... from ..." lines of the members finished elsewhere
  SlurmResources resources;
};

// "0-3,5,7-8" from sorted indices.
std::string array_spec(const std::vector<std::size_t>& indices);

// `#SBATCH --output="<slurm dir>/task-%a.out"`, a literal % doubled. Throws UnsafePathError
// for a folder with a double quote or a backslash.
std::string sbatch_output_line(const std::filesystem::path& slurm_dir);

// Writes member directories, the wrapper, slurm/jobs and slurm/capsule.sbatch. Refuses
// (UnsafePathError) a results folder or capsule path with a control character before
// writing anything. With nothing pending the script has no --array and exits 0.
SlurmExport export_slurm(const CampaignSurvey& survey, const SlurmOptions& options);

}  // namespace capsule::study
