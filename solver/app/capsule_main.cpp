// capsule: runs one scene (one member of a study) and writes one member file; beside it the
// subcommands check, version, units, shapes, bench, reference-bim, rigid-sphere and rigid-circle (CLI11).
// Thin command line over the solver library; all physics lives in solver/.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "solver/app/bench_command.hpp"
#include "common/cli_support.hpp"
#include "solver/app/reference_bim_command.hpp"
#include "solver/app/rigid_sphere_command.hpp"
#include "solver/app/shapes_command.hpp"
#include "solver/app/units_command.hpp"
#include "solver/scene/memory_estimate.hpp"
#include "solver/run/run_member.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "build_info.hpp"

namespace {

using capsule::cli::Command;

// docs/guide/scenes.md "Exit status"; run_member() and `check` return these.
const char* const exit_codes =
    "Exit status: 0 complete (check: the scene is valid), 1 the solver failed or a file could not be\n"
    "written, 2 bad scene, output path or command line (nothing was run), 3 the member ended unstable,\n"
    "4 stopped by SIGTERM, SIGINT or SIGUSR1 after writing a restart point (the same command continues),\n"
    "5 interrupted by a full disk or a lack of memory (the same command continues once there is room),\n"
    "6 the member's lock was taken over by another run: nothing of the member was touched.";

Command add_check_command(CLI::App& capsule) {
  auto scene = std::make_shared<std::string>();
  CLI::App& app = *capsule.add_subcommand("check", "validate a scene and print it with every default filled in");
  app.footer(std::string("Example: capsule check tests/data/scenes/circle_quick_2d.json\n") + exit_codes);
  app.add_option("scene", *scene, "scene JSON file")->required();
  return {&app, [scene] {
            try {
              auto s = capsule::Scene::load(*scene);
              // The canonical scene on stdout (study hashes it); the memory it needs on stderr.
              if (const std::string refusal = capsule::memory_refusal(s); !refusal.empty()) {
                std::cerr << "capsule: " << *scene << ": " << refusal << "\n";
                return 2;
              }
              std::cout << s.to_json().dump(2) << "\n";
              std::cerr << "capsule: " << capsule::describe_memory(capsule::estimate_memory(s)) << "; this machine has "
                        << capsule::format_bytes(capsule::physical_memory_bytes()) << "\n";
              return 0;
            } catch (const std::exception& e) {
              std::cerr << "capsule: " << e.what() << "\n";
              return 2;
            }
          }};
}

// What a member file of this binary records (study run checks it before each member).
Command add_version_command(CLI::App& capsule) {
  CLI::App& app = *capsule.add_subcommand(
      "version", "the code version and physics version this binary records in a member file, as JSON");
  app.footer("Exit status: 0 printed, 2 bad command line.");
  return {&app, [] {
            std::cout << nlohmann::json{{"code_version", capsule::build::code_version},
                                        {"physics_version", capsule::physics_version}}.dump()
                      << "\n";
            return 0;
          }};
}


}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"capsule: one capsule in shear flow (IB + MRT lattice Boltzmann + membrane FEM)\n"
               "  capsule SCENE.json -o MEMBER.h5   run one scene (docs/guide/scenes.md)\n"
               "  capsule COMMAND --help            a command's options"};
  app.footer(std::string("Examples:\n"
                         "  capsule check tests/data/scenes/circle_quick_2d.json\n"
                         "  capsule tests/data/scenes/circle_quick_2d.json -o quick.h5\n"
                         "  capsule results/demo/members/<member>/scene.json -o m.h5 --checkpoint-seconds 600\n"
                         "  capsule shapes results/demo/members/<member> --at-kt 0.5,1,2   shapes of a finished member\n") +
             exit_codes);
  app.set_version_flag("--version", std::string("capsule ") + capsule::build::code_version + " (physics version " +
                                        capsule::physics_version + ")",
                       "print the code version and physics version, then exit");
  app.require_subcommand(0, 1);
  std::vector<Command> commands;
  commands.push_back(add_check_command(app));
  commands.push_back(add_version_command(app));
  commands.push_back(capsule::cli::add_units_command(app));
  commands.push_back(capsule::cli::add_shapes_command(app));
  commands.push_back(capsule::cli::add_bench_command(app));
  commands.push_back(capsule::cli::add_reference_bim_command(app));
  commands.push_back(capsule::cli::add_rigid_sphere_command(app));
  commands.push_back(capsule::cli::add_rigid_circle_command(app));

  capsule::RunOptions opt;
  app.add_option("scene", opt.scene_path, "scene JSON file (to run one scene)");
  app.add_option("-o,--output", opt.output_path, "member file to write (HDF5)");
  app.add_option("--threads", opt.threads, "OpenMP threads inside this member (0 = OMP default)")
      ->check(capsule::cli::whole_number_at_least(0));
  app.add_option("--id", opt.member_id, "member id to record (set by study)");
  app.add_flag("-q,--quiet", opt.quiet, "no progress lines");
  app.add_option("--progress-seconds", opt.progress_seconds, "wall seconds between progress lines")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0, 1e7));
  app.add_option("--checkpoint-seconds", opt.checkpoint.every_seconds,
                 "wall seconds between restart points (OUT.restart; 0 = none); rerunning the same command continues from the last one")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0, 1e7, /*low_included=*/true));
  // Hidden test options: a restart point at a given step, and an end as if killed.
  app.add_option("--checkpoint-at-step", opt.checkpoint.at_step)->group("")->check(CLI::NonNegativeNumber);
  app.add_option("--stop-after-step", opt.checkpoint.stop_after_step)->group("")->check(CLI::NonNegativeNumber);
  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  for (const Command& c : commands)
    if (c.app->parsed()) return c.run();
  if (opt.scene_path.empty() || opt.output_path.empty()) {
    std::cerr << "capsule: " << (opt.scene_path.empty() ? "a scene file" : "-o MEMBER.h5")
              << " is required to run a scene (or a command: check, version, units, shapes, bench, reference-bim, "
                 "rigid-sphere, rigid-circle); see capsule --help\n";
    return 2;
  }
  return capsule::run_member(opt);
}
