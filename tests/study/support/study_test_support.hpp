#pragma once
// Helpers for the study tests: scratch folders, running the real `study` binary, tiny
// scenes that the real `capsule` runs in about a second.
#include <filesystem>
#include <sys/types.h>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace capsule::study::testing {

// A new empty folder under the system temp dir, named after the test.
std::filesystem::path scratch_dir(const std::string& name);

void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);

std::filesystem::path study_binary();
std::filesystem::path capsule_binary();  // $CAPSULE_BIN if set, else <build>/solver/capsule

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs `study ARGS...` in folder cwd with CAPSULE_BIN pointing at capsule_binary(); no shell
// sees the arguments unquoted.
CommandResult run_study(const std::vector<std::string>& args, const std::filesystem::path& cwd);

// Starts `study run c.json EXTRA...` in folder cwd as a child in a session of its own (so a test
// can kill exactly that run's process tree), stdout to /dev/null; returns its pid.
pid_t start_study_run(const std::filesystem::path& cwd, const std::vector<std::string>& extra = {});

// Runs a shell command line (tests only build it from quoted parts).
CommandResult run_shell(const std::string& command_line);

// A 2D circle with a = 4 and 32 segments: about 0.25 s of solver time per kt on one core
// (measured: kt 1 + 1 took 0.5 s), so members take a second or two.
nlohmann::json tiny_scene(double shear_kt, double recover_kt);

// A campaign document around tiny_scene with a grid over Ca.
nlohmann::json tiny_campaign(const std::string& name, const std::vector<double>& ca, double shear_kt,
                             double recover_kt);

// Polls `condition` every 10 ms for up to `seconds`; its last value.
bool wait_for(const std::function<bool()>& condition, double seconds);
// Sets a file's modification time `seconds` into the past (a stale lock or heartbeat).
void set_age(const std::filesystem::path& file, double seconds);

}  // namespace capsule::study::testing
