#include "tests/study/support/study_test_support.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "study/run/shell_quote.hpp"

namespace capsule::study::testing {

namespace fs = std::filesystem;

fs::path scratch_dir(const std::string& name) {
  std::string leaf = "capsule_study_test_";  // append(): GCC 12 -O3 false -Wrestrict on operator+
  leaf.append(name).append("_").append(std::to_string(::getpid()));
  const fs::path dir = fs::temp_directory_path() / leaf;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path study_binary() { return fs::path(CAPSULE_BINARY_DIR) / "study" / "study"; }

fs::path capsule_binary() {
  if (const char* env = std::getenv("CAPSULE_BIN"); env && *env) return env;
  return fs::path(CAPSULE_BINARY_DIR) / "solver" / "capsule";
}

CommandResult run_shell(const std::string& command_line) {
  CommandResult result;
  FILE* pipe = ::popen((command_line + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

CommandResult run_study(const std::vector<std::string>& args, const fs::path& cwd) {
  std::string line = "cd ";
  line.append(shell_quote(cwd.string())).append(" && CAPSULE_BIN=").append(shell_quote(capsule_binary().string()));
  line.append(" ").append(shell_quote(study_binary().string()));
  for (const auto& a : args) line.append(" ").append(shell_quote(a));
  return run_shell(line.append(" </dev/null"));
}

nlohmann::json tiny_scene(double shear_kt, double recover_kt) {
  return {{"dim", 2},
          {"shape", "circle"},
          {"Ca", 0.05},
          {"E_b", 0.0},
          {"V", 1.0},
          {"eta", 0.0},
          {"resolution", {{"a", 4}, {"segments", 32}}},
          {"protocol",
           {{"shear", {{"until", "time"}, {"kt", shear_kt}}}, {"recover", {{"until", "time"}, {"kt", recover_kt}}}}},
          {"output", {{"interval_kt", 0.1}}}};
}

nlohmann::json tiny_campaign(const std::string& name, const std::vector<double>& ca, double shear_kt,
                             double recover_kt) {
  return {{"name", name},
          {"description", "tiny 2D members for the study tests"},
          {"base", tiny_scene(shear_kt, recover_kt)},
          {"sweep", {{"grid", {{"Ca", ca}}}}}};
}

bool wait_for(const std::function<bool()>& condition, double seconds) {
  for (int i = 0; i < static_cast<int>(seconds * 100); ++i) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}

void set_age(const std::filesystem::path& file, double seconds) {
  std::filesystem::last_write_time(
      file, std::filesystem::file_time_type::clock::now() - std::chrono::seconds(static_cast<long>(seconds)));
}

pid_t start_study_run(const std::filesystem::path& cwd, const std::vector<std::string>& extra) {
  std::vector<std::string> args{study_binary().string(), "run", "c.json"};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string capsule = capsule_binary().string();
  const pid_t child = ::fork();
  if (child == 0) {
    ::setsid();
    if (::chdir(cwd.c_str()) != 0) ::_exit(127);
    ::setenv("CAPSULE_BIN", capsule.c_str(), 1);
    if (!std::freopen("/dev/null", "w", stdout)) ::_exit(127);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return child;
}

}  // namespace capsule::study::testing
