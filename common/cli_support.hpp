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

// A finite number in (low, high] (or [low, high] with low_included): "nan", "inf" and 1e300
// seconds read "must be a number in (0, 1e+07], got \"nan\"" instead of passing a sign check.
inline CLI::Validator finite_number_in(double low, double high, bool low_included = false) {
  const auto bound = [](double x) {
    std::string t = std::to_string(x);
    t.erase(t.find_last_not_of('0') + 1);
    if (!t.empty() && t.back() == '.') t.pop_back();
    return t;
  };
  const std::string range = (low_included ? "[" : "(") + bound(low) + ", " + bound(high) + "]";
  return CLI::Validator(
      [low, high, low_included, range](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool inside = low_included ? value >= low : value > low;
        if (text.empty() || *end != '\0' || errno == ERANGE || !(inside && value <= high))
          return "must be a number in " + range + ", got \"" + text + "\"";
        return "";
      },
      "NUMBER in " + range);
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
