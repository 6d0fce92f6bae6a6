// Running members, progress and restart points seen from `study` (docs/guide/running.md "Progress",
// "Checkpoints", "Time and memory estimates").
#include <catch2/catch.hpp>
#include <unistd.h>

#include <fstream>

#include <chrono>

#include "solver/io/member_file.hpp"
#include "solver/scene/scene.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/plan/plan_table.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

std::string host() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

void write_progress(const MemberPaths& p, long pid, const std::string& on_host) {
  const nlohmann::json j = {{"pid", pid}, {"host", on_host}, {"updated", 0.0}, {"phase", "shear"}, {"kt", 1.25},
                            {"steps", 1000}, {"D_xy", 0.1}, {"steps_per_second", 400.0}, {"mlups", 1.0},
                            {"phase_end_kt", 3.0}, {"phase_end_is_cap", false}, {"member_end_kt", 5.0},
                            {"member_end_is_cap", false}, {"eta_phase_seconds", 10.0}, {"eta_member_seconds", 190.0}};
  testing::write_text(p.progress, j.dump());
}

}  // namespace

TEST_CASE("study status: a live member is running with its kt and ETA, a dead one interrupted", "[study]") {
  const fs::path dir = testing::scratch_dir("running");
  testing::write_text(dir / "c.json", testing::tiny_campaign("running", {0.01, 0.02, 0.03}, 1, 1).dump(2));
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths live = s.layout.member(s.members[0]), dead = s.layout.member(s.members[1]);
  testing::write_text(live.partial, "x");
  write_progress(live, ::getpid(), host());  // this test process: alive
  testing::write_text(dead.partial, "x");
  write_progress(dead, 999999999, host());  // no such process
  fs::last_write_time(dead.partial, fs::file_time_type::clock::now() - std::chrono::hours(1));

  s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK(s.conditions[0].state == MemberState::running);
  CHECK(s.conditions[0].reason == "shear, kt 1.25 of 5, ETA 3m10s");
  CHECK(s.conditions[1].state == MemberState::interrupted);
  CHECK(!needs_run(s.conditions[0], false, false));  // a live capsule owns it
  CHECK(needs_run(s.conditions[1], false, false));

  const auto status = testing::run_study({"status", "c.json"}, dir);
  INFO(status.output);
  CHECK(status.output.find("running: 1") != std::string::npos);
  CHECK(status.output.find("[running] " + s.members[0].dir_name() + ": shear, kt 1.25 of 5, ETA 3m10s") !=
        std::string::npos);
}

TEST_CASE("study run continues an interrupted member from its restart point and logs its progress", "[study]") {
  const fs::path dir = testing::scratch_dir("restart");
  testing::write_text(dir / "c.json", testing::tiny_campaign("restart", {0.02, 0.04}, 2, 1).dump(2));
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);
  // The member killed after a restart point at step 600 (as a machine losing power would).
  std::string command;
  for (const std::string& word : {testing::capsule_binary().string(), p.scene.string(), std::string("-o"), p.h5.string(),
                                  std::string("--id"), s.members[0].id})
    command += "'" + word + "' ";
  command += "--threads 1 --checkpoint-at-step 600 --stop-after-step 700";
  const auto killed = testing::run_shell(command);
  INFO(killed.output);
  REQUIRE(killed.exit_code == 1);
  REQUIRE(fs::exists(p.restart));
  s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK(s.conditions[0].state == MemberState::interrupted);
  CHECK(s.conditions[0].reason.find("continues it from its restart point") != std::string::npos);

  const auto run = testing::run_study({"run", "c.json"}, dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(run.output.find("running 2 of 2 members") != std::string::npos);
  const std::string log = testing::read_text(p.log);
  CHECK(log.find("continuing from the restart point at step 600") != std::string::npos);
  CHECK(!fs::exists(p.restart));
  const auto m = capsule::io::read_member(p.h5.string());
  CHECK(m.complete());
  CHECK(m.attributes.at("restarts") == 1);

  // The plan now shows what the members took and corrects its model by their speed.
  const auto plan = testing::run_study({"plan", "c.json"}, dir);
  INFO(plan.output);
  CHECK(plan.output.find("seconds") != std::string::npos);
  CHECK(plan.output.find("2 complete") != std::string::npos);
}

TEST_CASE("study plan estimates seconds and memory per member and the campaign's wall time", "[study]") {
  const fs::path dir = testing::scratch_dir("estimate");
  testing::write_text(dir / "c.json", testing::tiny_campaign("estimate", {0.02, 0.04}, 2, 1).dump(2));
  const auto plan = testing::run_study({"plan", "c.json"}, dir);
  INFO(plan.output);
  REQUIRE(plan.exit_code == 0);
  CHECK(plan.output.find("~") != std::string::npos);
  CHECK(plan.output.find("estimated wall time: ") != std::string::npos);
  CHECK(plan.output.find(" MB") != std::string::npos);

  // The model: a 3D member costs far more per step than a 2D one, and membrane terms add to it.
  nlohmann::json s2 = testing::tiny_scene(2, 1);
  const CostEstimate c2 = estimate_cost(capsule::Scene::from_json(s2, "t").to_json());
  CHECK(c2.expected_kt == Approx(3));
  CHECK(c2.expected_seconds(1) > 0);
  nlohmann::json s3 = {{"dim", 3}, {"shape", "sphere"}, {"Ca", 0.1}, {"E_b", 0}, {"V", 1}, {"eta", 0},
                       {"protocol", {{"shear", {{"until", "steady"}}}, {"recover", {{"until", "settled"}}}}}};
  const CostEstimate c3 = estimate_cost(capsule::Scene::from_json(s3, "t").to_json());
  CHECK(c3.kt_is_bound);
  CHECK(c3.expected_kt == Approx(2 + 1.6 + 2 + 2.6));
  s3["E_b"] = 0.05;
  const CostEstimate c3b = estimate_cost(capsule::Scene::from_json(s3, "t").to_json());
  CHECK(c3b.membrane_seconds_per_step > c3.membrane_seconds_per_step);
  // 800 000 against 19 200 nodes (42x), the 3D kernel slower per node than the cached 2D one
  CHECK(c3.fluid_seconds_per_step > 42 * c2.fluid_seconds_per_step);
  CHECK(c3.memory_bytes > 100e6);  // 100 x 100 x 80 D3Q19: ~300 MB

  SpeedCalibration k;
  k.add(c2, 1000, 1, 2 * c2.seconds_for_steps(1000, 1));
  CHECK(k.factor == Approx(2));
  CHECK(k.members == 1);
  CHECK(k.length_members == 0);  // c2's phases have set durations: nothing to learn about lengths
  CHECK(k.seconds(c2, 1) == Approx(2 * c2.expected_seconds(1)));

  // A member whose condition-ended phases ran 5 times the model's expected length (a recovery
  // that runs to its cap): the next member of that kind is estimated 5 times as long, never
  // beyond its caps.
  SpeedCalibration long_phases;
  long_phases.add(c3, 5 * c3.expected_steps(), 1, c3.seconds_for_steps(5 * c3.expected_steps(), 1));
  CHECK(long_phases.factor == Approx(1));
  CHECK(long_phases.length_members == 1);
  CHECK(long_phases.length_factor == Approx(5));
  CHECK(long_phases.seconds(c3, 1) == Approx(c3.seconds_for_steps(5 * c3.expected_steps(), 1)));
  long_phases.add(c3, 1000 * c3.expected_steps(), 1, c3.seconds_for_steps(1000 * c3.expected_steps(), 1));
  CHECK(long_phases.seconds(c3, 1) == Approx(c3.seconds_for_steps(c3.steps(), 1)));  // the caps bound it
}
