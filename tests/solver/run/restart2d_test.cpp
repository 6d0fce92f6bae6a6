// Restart points inside a 2D member (docs/guide/running.md "Checkpoints"): a member killed and run again with
// the same command continues from its last restart point, and its rows, markers and shapes are
// bitwise those of an uninterrupted run; restart points of another run are refused.
#include <catch2/catch.hpp>

#include "tests/support/hdf5_damage.hpp"

#include "solver/io/state_archive.hpp"
#include "tests/solver/run/member_compare.hpp"
#include "tests/solver/run/tiny_scenes.hpp"

using namespace capsule;
using namespace capsule::testing;
namespace fs = std::filesystem;

namespace {

// With shapes: every piece of state a restart point carries.
nlohmann::json tiny_2d(double Ca = 0.05) { return tiny_2d_scene(Ca, {0.3, 1.1}); }

}  // namespace

TEST_CASE("2D restart point inside an output interval: the resumed member is bitwise the uninterrupted one",
          "[capsule2d][restart]") {
  const fs::path dir = scratch("2d_mid");
  const fs::path scene = write_scene(dir, "s", tiny_2d());
  require_restart_is_bitwise(dir, scene, 1234, 2000);
}

TEST_CASE("2D restart point on an output row: the row is not written twice", "[capsule2d][restart]") {
  const fs::path dir = scratch("2d_row");
  const fs::path scene = write_scene(dir, "s", tiny_2d());
  const auto probe = run_capsule(scene, dir / "probe.h5", "--quiet");
  REQUIRE(probe.exit_code == 0);
  const long n = steps_per_output(io::read_member((dir / "probe.h5").string()));
  require_restart_is_bitwise(dir, scene, 12 * n, 12 * n);  // killed right after writing it
}

TEST_CASE("a restart point of another scene, another member id or a damaged one is refused: the member starts afresh",
          "[capsule2d][restart]") {
  const fs::path dir = scratch("2d_refuse");
  const fs::path a = write_scene(dir, "a", tiny_2d(0.05)), b = write_scene(dir, "b", tiny_2d(0.06));
  const fs::path out = dir / "m.h5", restart = dir / "m.h5.restart";
  REQUIRE(run_capsule(b, dir / "b_whole.h5", "--quiet").exit_code == 0);
  const auto b_whole = io::read_member((dir / "b_whole.h5").string());

  SECTION("another scene") {
    REQUIRE(run_capsule(a, out, "--checkpoint-at-step 500 --stop-after-step 600").exit_code == 1);
    REQUIRE(fs::exists(restart));
    const auto r = run_capsule(b, out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    // The key that changed is named, with both values.
    CHECK(r.output.find("refused: another scene (key Ca: 0.05 in the restart point, 0.06 now); starting afresh") !=
          std::string::npos);
    require_bitwise_equal(b_whole, io::read_member(out.string()));
  }
  SECTION("another member id") {
    REQUIRE(run_capsule(b, out, "--id aaaa --checkpoint-at-step 500 --stop-after-step 600").exit_code == 1);
    const auto r = run_capsule(b, out, "--id bbbb");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("refused: member id \"aaaa\"") != std::string::npos);
    require_bitwise_equal(b_whole, io::read_member(out.string()));
  }
  SECTION("a restart point whose saved reference shape differs from the rebuilt one") {
    REQUIRE(run_capsule(b, out, "--checkpoint-at-step 500 --stop-after-step 600").exit_code == 1);
    io::StateArchive saved = io::StateArchive::read(restart.string());
    std::vector<double> l0 = saved.doubles("membrane.reference_lengths");
    l0[0] *= 1.0 + 1e-15;
    saved.put("membrane.reference_lengths", l0);
    saved.write(restart.string());
    const auto r = run_capsule(b, out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("refused: restart point: the membrane's reference lengths differs") != std::string::npos);
    require_bitwise_equal(b_whole, io::read_member(out.string()));
  }
  SECTION("one flipped bit in the saved series (Fletcher32 checksum)") {
    REQUIRE(run_capsule(b, out, "--checkpoint-at-step 500 --stop-after-step 600").exit_code == 1);
    capsule::testing::flip_bit_in_dataset(restart.string(), "member.series.D_xy");
    const auto r = run_capsule(b, out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("refused: " + restart.string() + ": dataset member.series.D_xy cannot be read: its checksum "
                        "does not match") != std::string::npos);
    require_bitwise_equal(b_whole, io::read_member(out.string()));
  }
  SECTION("a damaged file") {
    std::ofstream(restart) << "not HDF5";
    const auto r = run_capsule(b, out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("refused: ") != std::string::npos);
    require_bitwise_equal(b_whole, io::read_member(out.string()));
  }
  CHECK(!fs::exists(restart));
}

TEST_CASE("restart points by wall time: --checkpoint-seconds writes them, 0 writes none", "[capsule2d][restart]") {
  const fs::path dir = scratch("2d_seconds");
  nlohmann::json s = tiny_2d();
  // Long enough (about 0.4 s) that a 0.05 s interval comes round many times, on any machine.
  s["protocol"]["recover"]["kt"] = 6.0;
  const fs::path scene = write_scene(dir, "s", s);
  // A tiny interval writes one at almost every step check; the member still completes and
  // records how many it wrote and what they cost.
  const auto r = run_capsule(scene, dir / "m.h5", "--checkpoint-seconds 0.05 --quiet");
  REQUIRE(r.exit_code == 0);
  const auto m = io::read_member((dir / "m.h5").string());
  CHECK(m.attributes.at("checkpoints_written").get<long>() >= 1);
  CHECK(m.attributes.at("checkpoint_bytes").get<long>() > 0);
  CHECK(!fs::exists(dir / "m.h5.restart"));
  const auto off = run_capsule(scene, dir / "off.h5", "--checkpoint-seconds 0 --stop-after-step 900");
  REQUIRE(off.exit_code == 1);
  CHECK(!fs::exists(dir / "off.h5.restart"));
}
