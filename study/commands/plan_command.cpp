// `study plan`: the members of one campaign (or of several, shared members counted once), their
// state and cost (study/plan/plan_table.hpp); changes nothing.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "study/campaign/campaign.hpp"
#include "study/campaign/campaign_files.hpp"
#include "study/campaign/member_selection.hpp"
#include "study/commands/commands.hpp"
#include "study/plan/plan_table.hpp"
#include "study/state/campaign_owner.hpp"
#include "study/state/exit_status.hpp"

namespace capsule::study {

namespace {

struct PlanArguments {
  std::vector<std::string> files;
  std::string results_dir = "results";
  std::vector<std::string> cases, where;
};

int plan(const PlanArguments& a) {
  const std::vector<std::string> files = campaign_files_of(a.files);
  if (files.size() > 1) {
    if (!a.cases.empty() || !a.where.empty()) {
      std::cerr << "study plan: --case and --where plan one campaign file at a time\n";
      return exit_usage;
    }
    print_plans(files, a.results_dir, std::cout);
    return exit_ok;
  }
  const Campaign campaign = load_campaign(files.front());
  const ResultsLayout layout(a.results_dir, campaign.name);
  require_same_campaign(campaign, layout);
  print_plan(campaign, layout, std::cout,  // member by member: bounded memory
             select_members(files.front(), campaign, a.cases, a.where));
  return exit_ok;
}

}  // namespace

cli::Command add_plan_command(CLI::App& study) {
  auto a = std::make_shared<PlanArguments>();
  CLI::App& app = *study.add_subcommand("plan", "list the members, their state and cost; changes nothing");
  app.add_option("campaign", a->files,
                 "campaign JSON files, or folders of them (campaigns/ch*.json: every campaign of the dissertation, shared members "
                 "counted once in the total)")
      ->required()->expected(1, -1);
  app.add_option("--results", a->results_dir, "results folder")->capture_default_str();
  app.add_option("--case", a->cases, "plan only the members of this case (repeatable), as `study run --case`");
  app.add_option("--where", a->where,
                 "plan only the members whose scene has KEY=VALUE (repeatable, all must hold), as `study run --where`");
  return {&app, [a] { return plan(*a); }};
}

}  // namespace capsule::study
