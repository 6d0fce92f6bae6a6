// `study`: plan, run, track, export and analyse campaigns (docs/guide/campaigns.md "Commands").
// The dispatcher: each subcommand, with its options, is a file of study/commands/.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "common/cli_support.hpp"
#include "common/json_text.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "study/campaign/campaign_error.hpp"
#include "study/commands/commands.hpp"
#include "study/run/provenance.hpp"
#include "study/run/run_lock.hpp"
#include "study/run/script_path.hpp"
#include "study/state/exit_status.hpp"
#include "build_info.hpp"

namespace {

using namespace capsule::study;

// The exit status of a command that threw: 2 for what the user can correct (a bad campaign,
// scene or path, a dirty build), 5 while another run of the campaign is going, else 1.
int exit_status_of(const std::exception& e) {
  if (dynamic_cast<const CampaignError*>(&e) || dynamic_cast<const capsule::SceneError*>(&e) ||
      dynamic_cast<const UnsafePathError*>(&e) || dynamic_cast<const DirtyBuild*>(&e))
    return exit_usage;
  if (dynamic_cast<const RunStillGoing*>(&e)) return exit_run_still_going;
  return exit_failure;
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
  const std::vector<capsule::cli::Command> commands{
      add_plan_command(app),   add_run_command(app),     add_run_member_command(app), add_status_command(app),
      add_report_command(app), add_compare_command(app), add_thesis_command(app),     add_export_command(app)};
  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  for (const auto& command : commands)
    if (command.app->parsed()) return command.run();
  return exit_usage;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return main_body(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "study: " << capsule::terminal_text(e.what()) << "\n";
    return exit_status_of(e);
  }
}
