#pragma once
// Runs the built capsule binary in a shell with its output captured (tests of the command line).
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace capsule_test {

struct Result {
  int exit_code = -1;
  std::string output;
};

// Single-quoted for the shell.
inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// `capsule ARGS` with stdin closed; stdout and stderr together.
inline Result run_capsule(const std::string& args) {
  Result r;
  const std::string line = quote(std::string(CAPSULE_BINARY_DIR) + "/solver/capsule") + " " + args + " 2>&1 </dev/null";
  FILE* pipe = ::popen(line.c_str(), "r");
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace capsule_test
