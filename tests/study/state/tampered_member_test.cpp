// Nothing tampered reads as complete: a member file without its content hash is refused unless
// legacy files are asked for (solver/io/member_file.hpp), and status, plan and run verify the
// whole file before they call a member complete (study/state/member_verification.hpp).
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <thread>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/state/member_verification.hpp"
#include "tests/study/support/study_test_support.hpp"
#include "tests/support/hdf5_damage.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

void delete_root_attribute(const fs::path& file, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  H5Adelete(f, name.c_str());
  H5Fclose(f);
}

// Rewrites a root text attribute in place, as an editor of HDF5 files would; the content hash is kept.
void set_root_text(const fs::path& file, const std::string& name, const std::string& value) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  H5Adelete(f, name.c_str());
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(f, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char* text = value.c_str();
  H5Awrite(attr, type, &text);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(f);
}

// Doubles every value of a series (a dataset rewritten whole: its own checksum stays valid).
void edit_series(const fs::path& file, const std::string& series) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t d = H5Dopen2(f, ("series/" + series).c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  for (double& v : values) v *= 2;
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
}

}  // namespace

TEST_CASE("a member file whose content hash was removed and data edited is refused unless legacy files are asked for",
          "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("hash_removed");
  auto doc = testing::tiny_campaign("hash_removed", {0.02, 0.05}, 2, 2);
  doc["analysis"] = {{"fits", {"response"}}, {"figures", false}};
  testing::write_text(dir / "c.json", doc.dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const MemberPaths p = s.layout.member(s.members[0]);
  delete_root_attribute(p.h5, "content_hash");
  edit_series(p.h5, "D_xy");

  const auto report = testing::run_study({"report", "c.json"}, dir);
  INFO(report.output);
  CHECK(report.exit_code != 0);
  CHECK_THAT(report.output, Catch::Contains("no content hash"));
  CHECK_FALSE(fs::exists(s.layout.report_dir() / "fits.json"));
  const auto status = testing::run_study({"status", "c.json"}, dir);
  INFO(status.output);
  CHECK(status.exit_code != 0);
  CHECK_THAT(status.output, Catch::Contains("[unreadable] " + s.members[0].dir_name()) &&
                                Catch::Contains("no content hash"));

  // Asked for explicitly, the file is read as a legacy one.
  const auto legacy = testing::run_study({"report", "c.json", "--legacy-member-files"}, dir);
  INFO(legacy.output);
  CHECK(legacy.exit_code == 0);
  CHECK(fs::exists(s.layout.report_dir() / "fits.json"));
  fs::remove_all(dir);
}

TEST_CASE("status, plan and run verify a member file before calling it complete - the verification is remembered",
          "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("verified_complete");
  testing::write_text(dir / "c.json", testing::tiny_campaign("verified", {0.02}, 0.3, 0).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  REQUIRE(s.conditions[0].state == MemberState::complete);
  const MemberPaths p = s.layout.member(s.members[0]);
  // Verified once: the record names the file's size, times and hash.
  REQUIRE(fs::exists(verification_record(p.h5)));
  CHECK_THAT(testing::read_text(verification_record(p.h5)), Catch::Contains("content_hash"));

  SECTION("physics_version edited, the hash kept") { set_root_text(p.h5, "physics_version", "0"); }
  SECTION("status rewritten and an attribute removed, the hash kept") {
    set_root_text(p.h5, "status", "complete");  // rewritten the same: the file changed, its content not
    delete_root_attribute(p.h5, "code_version");
  }
  SECTION("one flipped bit in a dataset") { capsule::testing::flip_bit_in_dataset(p.h5.string(), "series/D_xy"); }
  const std::string damaged = testing::read_text(p.h5);

  for (const std::vector<std::string>& command : {std::vector<std::string>{"status", "c.json"},
                                                 std::vector<std::string>{"plan", "c.json"},
                                                 std::vector<std::string>{"run", "c.json"}}) {
    INFO(command[0]);
    const auto out = testing::run_study(command, dir);
    INFO(out.output);
    CHECK_THAT(out.output, Catch::Contains("unreadable"));
    if (command[0] != "plan") CHECK(out.exit_code != 0);
  }
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::unreadable);
  CHECK(testing::read_text(p.h5) == damaged);  // kept as it is, never rerun over
  CHECK_FALSE(fs::exists(verification_record(p.h5)));
  fs::remove_all(dir);
}

TEST_CASE("a verified member file is read whole again only when its size, times or hash change", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("verification_record");
  testing::write_text(dir / "c.json", testing::tiny_campaign("record", {0.02}, 0.3, 0).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const MemberPaths p = s.layout.member(s.members[0]);
  const fs::path record = verification_record(p.h5);
  const std::string recorded = testing::read_text(record);
  REQUIRE_FALSE(recorded.empty());
  const std::string hash = recorded.substr(recorded.find("content_hash ") + 13, recorded.size() - recorded.find("content_hash ") - 14);
  const auto record_time = fs::last_write_time(record);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  // The same file: answered from the record, which stays as it was.
  CHECK(verify_member_file(p.h5, hash).empty());
  CHECK(fs::last_write_time(record) == record_time);
  // Touched (a new modification time): read whole again and recorded anew.
  fs::last_write_time(p.h5, fs::file_time_type::clock::now());
  CHECK(verify_member_file(p.h5, hash).empty());
  CHECK(testing::read_text(record) != recorded);
  CHECK_THAT(testing::read_text(record), Catch::Contains("content_hash " + hash));
  fs::remove_all(dir);
}
