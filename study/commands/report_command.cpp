// `study report CAMPAIGN`: fits, tables and figures of the campaign's members in
// results/<campaign>/report (study/commands/analysis_commands.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "solver/io/member_file.hpp"
#include "study/commands/analysis_commands.hpp"
#include "study/commands/commands.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/state/exit_status.hpp"
#include "study/slurm/slurm_queue.hpp"

namespace capsule::study {

namespace {

struct ReportArguments {
  std::string file;
  std::string results_dir = "results";
  ReportOptions options;
  bool legacy_member_files = false;
};

}  // namespace

cli::Command add_report_command(CLI::App& study) {
  auto a = std::make_shared<ReportArguments>();
  CLI::App& app = *study.add_subcommand("report", "fit, tabulate and plot: results/<campaign>/report");
  app.footer(exit_status_help());
  app.add_option("campaign", a->file, "campaign JSON file")->required();
  app.add_option("--results", a->results_dir, "results folder")->capture_default_str();
  app.add_flag("--partial", a->options.partial,
               "write the report even when some member files cannot be read (report/PARTIAL.md names them); "
               "without it such a report is refused and the previous one kept");
  app.add_flag("--legacy-member-files", a->legacy_member_files, legacy_member_files_help);
  return {&app, [a] {
            io::accept_files_without_content_hash(a->legacy_member_files);
            return report_campaign(survey_campaign(a->file, a->results_dir, slurm_queue), a->options, std::cout);
          }};
}

}  // namespace capsule::study
