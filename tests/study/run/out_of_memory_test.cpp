// A member that runs out of memory ends interrupted (capsule's exit 5, resumable), with the
// cause named, never stopped or failed. The limit is an address-space limit (prlimit --as) set
// from the capsule binary's own measured peak on a tiny member plus 400 MB, under a member whose
// fluid alone needs about 1 GB: the allocation that fails is the solver's, not HDF5's start-up
// (which an address-space limit near the binary's baseline was seen to crash).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "study/run/shell_quote.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// The largest VmPeak (kB) seen while `capsule SCENE -o OUT --threads 1 -q` runs; 0 if unseen.
long peak_virtual_kb(const fs::path& scene, const fs::path& out) {
  const pid_t child = ::fork();
  if (child == 0) {
    const std::string capsule = testing::capsule_binary().string();
    std::freopen("/dev/null", "w", stderr);
    ::execl(capsule.c_str(), capsule.c_str(), scene.c_str(), "-o", out.c_str(), "--threads", "1", "-q",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  long peak = 0;
  for (;;) {
    std::ifstream status("/proc/" + std::to_string(child) + "/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("VmPeak:", 0) == 0) peak = std::max(peak, std::stol(line.substr(7)));
    int st = 0;
    if (::waitpid(child, &st, WNOHANG) == child) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return peak;
}

}  // namespace

TEST_CASE("a member out of memory ends interrupted with the cause named, and stays resumable", "[study]") {
  const fs::path dir = testing::scratch_dir("out_of_memory");
  if (testing::run_shell("prlimit --version >/dev/null 2>&1").exit_code != 0) {
    std::cout << "skipped (prlimit is not installed)\n";
    WARN("skipped: prlimit is not installed");
    return;
  }
  testing::write_text(dir / "tiny.json", testing::tiny_scene(0.3, 0.0).dump());
  const long baseline_kb = peak_virtual_kb(dir / "tiny.json", dir / "tiny.h5");
  REQUIRE(baseline_kb > 0);
  const long limit_bytes = baseline_kb * 1024 + 400L * 1024 * 1024;
  std::cout << "capsule's peak address space on a tiny member: " << baseline_kb / 1024 << " MB; limit "
            << limit_bytes / (1024 * 1024) << " MB\n";

  // a = 200 in 2D: about 1.8 GB in all, the fluid's population arrays about 1 GB.
  nlohmann::json c = testing::tiny_campaign("oom", {0.05}, 0.001, 0.0);
  c["base"]["resolution"]["a"] = 200;
  testing::write_text(dir / "c.json", c.dump(2));
  const std::string line = "cd " + shell_quote(dir.string()) + " && CAPSULE_BIN=" +
                           shell_quote(testing::capsule_binary().string()) + " prlimit --as=" +
                           std::to_string(limit_bytes) + " " + shell_quote(testing::study_binary().string()) +
                           " run c.json </dev/null";
  const auto run = testing::run_shell(line);
  INFO(run.output);
  CHECK(run.exit_code == 4);  // no member failed; one is not complete
  CHECK_THAT(run.output, Catch::Contains("interrupted: 1") && Catch::Contains("lack of memory") &&
                             Catch::Contains("out of memory"));
  fs::path member;
  for (const auto& e : fs::directory_iterator(dir / "results" / "oom" / "members")) member = e.path();
  CHECK(testing::read_text(member / "exit_status") == "5\n");
  CHECK_FALSE(fs::exists(member / "member.h5"));
  const auto status = testing::run_study({"status", "c.json"}, dir);
  INFO(status.output);
  CHECK(status.exit_code == 4);
  CHECK_THAT(status.output, Catch::Contains("interrupted") && Catch::Contains("continues it"));
  fs::remove_all(dir);
}
