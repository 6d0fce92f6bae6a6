// `study`: plan, run, track, export and analyse campaigns (docs/guide/campaigns.md "Commands").
#include <CLI/CLI.hpp>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "solver/app/cli_support.hpp"
#include "solver/io/member_file.hpp"
#include "solver/scene/json_text.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "study/report/analysis_commands.hpp"
#include "study/campaign/campaign_error.hpp"
#include "study/state/campaign_owner.hpp"
#include "study/run/campaign_runner.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/state/exit_status.hpp"
#include "study/campaign/campaign_files.hpp"
#include "study/run/member_run.hpp"
#include "study/run/provenance.hpp"
#include "study/campaign/member_selection.hpp"
#include "study/plan/plan_table.hpp"
#include "study/run/run_lock.hpp"
#include "study/run/script_path.hpp"
#include "study/slurm/slurm_export.hpp"
#include "study/state/status_json.hpp"
#include "build_info.hpp"

namespace {

using namespace capsule::study;

CLI::Validator slurm_form(bool (*accepts)(const std::string&), const std::string& allowed) {
  return CLI::Validator(
      [accepts, allowed](std::string& text) -> std::string {
        return accepts(text) ? "" : "\"" + text + "\" is not in Slurm's form (allowed: " + allowed + ")";
      },
      "SLURM");
}

int main_body(int argc, char** argv) {
  CLI::App app{"study: expand campaigns into members, run them with GNU Parallel, resume, report"};
  app.footer(std::string("Examples:\n"
                         "  study plan campaigns/ch3_ca.json          members, state and cost; changes nothing\n"
                         "  study run campaigns/demo.json             run what is not complete (resumable)\n"
                         "  study run campaigns/ch3_ca.json --where resolution.a=5\n"
                         "  study status campaigns/demo.json\n"
                         "  study report campaigns/demo.json          fits, tables, figures\n"
                         "  study plan campaigns/ch*.json             every campaign of the dissertation\n") +
             exit_status_help());
  app.set_version_flag("--version", std::string("study ") + capsule::build::code_version +
                                        " (physics version " + capsule::physics_version + ")",
                       "print the code version and physics version, then exit");
  app.require_subcommand(1);
  std::string results_dir = "results";
  const auto count = capsule::cli::whole_number_at_least(1);

  std::vector<std::string> plan_files;
  auto* plan = app.add_subcommand("plan", "list the members, their state and cost; changes nothing");
  plan->add_option("campaign", plan_files,
                   "campaign JSON files, or folders of them (campaigns/ch*.json: every campaign of the dissertation, shared members "
                   "counted once in the total)")
      ->required()->expected(1, -1);
  plan->add_option("--results", results_dir, "results folder")->capture_default_str();
  std::vector<std::string> plan_cases, plan_where;
  plan->add_option("--case", plan_cases, "plan only the members of this case (repeatable), as `study run --case`");
  plan->add_option("--where", plan_where,
                   "plan only the members whose scene has KEY=VALUE (repeatable, all must hold), as `study run --where`");

  RunRequest run_request;
  auto* run = app.add_subcommand("run", "run every member that is not complete (GNU Parallel); resumable");
  run->footer(exit_status_help());
  std::vector<std::string> run_files;
  run->add_option("campaign", run_files,
                  "campaign JSON files, or folders of them: run one after another, in path order (a member shared "
                  "with an earlier one is copied from it)")
      ->required()->expected(1, -1);
  run->add_option("--jobs,-j", run_request.jobs, "members at once (default: 2D members one thread each, as many at once as cores; 3D: one member on every core)")
      ->check(count);
  run->add_option("--threads,-t", run_request.threads, "OpenMP threads per member (default: chosen)")->check(count);
  run->add_option("--hosts", run_request.hosts_file,
                  "GNU Parallel --sshloginfile: run members on these hosts (shared filesystem assumed)")
      ->check(CLI::ExistingFile);
  run->add_option("--ssh", run_request.ssh_command, "ssh command for --hosts (GNU Parallel --ssh)");
  run->add_option("--retries", run_request.retries,
                  "with --hosts: tries of a member whose start failed (ssh could not reach its host), each on "
                  "another host; a member that ran and failed is not retried")
      ->capture_default_str()->check(count);
  run->add_option("--checkpoint-seconds", run_request.checkpoint_seconds,
                  "wall seconds between a member's restart points (capsule --checkpoint-seconds)")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0, 1e7));
  run->add_flag("--rerun-unstable", run_request.rerun_unstable, "also rerun members that ended unstable");
  run->add_flag("--allow-dirty", run_request.allow_dirty,
                "run even when this build's sources differ from every commit (recorded in run.json)");
  run->add_flag("--no-reuse{false}", run_request.reuse_finished,
                "run every member here, even one that another campaign under the results folder finished "
                "(default: copy that member's files)");
  run->add_flag("--rerun-stopped", run_request.rerun_stopped,
                "also rerun members that stopped (the solver refused their configuration)");
  run->add_option("--case", run_request.cases,
                  "run only the members of this case (repeatable; e.g. the 2D case of a campaign with 2D and 3D cases)");
  run->add_option("--where", run_request.where,
                  "run only the members whose scene has KEY=VALUE (repeatable, all must hold; e.g. resolution.a=5 "
                  "runs the cheap level of a resolution ladder first)");
  run->add_option("--results", results_dir, "results folder")->capture_default_str();

  MemberRunRequest member_request;
  auto* run_member = app.add_subcommand(
      "run-member", "run one member folder as every engine does (the generated run_member.sh execs it): its lock, "
                    "a complete member left alone, capsule's output appended to capsule.log, signals passed on");
  run_member->add_option("member_dir", member_request.member_dir, "the member's folder (<results>/<campaign>/members/<member>)")
      ->required()->check(CLI::ExistingDirectory);
  run_member->add_option("threads", member_request.threads, "OpenMP threads of the member")->required()->check(count);
  run_member->add_option("--capsule", member_request.capsule_binary, "the capsule binary")->required();
  run_member->add_option("--code-version", member_request.expected_code_version,
                         "start the member only if the capsule binary reports this code version (`capsule version`)");
  run_member->add_option("--checkpoint-seconds", member_request.checkpoint_seconds,
                         "wall seconds between restart points")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0, 1e7));

  std::string status_file;
  bool status_as_json = false;
  auto* status = app.add_subcommand("status", "counts per state and the reasons of failed / unstable members");
  status->footer(exit_status_help());
  status->add_option("campaign", status_file, "campaign JSON file")->required();
  status->add_flag("--json", status_as_json, "print the status as one JSON object (for scripts)");
  status->add_option("--results", results_dir, "results folder")->capture_default_str();

  std::string report_file;
  auto* report = app.add_subcommand("report", "fit, tabulate and plot: results/<campaign>/report");
  report->footer(exit_status_help());
  report->add_option("campaign", report_file, "campaign JSON file")->required();
  report->add_option("--results", results_dir, "results folder")->capture_default_str();
  ReportOptions report_options;
  report->add_flag("--partial", report_options.partial,
                   "write the report even when some member files cannot be read (report/PARTIAL.md names them); "
                   "without it such a report is refused and the previous one kept");

  bool legacy_member_files = false;
  const std::string legacy_help =
      "also read member files without a content hash (written before it existed); their content cannot be checked";
  report->add_flag("--legacy-member-files", legacy_member_files, legacy_help);

  std::vector<std::string> compare_files;
  bool table2 = false;
  auto* compare = app.add_subcommand("compare", "compare the fits of several campaigns' reports");
  compare->add_option("campaigns", compare_files, "campaign JSON files")->required()->expected(1, -1);
  compare->add_flag("--table2", table2, "also compare with the dissertation's Table 2");
  compare->add_option("--results", results_dir, "results folder")->capture_default_str();

  std::string thesis_out;
  auto* thesis = app.add_subcommand(
      "thesis", "write THESIS.md: Table 2, the ratios b/a and the claims of Chapters 2-5 against the shipped results");
  thesis->alias("dissertation");  // the word the documents and the code use; `thesis` stays for THESIS.md's users
  thesis->add_option("--results", results_dir, "results folder (reads <results>/<campaign>/report/fits.json)")
      ->capture_default_str();
  thesis->add_option("-o,--output", thesis_out, "file to write (default: <results>/THESIS.md)");
  thesis->add_flag("--legacy-member-files", legacy_member_files, legacy_help);

  std::vector<std::string> export_files;
  bool slurm = false;
  SlurmOptions slurm_options;
  auto* exporter = app.add_subcommand("export", "write a job list and a Slurm array script");
  exporter->add_option("campaign", export_files, "campaign JSON files, or folders of them")->required()->expected(1, -1);
  exporter->add_flag("--slurm", slurm, "write slurm/jobs and slurm/capsule.sbatch")->required();
  exporter->add_option("--threads,-t", slurm_options.threads,
                       "CPUs per task (default: 1 for 2D, " + std::to_string(default_3d_cpus) + " for 3D)")
      ->check(count);
  exporter->add_option("--time", slurm_options.time,
                       "Slurm --time per task (default: from the cost estimate of the largest member)")
      ->check(slurm_form(is_slurm_time, "minutes, H:MM:SS, D-HH[:MM[:SS]], at most 8 digits a number"));
  exporter->add_option("--mem", slurm_options.mem,
                       "Slurm --mem per task (default: from the lattice size of the largest member)")
      ->check(slurm_form(is_slurm_mem, "megabytes, or a number with K, M, G or T, at most 12 digits"));
  exporter->add_flag("--rerun-unstable", slurm_options.rerun_unstable, "include members that ended unstable");
  exporter->add_flag("--allow-dirty", slurm_options.allow_dirty,
                     "export even when this build's sources differ from every commit");
  exporter->add_flag("--rerun-stopped", slurm_options.rerun_stopped, "include members that stopped");
  exporter->add_flag("--no-reuse{false}", slurm_options.reuse_finished,
                     "export every member, even one that another campaign under the results folder finished "
                     "(default: copy that member's files)");
  exporter->add_option("--checkpoint-seconds", slurm_options.checkpoint_seconds,
                       "wall seconds between a member's restart points (a task also writes one 120 s before its time "
                       "limit)")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0, 1e7));
  exporter->add_option("--array-max", slurm_options.array_max,
                       "members per script: an array over this many is split into several (Slurm's MaxArraySize, "
                       "default 1001, bounds the task ids)")
      ->capture_default_str()->check(count);
  exporter->add_option("--throttle", slurm_options.throttle, "at most N tasks of a script at once (--array=...%N)")
      ->check(count);
  exporter->add_option("--partition,-p", slurm_options.partition, "#SBATCH --partition");
  exporter->add_option("--account,-A", slurm_options.account, "#SBATCH --account");
  exporter->add_option("--qos", slurm_options.qos, "#SBATCH --qos");
  exporter->add_option("--sbatch", slurm_options.sbatch_lines,
                       "a further #SBATCH line, e.g. --sbatch=--constraint=avx2 (repeatable)");
  exporter->add_option("--results", results_dir, "results folder")->capture_default_str();

  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  capsule::io::accept_files_without_content_hash(legacy_member_files);

  if (*plan) {
    const std::vector<std::string> files = campaign_files_of(plan_files);
    if (files.size() > 1) {
      if (!plan_cases.empty() || !plan_where.empty()) {
        std::cerr << "study plan: --case and --where plan one campaign file at a time\n";
        return exit_usage;
      }
      print_plans(files, results_dir, std::cout);
      return exit_ok;
    }
    const Campaign campaign = load_campaign(files.front());
    const ResultsLayout layout(results_dir, campaign.name);
    require_same_campaign(campaign, layout);
    print_plan(campaign, layout, std::cout,  // member by member: bounded memory
               select_members(files.front(), campaign, plan_cases, plan_where));
    return exit_ok;
  }
  run_request.allow_dirty = run_request.allow_dirty || allow_dirty_from_environment();
  slurm_options.allow_dirty = slurm_options.allow_dirty || allow_dirty_from_environment();
  if (*run_member) return run_one_member(member_request, std::cerr);
  if (*run) {
    run_request.results_dir = results_dir;
    run_request.progress_bar = ::isatty(STDOUT_FILENO) != 0;
    const std::vector<std::string> files = campaign_files_of(run_files);
    std::vector<int> codes;
    for (std::size_t i = 0; i < files.size(); ++i) {
      if (files.size() > 1) std::cout << "\n== " << files[i] << "\n" << std::flush;
      run_request.campaign_file = files[i];
      codes.push_back(run_campaign(run_request, std::cout).exit_code);
      if (const int signal = stop_signal_received(); signal != 0 && i + 1 < files.size()) {
        std::cout << "\nstopped by signal " << signal << " (" << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                  << "): " << files.size() - i - 1 << " campaign" << (files.size() - i - 1 == 1 ? "" : "s")
                  << " not started:";
        for (std::size_t j = i + 1; j < files.size(); ++j) std::cout << " " << files[j];
        std::cout << "\n";
        codes.push_back(exit_members_missing);
        break;
      }
    }
    return worst_exit_code(codes);
  }
  if (*status) {
    const CampaignSurvey survey = survey_campaign(status_file, results_dir, SurveyDetail::states_only);
    if (status_as_json) std::cout << status_json(survey).dump(2) << "\n";
    else print_status(survey, std::cout);
    return members_exit_code(survey);
  }
  if (*report) return report_campaign(survey_campaign(report_file, results_dir), report_options, std::cout);
  if (*compare) return compare_campaign_files(compare_files, table2, results_dir, std::cout);
  if (*thesis) {
    const std::filesystem::path out = thesis_out.empty() ? std::filesystem::path(results_dir) / "THESIS.md"
                                                         : std::filesystem::path(thesis_out);
    return write_dissertation_comparison(results_dir, out, std::cout);
  }
  if (*exporter) {
    for (const auto& file : campaign_files_of(export_files)) {
      const CampaignSurvey survey = survey_campaign(file, results_dir);
    const SlurmExport e = export_slurm(survey, slurm_options);
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
    return exit_ok;
  }
  return exit_usage;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return main_body(argc, argv);
  } catch (const CampaignError& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_usage;
  } catch (const capsule::SceneError& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_usage;
  } catch (const UnsafePathError& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_usage;
  } catch (const DirtyBuild& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_usage;
  } catch (const RunStillGoing& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_run_still_going;
  } catch (const std::exception& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_failure;
  }
}
