// `study`: plan, run, track, export and analyse campaigns (README "Studies").
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "solver/scene/scene.hpp"
#include "study/analysis_bridge.hpp"
#include "study/campaign_error.hpp"
#include "study/campaign_runner.hpp"
#include "study/campaign_survey.hpp"
#include "study/plan_table.hpp"
#include "study/slurm_export.hpp"

namespace {

using namespace capsule::study;

int main_body(int argc, char** argv) {
  CLI::App app{"study: expand campaigns into members, run them with GNU Parallel, resume, report"};
  app.require_subcommand(1);
  std::string results_dir = "results";

  std::string plan_file;
  auto* plan = app.add_subcommand("plan", "list the members, their state and cost; changes nothing");
  plan->add_option("campaign", plan_file, "campaign JSON file")->required();
  plan->add_option("--results", results_dir, "results folder")->capture_default_str();

  RunRequest run_request;
  auto* run = app.add_subcommand("run", "run every member that is not complete (GNU Parallel); resumable");
  run->add_option("campaign", run_request.campaign_file, "campaign JSON file")->required();
  run->add_option("--jobs,-j", run_request.jobs, "members at once (default: 2D members one thread each, as many at once as cores; 3D: one member on every core)")
      ->check(CLI::PositiveNumber);
  run->add_option("--threads,-t", run_request.threads, "OpenMP threads per member (default: chosen)")
      ->check(CLI::PositiveNumber);
  run->add_option("--hosts", run_request.hosts_file,
                  "GNU Parallel --sshloginfile: run members on these hosts (shared filesystem assumed)")
      ->check(CLI::ExistingFile);
  run->add_option("--ssh", run_request.ssh_command, "ssh command for --hosts (GNU Parallel --ssh)");
  run->add_flag("--rerun-unstable", run_request.rerun_unstable, "also rerun members that ended unstable");
  run->add_option("--results", results_dir, "results folder")->capture_default_str();

  std::string status_file;
  auto* status = app.add_subcommand("status", "counts per state and the reasons of failed / unstable members");
  status->add_option("campaign", status_file, "campaign JSON file")->required();
  status->add_option("--results", results_dir, "results folder")->capture_default_str();

  std::string report_file;
  auto* report = app.add_subcommand("report", "fit, tabulate and plot: results/<campaign>/report");
  report->add_option("campaign", report_file, "campaign JSON file")->required();
  report->add_option("--results", results_dir, "results folder")->capture_default_str();

  std::vector<std::string> compare_files;
  bool table2 = false;
  auto* compare = app.add_subcommand("compare", "compare the fits of several campaigns' reports");
  compare->add_option("campaigns", compare_files, "campaign JSON files")->required()->expected(1, -1);
  compare->add_flag("--table2", table2, "also compare with the dissertation's Table 2");
  compare->add_option("--results", results_dir, "results folder")->capture_default_str();

  std::string thesis_out;
  auto* thesis = app.add_subcommand(
      "thesis", "write THESIS.md: Table 2, the ratios b/a and the claims of Chapters 3-5 against the shipped results");
  thesis->add_option("--results", results_dir, "results folder (reads <results>/<campaign>/report/fits.json)")
      ->capture_default_str();
  thesis->add_option("-o,--output", thesis_out, "file to write (default: <results>/THESIS.md)");

  std::string export_file;
  bool slurm = false, export_rerun_unstable = false;
  int export_threads = 0;
  auto* exporter = app.add_subcommand("export", "write a job list and a Slurm array script");
  exporter->add_option("campaign", export_file, "campaign JSON file")->required();
  exporter->add_flag("--slurm", slurm, "write slurm/jobs and slurm/capsule.sbatch")->required();
  exporter->add_option("--threads,-t", export_threads, "CPUs per task (default: 1 for 2D, all cores for 3D)")
      ->check(CLI::PositiveNumber);
  exporter->add_flag("--rerun-unstable", export_rerun_unstable, "include members that ended unstable");
  exporter->add_option("--results", results_dir, "results folder")->capture_default_str();

  CLI11_PARSE(app, argc, argv);

  if (*plan) {
    print_plan(survey_campaign(plan_file, results_dir), std::cout);
    return 0;
  }
  if (*run) {
    run_request.results_dir = results_dir;
    run_request.progress_bar = ::isatty(STDOUT_FILENO) != 0;
    return run_campaign(run_request, std::cout).exit_code;
  }
  if (*status) {
    print_status(survey_campaign(status_file, results_dir), std::cout);
    return 0;
  }
  if (*report) return report_campaign(survey_campaign(report_file, results_dir), std::cout);
  if (*compare) return compare_campaign_files(compare_files, table2, results_dir, std::cout);
  if (*thesis) {
    const std::filesystem::path out = thesis_out.empty() ? std::filesystem::path(results_dir) / "THESIS.md"
                                                         : std::filesystem::path(thesis_out);
    return write_thesis_comparison(results_dir, out, std::cout);
  }
  if (*exporter) {
    const CampaignSurvey survey = survey_campaign(export_file, results_dir);
    const SlurmExport e = export_slurm(survey, export_threads, export_rerun_unstable);
    std::cout << "job list: " << e.job_list.string() << "\nscript:   " << e.script.string() << "\n"
              << e.pending.size() << " of " << survey.members.size() << " members to run; submit with: sbatch "
              << e.script.string() << "\n";
    return 0;
  }
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return main_body(argc, argv);
  } catch (const CampaignError& e) {
    std::cerr << "study: " << e.what() << "\n";
    return 2;
  } catch (const capsule::SceneError& e) {
    std::cerr << "study: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "study: " << e.what() << "\n";
    return 1;
  }
}
