// `study run-member MEMBER_DIR THREADS`: one member as every engine runs it; the generated
// run_member.sh execs it (study/run/member_job.hpp).
#include <iostream>
#include <memory>

#include "study/commands/commands.hpp"
#include "study/run/member_job.hpp"

namespace capsule::study {

cli::Command add_run_member_command(CLI::App& study) {
  auto request = std::make_shared<MemberJobRequest>();
  const auto count = cli::whole_number_at_least(1);
  CLI::App& app = *study.add_subcommand(
      "run-member", "run one member folder as every engine does (the generated run_member.sh execs it): its lock, "
                    "a complete member left alone, capsule's output appended to capsule.log, signals passed on");
  app.add_option("member_dir", request->member_dir, "the member's folder (<results>/<campaign>/members/<member>)")
      ->required()->check(CLI::ExistingDirectory);
  app.add_option("threads", request->threads, "OpenMP threads of the member")->required()->check(count);
  app.add_option("--capsule", request->capsule_binary, "the capsule binary")->required();
  app.add_option("--code-version", request->expected_code_version,
                 "start the member only if the capsule binary reports this code version (`capsule version`)");
  app.add_option("--checkpoint-seconds", request->checkpoint_seconds, "wall seconds between restart points")
      ->capture_default_str()->check(cli::finite_number_in(0, 1e7));
  return {&app, [request] { return run_member_job(*request, std::cerr); }};
}

}  // namespace capsule::study
