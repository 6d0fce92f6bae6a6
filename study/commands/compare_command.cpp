// `study compare CAMPAIGN...`: the fits of several campaigns' reports side by side, optionally
// against the dissertation's Table 2 (study/commands/analysis_commands.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "study/commands/analysis_commands.hpp"
#include "study/commands/commands.hpp"

namespace capsule::study {

namespace {

struct CompareArguments {
  std::vector<std::string> files;
  std::string results_dir = "results";
  bool table2 = false;
};

}  // namespace

cli::Command add_compare_command(CLI::App& study) {
  auto a = std::make_shared<CompareArguments>();
  CLI::App& app = *study.add_subcommand("compare", "compare the fits of several campaigns' reports");
  app.add_option("campaigns", a->files, "campaign JSON files")->required()->expected(1, -1);
  app.add_flag("--table2", a->table2, "also compare with the dissertation's Table 2");
  app.add_option("--results", a->results_dir, "results folder")->capture_default_str();
  return {&app, [a] { return compare_campaign_files(a->files, a->table2, a->results_dir, std::cout); }};
}

}  // namespace capsule::study
