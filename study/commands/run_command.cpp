// `study run`: the campaigns one after another (study/run/campaign_runner.hpp), each running
// every member that is not complete; a stop by signal starts no further campaign.
#include <csignal>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#include "study/campaign/campaign_files.hpp"
#include "study/commands/commands.hpp"
#include "study/run/campaign_runner.hpp"
#include "study/run/provenance.hpp"
#include "study/state/exit_status.hpp"
#include "study/slurm/slurm_queue.hpp"

namespace capsule::study {

namespace {

struct RunArguments {
  std::vector<std::string> files;
  std::string results_dir = "results";
  RunRequest request;
};

int run(RunArguments& a) {
  RunRequest& request = a.request;
  request.allow_dirty = request.allow_dirty || allow_dirty_from_environment();
  request.results_dir = a.results_dir;
  request.progress_bar = ::isatty(STDOUT_FILENO) != 0;
  const std::vector<std::string> files = campaign_files_of(a.files);
  std::vector<int> codes;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (files.size() > 1) std::cout << "\n== " << files[i] << "\n" << std::flush;
    request.campaign_file = files[i];
    codes.push_back(run_campaign(request, slurm_queue, std::cout).exit_code);
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

}  // namespace

cli::Command add_run_command(CLI::App& study) {
  auto a = std::make_shared<RunArguments>();
  RunRequest& r = a->request;
  const auto count = cli::whole_number_at_least(1);
  CLI::App& app = *study.add_subcommand("run", "run every member that is not complete (GNU Parallel); resumable");
  app.footer(exit_status_help());
  app.add_option("campaign", a->files,
                 "campaign JSON files, or folders of them: run one after another, in path order (a member shared "
                 "with an earlier one is copied from it)")
      ->required()->expected(1, -1);
  app.add_option("--jobs,-j", r.jobs, "members at once (default: 2D members one thread each, as many at once as cores; 3D: one member on every core)")
      ->check(count);
  app.add_option("--threads,-t", r.threads, "OpenMP threads per member (default: chosen)")->check(count);
  app.add_option("--hosts", r.hosts_file,
                 "GNU Parallel --sshloginfile: run members on these hosts (shared filesystem assumed)")
      ->check(CLI::ExistingFile);
  app.add_option("--ssh", r.ssh_command, "ssh command for --hosts (GNU Parallel --ssh)");
  app.add_option("--retries", r.retries,
                 "with --hosts: tries of a member whose start failed (ssh could not reach its host), each on "
                 "another host; a member that ran and failed is not retried")
      ->capture_default_str()->check(count);
  app.add_option("--checkpoint-seconds", r.checkpoint_seconds,
                 "wall seconds between a member's restart points (capsule --checkpoint-seconds)")
      ->capture_default_str()->check(cli::finite_number_in(0, 1e7));
  app.add_flag("--rerun-unstable", r.rerun_unstable, "also rerun members that ended unstable");
  app.add_flag("--allow-dirty", r.allow_dirty,
               "run even when this build's sources differ from every commit (recorded in run.json)");
  app.add_flag("--no-reuse{false}", r.reuse_finished,
               "run every member here, even one that another campaign under the results folder finished "
               "(default: copy that member's files)");
  app.add_flag("--rerun-stopped", r.rerun_stopped,
               "also rerun members that stopped (the solver refused their configuration)");
  app.add_option("--case", r.cases,
                 "run only the members of this case (repeatable; e.g. the 2D case of a campaign with 2D and 3D cases)");
  app.add_option("--where", r.where,
                 "run only the members whose scene has KEY=VALUE (repeatable, all must hold; e.g. resolution.a=5 "
                 "runs the cheap level of a resolution ladder first)");
  app.add_option("--results", a->results_dir, "results folder")->capture_default_str();
  return {&app, [a] { return run(*a); }};
}

}  // namespace capsule::study
