// `study export CAMPAIGN... --slurm`: per campaign, a job list and Slurm array scripts
// (study/slurm/slurm_export.hpp), and a line saying what to submit.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "study/campaign/campaign_files.hpp"
#include "study/commands/commands.hpp"
#include "study/run/provenance.hpp"
#include "study/slurm/slurm_export.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/state/exit_status.hpp"
#include "study/slurm/slurm_queue.hpp"

namespace capsule::study {

namespace {

struct ExportArguments {
  std::vector<std::string> files;
  std::string results_dir = "results";
  bool slurm = false;
  SlurmOptions options;
};

// An option value Slurm reads (--time, --mem), checked against its form.
CLI::Validator slurm_form(bool (*accepts)(const std::string&), const std::string& allowed) {
  return CLI::Validator(
      [accepts, allowed](std::string& text) -> std::string {
        return accepts(text) ? "" : "\"" + text + "\" is not in Slurm's form (allowed: " + allowed + ")";
      },
      "SLURM");
}

void print_export(const SlurmExport& e, const CampaignSurvey& survey) {
  std::cout << e.copied << "job list: " << e.job_list.string() << "\n";
  for (const auto& sc : e.scripts)
    std::cout << "script:   " << sc.path.string() << " (" << sc.tasks.size() << " tasks, job " << sc.job_name << ")\n";
  std::cout << e.pending.size() << " of " << survey.members.size() << " members to run";
  if (e.pending.empty())
    std::cout << ": nothing to submit\n";
  else
    std::cout << " (" << e.resources.cpus << " CPUs, --time " << e.resources.time << ", --mem " << e.resources.mem
              << " per task); submit with: sh " << e.submit.string() << " (arguments go to sbatch)\n";
}

int export_campaigns(ExportArguments& a) {
  a.options.allow_dirty = a.options.allow_dirty || allow_dirty_from_environment();
  for (const auto& file : campaign_files_of(a.files)) {
    const CampaignSurvey survey = survey_campaign(file, a.results_dir, slurm_queue);
    print_export(export_slurm(survey, a.options), survey);
  }
  return exit_ok;
}

}  // namespace

cli::Command add_export_command(CLI::App& study) {
  auto a = std::make_shared<ExportArguments>();
  SlurmOptions& o = a->options;
  const auto count = cli::whole_number_at_least(1);
  CLI::App& app = *study.add_subcommand("export", "write a job list and a Slurm array script");
  app.add_option("campaign", a->files, "campaign JSON files, or folders of them")->required()->expected(1, -1);
  app.add_flag("--slurm", a->slurm, "write slurm/jobs and slurm/capsule.sbatch")->required();
  app.add_option("--threads,-t", o.threads,
                 "CPUs per task (default: 1 for 2D, " + std::to_string(default_3d_cpus) + " for 3D)")
      ->check(count);
  app.add_option("--time", o.time, "Slurm --time per task (default: from the cost estimate of the largest member)")
      ->check(slurm_form(is_slurm_time, "minutes, H:MM:SS, D-HH[:MM[:SS]], at most 8 digits a number"));
  app.add_option("--mem", o.mem, "Slurm --mem per task (default: from the lattice size of the largest member)")
      ->check(slurm_form(is_slurm_mem, "megabytes, or a number with K, M, G or T, at most 12 digits"));
  app.add_flag("--rerun-unstable", o.rerun_unstable, "include members that ended unstable");
  app.add_flag("--allow-dirty", o.allow_dirty, "export even when this build's sources differ from every commit");
  app.add_flag("--rerun-stopped", o.rerun_stopped, "include members that stopped");
  app.add_flag("--no-reuse{false}", o.reuse_finished,
               "export every member, even one that another campaign under the results folder finished "
               "(default: copy that member's files)");
  app.add_option("--checkpoint-seconds", o.checkpoint_seconds,
                 "wall seconds between a member's restart points (a task also writes one 120 s before its time "
                 "limit)")
      ->capture_default_str()->check(cli::finite_number_in(0, 1e7));
  app.add_option("--array-max", o.array_max,
                 "members per script: an array over this many is split into several (Slurm's MaxArraySize, "
                 "default 1001, bounds the task ids)")
      ->capture_default_str()->check(count);
  app.add_option("--throttle", o.throttle, "at most N tasks of a script at once (--array=...%N)")->check(count);
  app.add_option("--partition,-p", o.partition, "#SBATCH --partition");
  app.add_option("--account,-A", o.account, "#SBATCH --account");
  app.add_option("--qos", o.qos, "#SBATCH --qos");
  app.add_option("--sbatch", o.sbatch_lines, "a further #SBATCH line, e.g. --sbatch=--constraint=avx2 (repeatable)");
  app.add_option("--results", a->results_dir, "results folder")->capture_default_str();
  return {&app, [a] { return export_campaigns(*a); }};
}

}  // namespace capsule::study
