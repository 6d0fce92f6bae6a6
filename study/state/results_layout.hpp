#pragma once
// Where a campaign's results live:
//   <results>/<campaign>/campaign.json      the campaign file as last run
//   <results>/<campaign>/campaign_source    the absolute path of the campaign file that made it
//   <results>/<campaign>/run.json           code version, host, jobs x threads, times, summary (last run)
//   <results>/<campaign>/runs.jsonl         every run's run.json, one line each, oldest first
//   <results>/<campaign>/joblog             GNU Parallel's --joblog, appended by every run
//   <results>/<campaign>/.lock, .running    the run lock and who holds it (run_lock.hpp)
//   <results>/<campaign>/jobs               the job list handed to GNU Parallel (member dirs)
//   <results>/<campaign>/run_member.sh      the generated wrapper that runs one member
//   <results>/<campaign>/members/<slug>-<id>/{scene.json, member.h5, capsule.log, exit_status}
//       and while a member runs: member.h5.partial, member.h5.restart, member.h5.progress
//   <results>/<campaign>/slurm/             `study export --slurm` output
//   <results>/<campaign>/report/            `study report` output
#include <filesystem>
#include <string>

#include "solver/common/atomic_write.hpp"
#include "study/campaign/expansion.hpp"

namespace capsule::study {

struct MemberPaths {
  std::filesystem::path dir, scene, h5, partial, log, exit_status;
  std::filesystem::path restart;   // member.h5.restart: the capsule's last restart point
  std::filesystem::path progress;  // member.h5.progress: the running capsule's progress (JSON)
};

struct ResultsLayout {
  std::filesystem::path root;  // absolute <results>/<campaign>

  ResultsLayout(const std::filesystem::path& results_dir, const std::string& campaign_name);

  std::filesystem::path campaign_json() const { return root / "campaign.json"; }
  std::filesystem::path campaign_source() const { return root / "campaign_source"; }
  std::filesystem::path run_json() const { return root / "run.json"; }
  std::filesystem::path run_history() const { return root / "runs.jsonl"; }
  std::filesystem::path running_info() const { return root / ".running"; }
  std::filesystem::path joblog() const { return root / "joblog"; }
  std::filesystem::path jobs_file() const { return root / "jobs"; }
  std::filesystem::path wrapper() const { return root / "run_member.sh"; }
  std::filesystem::path lock_file() const { return root / ".lock"; }
  std::filesystem::path members_dir() const { return root / "members"; }
  std::filesystem::path slurm_dir() const { return root / "slurm"; }
  std::filesystem::path report_dir() const { return root / "report"; }
  MemberPaths member(const Member& m) const;
};

// The files of the member folder dir (any campaign's).
MemberPaths member_paths_in(const std::filesystem::path& dir);

// Symbolic links inside a campaign's folder are refused: a link at members/ sends the wrapper
// (<member>/../../run_member.sh) and every scene.json elsewhere, and a member folder linked to
// another member would have that member's files cleared. The results folder itself (and the
// campaign's folder) may be links: paths below them are resolved from there.
// "" when neither the member folder nor its members/ folder is a symbolic link; else why.
std::string linked_member_folder(const std::filesystem::path& member_dir);
// Throws std::runtime_error naming the link when <root>/members is a symbolic link.
void require_no_linked_members_folder(const ResultsLayout& layout);

// Writes text to path atomically (solver/common/atomic_write.hpp).
using capsule::write_file_atomically;
// The whole file as text; "" when it does not exist or cannot be read.
std::string read_file_text(const std::filesystem::path& path);

}  // namespace capsule::study
