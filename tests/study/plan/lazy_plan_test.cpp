// `study plan` expands, inspects and prints members one at a time: a large grid plans in
// bounded memory (it used to hold every member scene: about 6 GB for 10^6 members).
#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "study/campaign/campaign.hpp"
#include "study/campaign/expansion.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// Peak resident memory (MB) of `study ARGS...` run in dir, its output discarded.
double peak_megabytes(const std::vector<std::string>& args, const fs::path& dir, int& exit_code) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::chdir(dir.c_str());
    std::freopen("/dev/null", "w", stdout);
    const std::string study = testing::study_binary().string();
    std::vector<char*> argv{const_cast<char*>(study.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(study.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  ::wait4(child, &status, 0, &usage);
  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in kB on Linux
}

nlohmann::json grid_campaign(const std::string& name, int n_ca, int n_eb) {
  std::vector<double> ca, eb;
  for (int i = 1; i <= n_ca; ++i) ca.push_back(0.001 * i);
  for (int i = 0; i < n_eb; ++i) eb.push_back(0.001 * i);
  auto doc = testing::tiny_campaign(name, ca, 1, 1);
  doc["sweep"]["grid"]["E_b"] = eb;
  return doc;
}

}  // namespace

TEST_CASE("for_each_member visits the members of expand_campaign in the same order", "[study]") {
  const Campaign c = parse_campaign(grid_campaign("order", 3, 4).dump(), "order.json");
  const auto all = expand_campaign(c);
  std::vector<std::string> ids;
  for_each_member(
      c, [&ids](Member&& m) { ids.push_back(m.id); }, [](std::size_t, const std::string&) {});
  REQUIRE(ids.size() == 12);
  for (std::size_t i = 0; i < ids.size(); ++i) CHECK(ids[i] == all[i].id);
  CHECK(all[1].parameters[1].second == 0.001);  // E_b, the last grid axis, varies fastest
}

TEST_CASE("study plan of a 10^4-member grid stays within a few MB of a 4-member one", "[study]") {
  const fs::path dir = testing::scratch_dir("lazy_plan");
  testing::write_text(dir / "small.json", grid_campaign("small", 2, 2).dump());
  testing::write_text(dir / "large.json", grid_campaign("large", 100, 100).dump());
  int small_code = -1, large_code = -1;
  const double small = peak_megabytes({"plan", "small.json"}, dir, small_code);
  const double large = peak_megabytes({"plan", "large.json"}, dir, large_code);
  INFO("peak RSS: 4 members " << small << " MB, 10^4 members " << large << " MB");
  CHECK(small_code == 0);
  CHECK(large_code == 0);
  // Holding the members took about 8 kB each (80 MB here); the duplicate check keeps ~40 B.
  CHECK(large - small < 15.0);
  fs::remove_all(dir);
}
