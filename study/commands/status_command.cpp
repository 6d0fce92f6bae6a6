// `study status CAMPAIGN`: counts per state and the reasons of failed / unstable members, as
// text or one JSON object (study/state/status_json.hpp); the exit status says what is left.
#include <iostream>
#include <memory>
#include <string>

#include "study/commands/commands.hpp"
#include "study/run/campaign_runner.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/state/exit_status.hpp"
#include "study/state/status_json.hpp"
#include "study/slurm/slurm_queue.hpp"

namespace capsule::study {

namespace {

struct StatusArguments {
  std::string file;
  std::string results_dir = "results";
  bool as_json = false;
};

int status(const StatusArguments& a) {
  const CampaignSurvey survey = survey_campaign(a.file, a.results_dir, slurm_queue, SurveyDetail::states_only);
  if (a.as_json) std::cout << status_json(survey).dump(2) << "\n";
  else print_status(survey, std::cout);
  return members_exit_code(survey);
}

}  // namespace

cli::Command add_status_command(CLI::App& study) {
  auto a = std::make_shared<StatusArguments>();
  CLI::App& app = *study.add_subcommand("status", "counts per state and the reasons of failed / unstable members");
  app.footer(exit_status_help());
  app.add_option("campaign", a->file, "campaign JSON file")->required();
  app.add_flag("--json", a->as_json, "print the status as one JSON object (for scripts)");
  app.add_option("--results", a->results_dir, "results folder")->capture_default_str();
  return {&app, [a] { return status(*a); }};
}

}  // namespace capsule::study
