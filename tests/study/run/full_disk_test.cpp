// A member that runs out of disk space is interrupted, not ended: no member file is written, its
// last whole restart point stays, the cause is named, and the next run continues it once there is
// room (solver/run/run_member.hpp, exit 5). The disk is a real one: a small tmpfs, mounted in a
// user and mount namespace of its own (unshare -rm); where the machine refuses that, the test says
// why and is skipped.
#include <catch2/catch.hpp>

#include <iostream>

#include "study/run/shell_quote.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a disk that fills while a member writes its restart point leaves the member interrupted and resumable",
          "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("full_disk");
  testing::write_text(dir / "c.json", testing::tiny_campaign("full", {0.02}, 30, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "template", slurm_queue);
  prepare_member_directories(s);
  const std::string member = fs::relative(s.layout.member(s.members[0]).dir, dir / "template").string();
  fs::create_directories(dir / "disk");

  const auto probe = testing::run_shell("unshare -rm sh -c " +
                                        shell_quote("mount -t tmpfs -o size=1m tmpfs " + shell_quote((dir / "disk").string())));
  if (probe.exit_code != 0) {
    std::cout << "full_disk_test skipped: this machine refuses a tmpfs in a user namespace (unshare -rm): "
              << probe.output << "\n";
    fs::remove_all(dir);
    return;
  }
  // Inside the namespace: the member on a 16 MB tmpfs; once its first restart point is written the
  // disk is filled to 48 kB of room (enough for a log line and exit_status, not for a restart point).
  const std::string script = R"SH(
set -u
disk=$1; member=$disk/$2
mount -t tmpfs -o size=16m tmpfs "$disk" || exit 77
cp -a "$3/." "$disk/"
"$STUDY" run-member --capsule "$CAPSULE" --checkpoint-seconds 0.3 -- "$member" 1 2>"$4/first.err" &
pid=$!
i=0
while [ ! -e "$member/member.h5.restart" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i+1)); done
avail=$(df -k --output=avail "$disk" | tail -n 1)
dd if=/dev/zero of="$disk/fill" bs=1k count=$((avail - 48)) 2>/dev/null
wait $pid
echo "EXIT_STATUS $(cat "$member/exit_status")"
[ -e "$member/member.h5" ] && echo "MEMBER_FILE_WRITTEN"
[ -e "$member/member.h5.restart" ] && echo "RESTART_KEPT"
"$STUDY" status "$4/c.json" --results "$disk"
echo "STATUS_FULL $?"
rm "$disk/fill"
"$STUDY" run-member --capsule "$CAPSULE" -- "$member" 1
"$STUDY" status "$4/c.json" --results "$disk"
echo "STATUS_FREED $?"
cat "$member/capsule.log"
)SH";
  testing::write_text(dir / "script.sh", script);
  const auto out = testing::run_shell("STUDY=" + shell_quote(testing::study_binary().string()) +
                                      " CAPSULE=" + shell_quote(testing::capsule_binary().string()) +
                                      " unshare -rm sh " + shell_quote((dir / "script.sh").string()) + " " +
                                      shell_quote((dir / "disk").string()) + " " + shell_quote(member) + " " +
                                      shell_quote((dir / "template").string()) + " " + shell_quote(dir.string()));
  INFO(out.output);
  CHECK(out.output.find("EXIT_STATUS 5") != std::string::npos);
  CHECK(out.output.find("MEMBER_FILE_WRITTEN") == std::string::npos);
  CHECK(out.output.find("RESTART_KEPT") != std::string::npos);
  CHECK_THAT(out.output, Catch::Contains("[interrupted] " + s.members[0].dir_name()) &&
                             Catch::Contains("no space left on the disk"));
  CHECK(out.output.find("STATUS_FULL 4") != std::string::npos);
  CHECK(out.output.find("continuing from the restart point") != std::string::npos);
  CHECK(out.output.find("STATUS_FREED 0") != std::string::npos);
  fs::remove_all(dir);
}

