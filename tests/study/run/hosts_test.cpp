// Several hosts: GNU Parallel's --sshloginfile with two host entries. An --ssh stand-in
// runs the remote command locally (as ssh would on a host sharing the filesystem).
#include <catch2/catch.hpp>
#include <algorithm>
#include <set>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/run/joblog.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("members run on every host of a --hosts file", "[study]") {
  const fs::path dir = testing::scratch_dir("hosts");
  testing::write_text(dir / "c.json", testing::tiny_campaign("hosts", {0.01, 0.02, 0.03, 0.04}, 1, 1).dump());
  // One job slot per host ("1/host"), so with 4 members both hosts must take some.
  testing::write_text(dir / "hosts", "1/node-a\n1/node-b\n");
  // GNU Parallel calls: SSH HOST -- COMMAND...; run COMMAND here instead.
  testing::write_text(dir / "fake-ssh", "#!/bin/sh\nhost=$1; shift\n[ \"$1\" = \"--\" ] && shift\nexec sh -c \"$*\"\n");
  fs::permissions(dir / "fake-ssh", fs::perms::owner_all);

  // A results folder whose name a shell would mangle if anything were interpolated unquoted.
  const std::string results = "res 'q $(false) *";
  const auto run = testing::run_study(
      {"run", "c.json", "--hosts", "hosts", "--ssh", (dir / "fake-ssh").string(), "--results", results}, dir);
  INFO(run.output);
  CHECK(run.exit_code == 0);
  CHECK(run.output.find("at once per host") != std::string::npos);

  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / results, slurm_queue);
  CHECK(s.count(MemberState::complete) == 4);
  const auto log = read_joblog(s.layout.joblog());
  REQUIRE(log.size() == 4);
  std::set<std::string> hosts;
  for (const auto& e : log) {
    hosts.insert(e.host);
    CHECK(e.exit_value == 0);
  }
  CHECK(hosts == std::set<std::string>{"node-a", "node-b"});
  fs::remove_all(dir);
}

TEST_CASE("the hosts file's per-host counts are honoured: 1/host runs one member at a time", "[study]") {
  const fs::path dir = testing::scratch_dir("hosts_counts");
  testing::write_text(dir / "c.json", testing::tiny_campaign("counts", {0.01, 0.02, 0.03}, 3, 0).dump());
  testing::write_text(dir / "hosts", "1/node-a\n");
  testing::write_text(dir / "fake-ssh", "#!/bin/sh\nhost=$1; shift\n[ \"$1\" = \"--\" ] && shift\nexec sh -c \"$*\"\n");
  fs::permissions(dir / "fake-ssh", fs::perms::owner_all);
  // No -j: study passes no --jobs, so GNU Parallel takes the 1 of "1/node-a".
  const auto run = testing::run_study({"run", "c.json", "--hosts", "hosts", "--ssh", (dir / "fake-ssh").string()}, dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  auto log = read_joblog(s.layout.joblog());
  REQUIRE(log.size() == 3);
  std::sort(log.begin(), log.end(), [](const JoblogEntry& a, const JoblogEntry& b) { return a.start < b.start; });
  for (std::size_t i = 1; i < log.size(); ++i)  // each starts after the one before ended (10 ms of clock slack)
    CHECK(log[i].start >= log[i - 1].start + log[i - 1].runtime - 0.01);
  fs::remove_all(dir);
}
