#include "study/slurm/slurm_export.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "build_info.hpp"
#include "study/run/capsule_binary.hpp"
#include "study/run/provenance.hpp"
#include "study/state/member_reuse.hpp"
#include "study/run/script_path.hpp"
#include "study/campaign/member_id.hpp"
#include "study/run/member_wrapper.hpp"
#include "study/state/run_record.hpp"
#include "study/run/run_lock.hpp"
#include "study/run/shell_quote.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

std::string array_spec(const std::vector<std::size_t>& indices) {
  std::string spec;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    // append(), not operator+: GCC 12 -O3 reports a false -Wrestrict on "literal" + string.
    if (!spec.empty()) spec.append(",");
    spec.append(std::to_string(indices[i]));
    if (j > i) spec.append("-").append(std::to_string(indices[j]));
    i = j + 1;
  }
  return spec;
}

std::string sbatch_output_line(const fs::path& slurm_dir) {
  const std::string dir = slurm_dir.string();
  if (dir.find_first_of("\"\\") != std::string::npos)
    throw UnsafePathError("the Slurm folder contains a '\"' or '\\', which an #SBATCH line cannot quote: " + dir);
  std::string escaped;  // Slurm expands %A, %a, %j, ... in the output name: a literal % is %%
  for (char c : dir) escaped += c == '%' ? std::string("%%") : std::string(1, c);
  return "#SBATCH --output=\"" + escaped + "/task-%A_%a.out\"";
}

namespace {

// A partition, account or QOS name: what Slurm allows, nothing a script could read otherwise.
void require_slurm_name(const std::string& option, const std::string& value) {
  if (value.empty()) return;
  for (char c : value)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == ',' || c == ':' ||
          c == '+'))
      throw UnsafePathError(option + " \"" + value +
                                  "\" is not a Slurm name (allowed: letters, digits and _ - . , : +)");
}

// An extra #SBATCH line: one option ("--x" or "--x=value"), no line break.
void require_sbatch_line(const std::string& line) {
  for (char c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw UnsafePathError("--sbatch \"" + line + "\" contains a control character, refused in a generated script");
  if (line.rfind("--", 0) != 0) throw UnsafePathError("--sbatch \"" + line + "\": an sbatch option starts with --");
}

std::string job_name_base(const CampaignSurvey& survey) {
  // Two results folders may hold campaigns of one name: the folder's hash tells their jobs apart.
  char hash[9];
  std::snprintf(hash, sizeof hash, "%08llx",
                static_cast<unsigned long long>(fnv1a_64(survey.layout.root.string()) & 0xffffffffull));
  return std::string(survey.campaign.name).append("-").append(hash);
}


// Every path and name that reaches the job list or a script, checked before anything is written.
void require_safe_export(const CampaignSurvey& survey, const SlurmOptions& options, const fs::path& capsule_binary) {
  require_script_safe("the results folder", survey.layout.root);
  require_script_safe("the capsule binary's path", capsule_binary);
  require_slurm_name("--partition", options.partition);
  require_slurm_name("--account", options.account);
  require_slurm_name("--qos", options.qos);
  for (const auto& line : options.sbatch_lines) require_sbatch_line(line);
  if (options.array_max < 1) throw UnsafePathError("--array-max must be at least 1");
}

// A member another campaign under the same results folder finished is copied, not exported:
// the indices of those copied, their "copied ..." lines in *lines.
std::vector<std::size_t> copy_finished_elsewhere(const CampaignSurvey& survey, std::string& lines) {
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < survey.members.size(); ++i)
    if (const MemberState st = survey.conditions[i].state;
        needs_run(survey.conditions[i], false, false) && st != MemberState::unstable && st != MemberState::stopped)
      candidates.push_back(i);
  std::ostringstream out;
  const auto copied = copy_reusable_members(survey.members, candidates, survey.layout, out);
  lines = out.str();
  return copied;
}

// One script per array_max members that have work (Slurm refuses an index >= MaxArraySize):
// capsule.sbatch, or capsule-<k>.sbatch when split.
std::vector<SlurmScript> split_into_scripts(const std::vector<std::size_t>& pending, std::size_t array_max,
                                            const std::string& base, const fs::path& slurm_dir) {
  std::vector<SlurmScript> scripts;
  for (std::size_t i : pending) {
    const std::size_t k = i / array_max;
    if (scripts.empty() || scripts.back().offset != k * array_max) {
      SlurmScript sc;
      sc.offset = k * array_max;
      sc.job_name = base;
      sc.job_name.append("-").append(std::to_string(k));
      scripts.push_back(sc);
    }
    scripts.back().tasks.push_back(i - scripts.back().offset);
  }
  if (scripts.empty()) scripts.push_back(SlurmScript{{}, std::string(base).append("-0"), 0, {}});
  const bool split = scripts.size() > 1;
  for (auto& sc : scripts)
    sc.path = slurm_dir / (split ? std::string("capsule-").append(std::to_string(sc.offset / array_max)).append(".sbatch")
                                 : std::string("capsule.sbatch"));
  return scripts;
}

// The #SBATCH lines of one script: its array, resources, output file, signal and the options given.
std::string sbatch_lines(const SlurmScript& sc, const SlurmResources& r, const SlurmOptions& options,
                         const std::string& output_line) {
  std::ostringstream s;
  s << "#SBATCH --job-name=" << sc.job_name << "\n";
  if (!sc.tasks.empty()) {
    s << "#SBATCH --array=" << array_spec(sc.tasks);
    if (options.throttle > 0) s << "%" << options.throttle;
    s << "\n";
  }
  s << "#SBATCH --cpus-per-task=" << r.cpus << "\n"
    << "#SBATCH --time=" << r.time << "\n"
    << "#SBATCH --mem=" << r.mem << "\n"
    << "#SBATCH --ntasks=1\n"
    << output_line << "\n"
    << "#SBATCH --signal=B:USR1@120\n";
  if (!options.partition.empty()) s << "#SBATCH --partition=" << options.partition << "\n";
  if (!options.account.empty()) s << "#SBATCH --account=" << options.account << "\n";
  if (!options.qos.empty()) s << "#SBATCH --qos=" << options.qos << "\n";
  for (const auto& line : options.sbatch_lines) s << "#SBATCH " << line << "\n";
  return s.str();
}

// One sbatch array script: task t runs the member on line offset + t + 1 of the job list
// through the member wrapper.
std::string sbatch_script(const CampaignSurvey& survey, const SlurmExport& result, const SlurmScript& sc,
                          const SlurmOptions& options, const std::string& output_line) {
  const SlurmResources& r = result.resources;
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Generated by `study export --slurm` for campaign " << survey.campaign.name << ".\n"
    << "# Array task t runs member " << sc.offset << " + t (line " << sc.offset << " + t + 1 of the job list); the\n"
    << "# results folder must be on a filesystem every node shares. Submit every script: sh "
    << shell_quote(result.submit.string()) << "\n"
    << "# Afterwards: study status <campaign file> (completion is read from each member file; queued\n"
    << "# tasks from squeue). Before resubmitting, export again: finished and queued members are left out.\n"
    << "# --time and --mem: the largest pending member's cost estimate with margins (override them\n"
    << "# with study export --time / --mem); --cpus-per-task: study export --threads, else 1 (2D) or "
    << default_3d_cpus << " (3D).\n"
    << "# --signal: 120 s before the time limit the member writes a restart point and stops; the next\n"
    << "# submission continues it from there.\n"
    << sbatch_lines(sc, r, options, output_line) << "set -euo pipefail\n";
  if (sc.tasks.empty())
    s << "echo \"nothing to run: every member of campaign " << survey.campaign.name
      << " was finished or queued when this script was exported\"\n"
      << "exit 0\n";
  s << "job_list=" << shell_quote(result.job_list.string()) << "\n"
    << "wrapper=" << shell_quote(survey.layout.wrapper().string()) << "\n"
    << "task=${SLURM_ARRAY_TASK_ID:?set by sbatch --array}\n"
    << "member_dir=$(sed -n \"$((" << sc.offset << " + task + 1))p\" \"$job_list\")\n"
    << "if [ -z \"$member_dir\" ]; then echo \"no member " << sc.offset << " + $task in $job_list\" >&2; exit 2; fi\n"
    << "echo \"task $task of job ${SLURM_ARRAY_JOB_ID:-?}: $member_dir (its log: $member_dir/capsule.log)\"\n"
    << "exec \"$wrapper\" \"$member_dir\" \"${SLURM_CPUS_PER_TASK:-" << r.cpus << "}\"\n";
  return s.str();
}

void write_executable(const fs::path& path, const std::string& text) {
  write_file_atomically(path, text);
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
}

// Writes the scripts, submit.sh (sbatch of every script with work) and export.json.
void write_scripts(const CampaignSurvey& survey, const SlurmExport& result, const SlurmOptions& options,
                   const std::string& output_line) {
  const fs::path slurm_dir = survey.layout.slurm_dir();
  nlohmann::json record = {{"exported", utc_now_iso8601()},
                           {"campaign", survey.campaign.name},
                           {"job_list", result.job_list.string()},
                           {"scripts", nlohmann::json::array()}};
  std::string submit = "#!/bin/sh\n# Generated by `study export --slurm` for campaign ";
  submit.append(survey.campaign.name)
      .append(": submits every script of this export.\n# Arguments go to each sbatch, e.g. "
              "sh submit.sh -p PARTITION -A ACCOUNT\nset -e\n");
  for (const SlurmScript& sc : result.scripts) {
    write_executable(sc.path, sbatch_script(survey, result, sc, options, output_line));
    if (!sc.tasks.empty()) submit.append("sbatch \"$@\" ").append(shell_quote(sc.path.string())).append("\n");
    record["scripts"].push_back({{"script", sc.path.string()},
                                 {"job_name", sc.job_name},
                                 {"offset", sc.offset},
                                 {"tasks", sc.tasks.size()}});
  }
  write_executable(result.submit, submit);
  write_file_atomically(slurm_dir / "export.json", record.dump(2) + "\n");
}

}  // namespace

SlurmExport export_slurm(const CampaignSurvey& survey, const SlurmOptions& options) {
  const fs::path capsule_binary = find_capsule_binary();
  const fs::path slurm_dir = survey.layout.slurm_dir();
  require_committed_build(build::code_version, options.allow_dirty, "study export");
  const std::string capsule_version = capsule_code_version(capsule_binary);
  require_committed_build(capsule_version, options.allow_dirty, "study export (capsule binary " + capsule_binary.string() + ")");
  require_safe_export(survey, options, capsule_binary);
  const std::string output_line = sbatch_output_line(slurm_dir);

  // A `study run` of this campaign still going would start members this export lists: one
  // member would then run twice in one folder. Held while exporting (exit 5 like run).
  fs::create_directories(survey.layout.root);
  const RunLock lock(survey.layout.lock_file(), survey.layout.running_info(), members_in_progress(survey));

  SlurmExport result;
  result.job_list = slurm_dir / "jobs";
  result.submit = slurm_dir / "submit.sh";
  prepare_member_directories(survey);
  const std::vector<std::size_t> copied =
      options.reuse_finished ? copy_finished_elsewhere(survey, result.copied) : std::vector<std::size_t>{};
  std::string list;
  std::vector<const Member*> pending_members;
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    list += survey.layout.member(survey.members[i]).dir.string() + "\n";
    if (std::find(copied.begin(), copied.end(), i) != copied.end()) continue;
    // Queued members (an earlier submission waits in Slurm's queue) are not needs_run: left out.
    if (needs_run(survey.conditions[i], options.rerun_unstable, options.rerun_stopped)) {
      result.pending.push_back(i);
      pending_members.push_back(&survey.members[i]);
    }
  }
  result.resources = slurm_resources(pending_members, options.threads, options.time, options.mem);
  result.scripts = split_into_scripts(result.pending, options.array_max, job_name_base(survey), slurm_dir);

  fs::create_directories(slurm_dir);
  // Scripts of an earlier export would run an out-of-date array: removed (the wrapper would
  // still refuse to run a complete member twice, but a stale script has no business here).
  for (const auto& e : fs::directory_iterator(slurm_dir))
    if (const std::string f = e.path().filename().string(); f.rfind("capsule", 0) == 0 && e.path().extension() == ".sbatch")
      fs::remove(e.path());
  write_file_atomically(result.job_list, list);
  write_member_wrapper(survey.layout.wrapper(),
                       {survey.campaign.name, own_executable(), capsule_binary, options.checkpoint_seconds, capsule_version});
  write_scripts(survey, result, options, output_line);
  return result;
}

}  // namespace capsule::study
