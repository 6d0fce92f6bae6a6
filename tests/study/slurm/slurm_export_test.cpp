// Slurm export: the sbatch script is valid bash, and its task i runs member i.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/run/shell_quote.hpp"
#include "study/run/script_path.hpp"
#include "study/slurm/slurm_export.hpp"
#include "study/slurm/slurm_resources.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("array specs compress runs of indices", "[study]") {
  CHECK(array_spec({0, 1, 2, 3}) == "0-3");
  CHECK(array_spec({0, 2, 3, 4, 7}) == "0,2-4,7");
  CHECK(array_spec({5}) == "5");
}

TEST_CASE("the Slurm script passes bash -n and task i runs member i", "[study]") {
  const fs::path dir = testing::scratch_dir("slurm");
  testing::write_text(dir / "c.json", testing::tiny_campaign("slurm", {0.01, 0.02, 0.03}, 1, 1).dump());
  const auto exported = testing::run_study({"export", "c.json", "--slurm"}, dir);
  INFO(exported.output);
  REQUIRE(exported.exit_code == 0);

  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const fs::path script = s.layout.slurm_dir() / "capsule.sbatch";
  REQUIRE(fs::exists(script));
  const std::string text = testing::read_text(script);
  CHECK(text.find("#SBATCH --array=0-2\n") != std::string::npos);
  CHECK(text.find("#SBATCH --cpus-per-task=1\n") != std::string::npos);
  CHECK(testing::run_shell("bash -n " + shell_quote(script.string())).exit_code == 0);

  // Task 1 runs member 1 and nothing else.
  const auto task = testing::run_shell("SLURM_ARRAY_TASK_ID=1 bash " + shell_quote(script.string()));
  INFO(task.output);
  CHECK(task.exit_code == 0);
  const CampaignSurvey after = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK(after.conditions[0].state == MemberState::fresh);
  CHECK(after.conditions[1].state == MemberState::complete);
  CHECK(after.conditions[2].state == MemberState::fresh);

  // A task past the end of the list fails loudly instead of running something else.
  CHECK(testing::run_shell("SLURM_ARRAY_TASK_ID=7 bash " + shell_quote(script.string())).exit_code == 2);

  // Exporting again leaves the complete member out of the array.
  REQUIRE(testing::run_study({"export", "c.json", "--slurm"}, dir).exit_code == 0);
  CHECK(testing::read_text(script).find("#SBATCH --array=0,2\n") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("Slurm export refuses a results path with a line break before writing anything", "[study]") {
  const fs::path dir = testing::scratch_dir("slurm_newline");
  testing::write_text(dir / "c.json", testing::tiny_campaign("slurm_nl", {0.01}, 1, 1).dump());
  const std::string results = "res\ntouch INJECTED\n";
  const auto r = testing::run_study({"export", "c.json", "--slurm", "--results", results}, dir);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("the results folder contains a control character (byte 0x0a") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / results));
  CHECK_FALSE(fs::exists(dir / "INJECTED"));
  // study run refuses it the same way.
  const auto run = testing::run_study({"run", "c.json", "--results", results}, dir);
  CHECK(run.exit_code == 2);
  CHECK(run.output.find("control character") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the #SBATCH --output line is quoted, with % doubled, one file per submission and task", "[study]") {
  CHECK(sbatch_output_line("/shared/my results/100%/slurm") ==
        "#SBATCH --output=\"/shared/my results/100%%/slurm/task-%A_%a.out\"");
  CHECK_THROWS_AS(sbatch_output_line("/shared/a\"b/slurm"), UnsafePathError);
}

TEST_CASE("Slurm resources: CPUs from --threads or the dimension, not this machine - --time and --mem", "[study]") {
  const fs::path dir = testing::scratch_dir("slurm_resources");
  nlohmann::json doc = testing::tiny_campaign("slurm3d", {0.05}, 1, 1);
  doc["base"]["dim"] = 3;
  doc["base"]["shape"] = "sphere";
  doc["base"]["resolution"] = {{"a", 4}, {"mesh_level", 2}};
  testing::write_text(dir / "c.json", doc.dump());
  REQUIRE(testing::run_study({"export", "c.json", "--slurm"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const fs::path script = s.layout.slurm_dir() / "capsule.sbatch";
  std::string text = testing::read_text(script);
  INFO(text);
  CHECK(text.find("#SBATCH --cpus-per-task=" + std::to_string(default_3d_cpus) + "\n") != std::string::npos);
  const long minutes = estimated_minutes(s.members[0], default_3d_cpus);
  CHECK(minutes >= 10);
  CHECK(text.find("#SBATCH --time=" + std::to_string(std::max(15L, minutes)) + "\n") != std::string::npos);
  CHECK(text.find("#SBATCH --mem=" + std::to_string(estimated_megabytes(s.members[0])) + "\n") != std::string::npos);
  CHECK(text.find("#SBATCH --output=\"") != std::string::npos);
  CHECK(testing::run_shell("bash -n " + shell_quote(script.string())).exit_code == 0);

  REQUIRE(testing::run_study({"export", "c.json", "--slurm", "-t", "3", "--time", "2:00:00", "--mem", "4G"}, dir)
              .exit_code == 0);
  text = testing::read_text(script);
  CHECK(text.find("#SBATCH --cpus-per-task=3\n") != std::string::npos);
  CHECK(text.find("#SBATCH --time=2:00:00\n") != std::string::npos);
  CHECK(text.find("#SBATCH --mem=4G\n") != std::string::npos);
  CHECK(is_slurm_time("90"));
  CHECK(is_slurm_time("1-12:00"));
  CHECK_FALSE(is_slurm_time("1h; rm -rf /"));
  CHECK(is_slurm_mem("2048"));
  CHECK_FALSE(is_slurm_mem("4 GB"));
  fs::remove_all(dir);
}

TEST_CASE("with nothing pending the Slurm script has no --array and exits 0", "[study]") {
  const fs::path dir = testing::scratch_dir("slurm_done");
  testing::write_text(dir / "c.json", testing::tiny_campaign("slurm_done", {0.05}, 1, 1).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const auto exported = testing::run_study({"export", "c.json", "--slurm"}, dir);
  INFO(exported.output);
  REQUIRE(exported.exit_code == 0);
  CHECK(exported.output.find("0 of 1 members to run: nothing to submit") != std::string::npos);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const fs::path script = s.layout.slurm_dir() / "capsule.sbatch";
  const std::string text = testing::read_text(script);
  CHECK(text.find("#SBATCH --array") == std::string::npos);
  const auto task = testing::run_shell("bash " + shell_quote(script.string()));
  CHECK(task.exit_code == 0);
  CHECK(task.output.find("nothing to run") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("an array over --array-max members is split into scripts Slurm accepts, with a submit helper", "[study]") {
  const fs::path dir = testing::scratch_dir("slurm_split");
  std::vector<double> ca;
  for (int i = 0; i < 1100; ++i) ca.push_back(0.01 + 1e-4 * i);
  testing::write_text(dir / "c.json", testing::tiny_campaign("split", ca, 1, 1).dump());
  const auto exported = testing::run_study({"export", "c.json", "--slurm", "--throttle", "50", "-p", "short", "-A",
                                            "proj_1", "--qos", "normal", "--sbatch=--constraint=avx2"},
                                           dir);
  INFO(exported.output);
  REQUIRE(exported.exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const std::string first = testing::read_text(s.layout.slurm_dir() / "capsule-0.sbatch");
  const std::string second = testing::read_text(s.layout.slurm_dir() / "capsule-1.sbatch");
  // Task ids stay below Slurm's default MaxArraySize (1001); the second script starts at 1000.
  CHECK(first.find("#SBATCH --array=0-999%50\n") != std::string::npos);
  CHECK(second.find("#SBATCH --array=0-99%50\n") != std::string::npos);
  CHECK(second.find("$((1000 + task + 1))p") != std::string::npos);
  for (const std::string line : {"#SBATCH --partition=short\n", "#SBATCH --account=proj_1\n", "#SBATCH --qos=normal\n",
                                 "#SBATCH --constraint=avx2\n", "#SBATCH --signal=B:USR1@120\n", "task-%A_%a.out"})
    CHECK(first.find(line) != std::string::npos);
  CHECK_FALSE(fs::exists(s.layout.slurm_dir() / "capsule.sbatch"));
  const std::string submit = testing::read_text(s.layout.slurm_dir() / "submit.sh");
  CHECK(submit.find("capsule-0.sbatch") != std::string::npos);
  CHECK(submit.find("capsule-1.sbatch") != std::string::npos);
  CHECK(testing::run_shell("sh -n " + shell_quote((s.layout.slurm_dir() / "submit.sh").string())).exit_code == 0);
  // Task 99 of the second script runs member 1099.
  const auto task = testing::run_shell("SLURM_ARRAY_TASK_ID=99 bash " +
                                       shell_quote((s.layout.slurm_dir() / "capsule-1.sbatch").string()) + " 2>&1");
  INFO(task.output);
  CHECK(task.exit_code == 0);
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[1099].state == MemberState::complete);
  // A name Slurm would not take, or a line break, is refused before anything is written.
  CHECK(testing::run_study({"export", "c.json", "--slurm", "-p", "a b"}, dir).exit_code == 2);
  CHECK(testing::run_study({"export", "c.json", "--slurm", "--sbatch=--x\nrm -rf /"}, dir).exit_code == 2);
  fs::remove_all(dir);
}

TEST_CASE("members whose Slurm task waits in the queue are queued: status says so, re-export and run leave them out",
          "[study]") {
  const fs::path dir = testing::scratch_dir("slurm_queued");
  testing::write_text(dir / "c.json", testing::tiny_campaign("queued", {0.01, 0.02, 0.03}, 1, 1).dump());
  REQUIRE(testing::run_study({"export", "c.json", "--slurm"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const std::string job = nlohmann::json::parse(testing::read_text(s.layout.slurm_dir() / "export.json"))["scripts"][0]
                              ["job_name"];
  // A stand-in squeue: task 1 held in the queue, task 2 running.
  fs::create_directories(dir / "bin");
  testing::write_text(dir / "bin" / "squeue", "#!/bin/sh\necho '" + job + " 1 PENDING'\necho '" + job + " 2 RUNNING'\n");
  fs::permissions(dir / "bin" / "squeue", fs::perms::owner_all);
  const std::string path = "PATH=" + shell_quote((dir / "bin").string()) + ":\"$PATH\" ";
  const auto study = [&](const std::string& args) {
    return testing::run_shell("cd " + shell_quote(dir.string()) + " && " + path + "CAPSULE_BIN=" +
                              shell_quote(testing::capsule_binary().string()) + " " +
                              shell_quote(testing::study_binary().string()) + " " + args + " </dev/null");
  };
  const auto status = study("status c.json");
  INFO(status.output);
  CHECK(status.exit_code == 4);
  CHECK(status.output.find("queued: 1") != std::string::npos);
  CHECK(status.output.find("[queued] " + s.members[1].dir_name() + ": waiting in Slurm's queue: job " + job +
                           " task 1 (PENDING)") != std::string::npos);
  CHECK(status.output.find("`study export --slurm` again") != std::string::npos);
  const auto again = study("export c.json --slurm");
  INFO(again.output);
  CHECK(testing::read_text(s.layout.slurm_dir() / "capsule.sbatch").find("#SBATCH --array=0,2\n") != std::string::npos);
  const auto run = study("run c.json");
  INFO(run.output);
  CHECK(run.output.find("running 2 of 3") != std::string::npos);  // not the queued one
  fs::remove_all(dir);
}
