// `capsule shapes` (solver/run/shape_rerun.hpp): the shapes of a member that ended without
// storing them, by a rerun that stops at the last time asked for. They must be bit for bit those
// of the same scene run with output.shapes_at_kt, the member's files must stay as they were, and
// bad input must be refused before anything runs.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <map>

#include "capsule_process.hpp"
#include "solver/scene/scene.hpp"
#include "tests/solver/run/member_compare.hpp"
#include "tests/solver/run/tiny_scenes.hpp"

using namespace capsule;
using namespace capsule::testing;
namespace fs = std::filesystem;

namespace {

nlohmann::json tiny_2d(double Ca = 0.05) { return tiny_2d_scene(Ca, {}); }
nlohmann::json tiny_3d() { return tiny_3d_scene({}); }

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file of a folder with its bytes: what a command may not change.
std::map<std::string, std::string> folder_contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = bytes_of(e.path());
  return files;
}

// A member folder as `study` leaves it: scene.json (without shapes) and the finished member.h5.
fs::path finished_member(const fs::path& dir, const nlohmann::json& scene, const std::string& extra = "--quiet") {
  const fs::path member = dir / "member";
  fs::create_directories(member);
  const auto run = run_capsule(write_scene(member, "scene", scene), member / "member.h5", extra);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  return member;
}

// The same scene run to its end with the shapes (and snapshots) stored by the member itself.
io::MemberData run_with_shapes(const fs::path& dir, nlohmann::json scene, const std::vector<double>& kt,
                               const std::string& snapshots = "none") {
  scene["output"]["shapes_at_kt"] = kt;
  scene["output"]["snapshots"] = snapshots;
  const auto run = run_capsule(write_scene(dir, "with_shapes", scene), dir / "with_shapes.h5", "--quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  return io::read_member((dir / "with_shapes.h5").string());
}

capsule_test::Result shapes(const fs::path& member, const std::string& args) {
  return capsule_test::run_capsule("shapes " + capsule_test::quote(member.string()) + " " + args);
}

void require_same_shapes(const io::MemberData& a, const io::MemberData& b) {
  REQUIRE(a.shapes.size() == b.shapes.size());
  for (std::size_t i = 0; i < a.shapes.size(); ++i) {
    INFO("shape " << i);
    CHECK(same_bits({a.shapes[i].kt}, {b.shapes[i].kt}));
    CHECK(a.shapes[i].dim == b.shapes[i].dim);
    CHECK(same_bits(a.shapes[i].xyz, b.shapes[i].xyz));
  }
  CHECK(a.triangles == b.triangles);
}

}  // namespace

TEST_CASE("capsule shapes of a 2D member: the stored run's shapes bit for bit from a rerun stopped early",
          "[capsule2d]") {
  const fs::path dir = scratch("shapes_2d");
  const fs::path member = finished_member(dir, tiny_2d());
  const auto before = folder_contents(member);
  const io::MemberData stored = run_with_shapes(dir, tiny_2d(), {0.3, 0.6});

  const auto r = shapes(member, "--at-kt 0.6,0.3 --threads 1");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("reproduce the member's series bitwise") != std::string::npos);
  const io::MemberData got = io::read_member((member / "shapes.h5").string());  // checks its content hash
  CHECK(got.status == "shapes");
  CHECK(got.series.empty());
  CHECK(got.markers.empty());
  require_same_shapes(stored, got);

  // It ran to the row of kt = 0.6 and no further: 12 of the member's rows, the steps to there.
  const io::MemberData m = io::read_member((member / "member.h5").string());
  const long steps_per_row = steps_per_output(m);
  CHECK(got.attributes.at("steps").get<long>() == 12 * steps_per_row);
  CHECK(got.attributes.at("rerun_steps").get<long>() == 12 * steps_per_row);
  CHECK(got.attributes.at("steps").get<long>() < m.attributes.at("steps").get<long>());
  CHECK(got.attributes.at("stopped_at_kt").get<double>() == Approx(0.6).margin(1e-12));
  CHECK(got.attributes.at("series_rows_compared") == 13);
  CHECK(got.attributes.at("series_max_difference") == 0.0);
  CHECK(got.attributes.at("member_id") == m.attributes.at("member_id"));
  CHECK(got.attributes.at("scene").at("output").at("shapes_at_kt") == nlohmann::json::array({0.3, 0.6}));

  // The member's folder: the same files, byte for byte, and the shape file beside them.
  auto after = folder_contents(member);
  REQUIRE(after.erase("shapes.h5") == 1);
  CHECK(after == before);
  fs::remove_all(dir);
}

TEST_CASE("capsule shapes of a 3D member: shapes and snapshots as the stored run's", "[capsule3d]") {
  const fs::path dir = scratch("shapes_3d");
  const fs::path member = finished_member(dir, tiny_3d());
  const auto before = folder_contents(member);
  const io::MemberData stored = run_with_shapes(dir, tiny_3d(), {0.1, 0.25}, "vtk");

  const fs::path out = dir / "frames" / "s.h5";
  fs::create_directories(out.parent_path());
  const auto r = shapes(member, "--at-kt 0.1,0.25 --snapshots vtk -q -o " + capsule_test::quote(out.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const io::MemberData got = io::read_member(out.string());
  require_same_shapes(stored, got);
  CHECK(got.triangles.size() == 3 * 320);  // level 2
  const io::MemberData m = io::read_member((member / "member.h5").string());
  CHECK(got.attributes.at("steps").get<long>() == 5 * steps_per_output(m));  // the row of kt = 0.25
  CHECK(got.attributes.at("threads") == m.attributes.at("threads"));         // the member's own count
  // The frames are those the member would have written, byte for byte; the .pvd lists them.
  for (const char* frame : {"_kt0000.100.vtp", "_kt0000.250.vtp"}) {
    INFO(frame);
    REQUIRE(fs::exists(dir / "frames" / (std::string("s") + frame)));
    CHECK(bytes_of(dir / "frames" / (std::string("s") + frame)) == bytes_of(dir / (std::string("with_shapes") + frame)));
  }
  CHECK(bytes_of(dir / "frames" / "s.pvd").find("s_kt0000.250.vtp") != std::string::npos);
  CHECK(folder_contents(member) == before);
  fs::remove_all(dir);
}

TEST_CASE("capsule shapes continues the member's restart point when it precedes the first time", "[capsule2d][restart]") {
  const fs::path dir = scratch("shapes_restart");
  fs::create_directories(dir / "member");
  const fs::path scene = write_scene(dir / "member", "scene", tiny_2d());
  const fs::path file = dir / "member" / "member.h5";
  // A member killed after a restart point at step 700, finished by the same command; the
  // restart point it continued from is put back, as a member that keeps one would have it.
  const auto killed = run_capsule(scene, file, "--quiet --checkpoint-at-step 700 --stop-after-step 800");
  REQUIRE(killed.exit_code == 1);
  fs::copy_file(file.string() + ".restart", dir / "kept.restart");
  REQUIRE(run_capsule(scene, file, "--quiet").exit_code == 0);
  REQUIRE(!fs::exists(file.string() + ".restart"));
  fs::copy_file(dir / "kept.restart", file.string() + ".restart");
  const auto before = folder_contents(dir / "member");
  const io::MemberData stored = run_with_shapes(dir, tiny_2d(), {0.3, 0.6, 0.9});

  const auto late = shapes(dir / "member", "--at-kt 0.6,0.9 -o " + capsule_test::quote((dir / "late.h5").string()));
  INFO(late.output);
  REQUIRE(late.exit_code == 0);
  CHECK(late.output.find("from the member's restart point at step 700") != std::string::npos);
  const io::MemberData from_restart = io::read_member((dir / "late.h5").string());
  CHECK(from_restart.attributes.at("rerun_steps").get<long>() == from_restart.attributes.at("steps").get<long>() - 700);
  REQUIRE(from_restart.shapes.size() == 2);
  CHECK(same_bits(from_restart.shapes[0].xyz, stored.shapes[1].xyz));
  CHECK(same_bits(from_restart.shapes[1].xyz, stored.shapes[2].xyz));

  // A first time before the restart point: the member's own is skipped, the rerun starts at 0;
  // one named with --restart is refused.
  const auto early = shapes(dir / "member", "--at-kt 0.3,0.6 -o " + capsule_test::quote((dir / "early.h5").string()));
  INFO(early.output);
  REQUIRE(early.exit_code == 0);
  CHECK(early.output.find("is not used (its last row is at kt = ") != std::string::npos);
  const io::MemberData from_start = io::read_member((dir / "early.h5").string());
  CHECK(from_start.attributes.at("rerun_from") == "kt = 0");
  REQUIRE(from_start.shapes.size() == 2);
  CHECK(same_bits(from_start.shapes[0].xyz, stored.shapes[0].xyz));
  const auto named = shapes(dir / "member", "--at-kt 0.3 --restart " + capsule_test::quote(file.string() + ".restart"));
  CHECK(named.exit_code == 2);
  CHECK(named.output.find("cannot be continued") != std::string::npos);
  CHECK(folder_contents(dir / "member") == before);  // the restart point too
  fs::remove_all(dir);
}

TEST_CASE("capsule shapes refuses what is not a finished member and times outside its rows", "[capsule2d]") {
  const fs::path dir = scratch("shapes_refused");
  const fs::path member = finished_member(dir, tiny_2d());
  const auto before = folder_contents(member);
  const auto refused = [&](const fs::path& where, const std::string& args, const std::string& message) {
    const auto r = shapes(where, args);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(message) != std::string::npos);
  };
  const double last = io::read_member((member / "member.h5").string()).series.at("kt").back();
  refused(member, "--at-kt 0.5," + std::to_string(last + 0.5), (member / "member.h5").string() + ": --at-kt ");
  refused(member, "--at-kt 99", "is outside the member's run: its rows span kt = 0 to ");
  refused(member, "--at-kt -1", "must be a number in [0, 100000]");
  refused(member, "--at-kt 0.5 --snapshots vtk", "snapshots are written for 3D members only");
  refused(member, "--at-kt 0.5 -o " + capsule_test::quote((member / "member.h5").string()), "is the member's own file");
  refused(dir, "--at-kt 0.5", "not a member folder (it holds no member.h5");
  refused(dir / "nowhere", "--at-kt 0.5", "no such member folder");
  CHECK(folder_contents(member) == before);

  // scene.json must be the scene member.h5 ran; its output keys may differ.
  nlohmann::json edited = tiny_2d();
  edited["output"]["shapes_at_kt"] = {0.5};
  write_scene(member, "scene", edited);
  CHECK(shapes(member, "--at-kt 0.5 -q").exit_code == 0);
  edited["Ca"] = 0.07;
  write_scene(member, "scene", edited);
  refused(member, "--at-kt 0.5", "scene.json: not the scene " + (member / "member.h5").string() + " ran (key Ca: 0.07 in scene.json");

  // A member killed before its end: only member.h5.partial and its restart point.
  const fs::path killed = dir / "killed";
  fs::create_directories(killed);
  REQUIRE(run_capsule(write_scene(killed, "scene", tiny_2d()), killed / "member.h5",
                      "--quiet --checkpoint-at-step 500 --stop-after-step 600")
              .exit_code == 1);
  refused(killed, "--at-kt 0.1", "the member has not ended (only member.h5.partial");
  CHECK(!fs::exists(killed / "shapes.h5"));
  fs::remove_all(dir);
}

TEST_CASE("capsule shapes refuses a member whose series the rerun does not reproduce", "[capsule2d]") {
  // A member file of another build whose physics gave other numbers: made here from the rows of
  // Ca = 0.06 under the scene of Ca = 0.05.
  const fs::path dir = scratch("shapes_other_build");
  const auto other = run_capsule(write_scene(dir, "other", tiny_2d(0.06)), dir / "other.h5", "--quiet");
  REQUIRE(other.exit_code == 0);
  const io::MemberData rows = io::read_member((dir / "other.h5").string());
  fs::create_directories(dir / "member");
  {
    io::MemberWriter w((dir / "member" / "member.h5").string());
    w.set_scene(Scene::from_json(tiny_2d(0.05), "tiny_2d").to_json());
    w.set_attribute("code_version", "0000000another");
    w.set_attribute("physics_version", "6");
    w.set_attribute("threads", 1L);
    for (std::size_t r = 0; r < rows.series.at("kt").size(); ++r) {
      std::map<std::string, double> row;
      for (const auto& [name, values] : rows.series) row[name] = values[r];
      w.append(row, rows.beta[r]);
    }
    w.finish("complete");
  }
  const auto before = folder_contents(dir / "member");
  const auto r = shapes(dir / "member", "--at-kt 0.5");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("does not reproduce") != std::string::npos);
  CHECK(r.output.find("code 0000000another") != std::string::npos);
  CHECK(folder_contents(dir / "member") == before);  // nothing written

  const auto accepted = shapes(dir / "member", "--at-kt 0.5 --accept-difference");
  INFO(accepted.output);
  REQUIRE(accepted.exit_code == 0);
  const io::MemberData got = io::read_member((dir / "member" / "shapes.h5").string());
  CHECK(got.attributes.at("series_check").get<std::string>().rfind("NOT REPRODUCED", 0) == 0);
  CHECK(got.attributes.at("series_max_difference").get<double>() > 0);
  fs::remove_all(dir);
}
