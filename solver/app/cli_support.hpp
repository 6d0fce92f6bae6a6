#pragma once
// Command-line plumbing shared by `capsule` and `study` (CLI11): whole-number options with
// a plain message, and parse errors mapped to the documented exit status 2 (CLI11 itself
// returns 104-109 for them, and 0 for --help).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <functional>
#include <string>

namespace capsule::cli {

// A whole number >= minimum (and <= 1e6): "-j 0" reads "must be a whole number >= 1, got 0"
// instead of CLI11's range up to the largest double.
inline CLI::Validator whole_number_at_least(long minimum) {
  const std::string description = "INT>=" + std::to_string(minimum);
  return CLI::Validator(
      [minimum](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long value = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno == ERANGE || value < minimum || value > 1000000)
          return "must be a whole number from " + std::to_string(minimum) + " to 1000000, got \"" + text + "\"";
        return "";
      },
      description);
}

// A subcommand of `capsule`: added to the app by its add_*_command(), run after parsing when
// the command line named it; run() returns the exit status.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

// Parses argv; on a command-line error prints CLI11's message and returns 2 (0 for --help
// and --version). Returns -1 when parsing succeeded and the program should go on.
inline int parse_or_exit_code(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return -1;
}

}  // namespace capsule::cli
