#pragma once
// `study export FILE --slurm`: a job list (member i on line i+1), sbatch array scripts whose
// tasks run the pending members through the same wrapper `study run` uses (so a member runs at
// most once at a time and never after it is complete, whatever is submitted twice), a
// submit.sh that submits them all, and slurm/export.json naming the jobs, from which `study
// status` asks squeue which members wait in the queue. Arrays over array_max members are split
// into several scripts. Assumes the results folder is on a filesystem shared by the nodes.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_resources.hpp"

namespace capsule::study {

struct SlurmOptions {
  int threads = 0;            // --cpus-per-task; 0: 1 for 2D, default_3d_cpus for 3D (slurm_resources.hpp)
  std::string time, mem;      // "" : from the cost estimate
  bool rerun_unstable = false;
  bool rerun_stopped = false;
  bool reuse_finished = true;  // copy a member another campaign finished instead of exporting it (member_reuse.hpp)
  bool allow_dirty = false;    // export from a build whose sources differ from every commit (provenance.hpp)
  double checkpoint_seconds = 300;  // capsule --checkpoint-seconds in every task
  std::size_t array_max = 1000;     // members per script: Slurm refuses array indices >= MaxArraySize (default 1001)
  int throttle = 0;                 // --array=...%N: at most N tasks of a script at once (0: no limit)
  std::string partition, account, qos;     // #SBATCH --partition / --account / --qos ("" : none)
  std::vector<std::string> sbatch_lines;  // further #SBATCH lines, each "--option[=value]"
};

// One sbatch script: the members [offset, offset + array_max) of the job list; task t runs
// line offset + t + 1.
struct SlurmScript {
  std::filesystem::path path;
  std::string job_name;      // <campaign>-<8 hex of the results folder>-<k>: what squeue shows
  std::size_t offset = 0;
  std::vector<std::size_t> tasks;  // the --array task ids (member index - offset)
};

struct SlurmExport {
  std::filesystem::path job_list;    // every member, in order
  std::filesystem::path submit;      // submit.sh: sbatch of every script, arguments passed on
  std::vector<SlurmScript> scripts;  // one, or one per array_max members that have work
  std::vector<std::size_t> pending;  // member indices in some --array spec
  std::string copied;                // "copied ... from ..." lines of the members finished elsewhere
  SlurmResources resources;
};

// "0-3,5,7-8" from sorted indices.
std::string array_spec(const std::vector<std::size_t>& indices);

// `#SBATCH --output="<slurm dir>/task-%A_%a.out"` (array job id and task: one file per
// submission, never overwritten by the next), a literal % doubled. Throws UnsafePathError
// for a folder with a double quote or a backslash.
std::string sbatch_output_line(const std::filesystem::path& slurm_dir);

// Writes member directories, the wrapper, slurm/jobs, the scripts (slurm/capsule.sbatch, or
// capsule-<k>.sbatch when split), slurm/submit.sh and slurm/export.json. Refuses
// (UnsafePathError) a results folder or capsule path with a control character before
// writing anything. With nothing pending the script has no --array and exits 0.
SlurmExport export_slurm(const CampaignSurvey& survey, const SlurmOptions& options);

}  // namespace capsule::study
