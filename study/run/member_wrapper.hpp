#pragma once
// The generated script GNU Parallel (or a Slurm task) runs for one member:
//   run_member.sh MEMBER_DIR THREADS
// It execs `study run-member` (study/run/member_job.hpp) with the capsule binary and the restart
// point interval: the member's lock, a complete member left alone, capsule's output appended to
// MEMBER_DIR/capsule.log, its exit status kept in MEMBER_DIR/exit_status, signals passed on. A
// member killed earlier continues from its restart point. Arguments arrive as positional
// parameters and are always quoted: nothing is interpolated.
#include <filesystem>
#include <string>

namespace capsule::study {

struct WrapperSettings {
  std::string campaign_name;
  std::filesystem::path study_binary, capsule_binary;
  double checkpoint_seconds = 300;
  // The capsule binary's code version when the run or export began: run-member refuses to
  // start a member with a binary that reports another (rebuilt mid-campaign). Empty: no check.
  std::string capsule_code_version;
};

std::string member_wrapper_text(const WrapperSettings& settings);

// Writes the wrapper (mode 0755) atomically.
void write_member_wrapper(const std::filesystem::path& path, const WrapperSettings& settings);

}  // namespace capsule::study
