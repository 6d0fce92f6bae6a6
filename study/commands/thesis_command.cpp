// `study thesis` (alias `dissertation`): THESIS.md, Table 2, the ratios b/a and the claims of
// Chapters 2-5 against the shipped results (study/commands/analysis_commands.hpp).
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "solver/io/member_file.hpp"
#include "study/commands/analysis_commands.hpp"
#include "study/commands/commands.hpp"

namespace capsule::study {

namespace {

struct ThesisArguments {
  std::string results_dir = "results";
  std::string out;  // "" : <results>/THESIS.md
  bool legacy_member_files = false;
};

int thesis(const ThesisArguments& a) {
  io::accept_files_without_content_hash(a.legacy_member_files);
  const std::filesystem::path out = a.out.empty() ? std::filesystem::path(a.results_dir) / "THESIS.md"
                                                  : std::filesystem::path(a.out);
  return write_dissertation_comparison(a.results_dir, out, std::cout);
}

}  // namespace

cli::Command add_thesis_command(CLI::App& study) {
  auto a = std::make_shared<ThesisArguments>();
  CLI::App& app = *study.add_subcommand(
      "thesis", "write THESIS.md: Table 2, the ratios b/a and the claims of Chapters 2-5 against the shipped results");
  app.alias("dissertation");  // the word the documents and the code use; `thesis` stays for THESIS.md's users
  app.add_option("--results", a->results_dir, "results folder (reads <results>/<campaign>/report/fits.json)")
      ->capture_default_str();
  app.add_option("-o,--output", a->out, "file to write (default: <results>/THESIS.md)");
  app.add_flag("--legacy-member-files", a->legacy_member_files, legacy_member_files_help);
  return {&app, [a] { return thesis(*a); }};
}

}  // namespace capsule::study
