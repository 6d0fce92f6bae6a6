// `capsule check` prints the memory a scene needs and refuses one larger than the machine.
#include <catch2/catch.hpp>

#include "solver/scene/memory_estimate.hpp"
#include "tests/solver/run/member_compare.hpp"

using namespace capsule;
using namespace capsule::testing;

TEST_CASE("capsule check prints the memory a scene needs and refuses one larger than this machine", "[capsule2d]") {
  const auto dir = scratch("memory");
  nlohmann::json s = {{"dim", 2}, {"shape", "circle"}, {"Ca", 0.05}, {"E_b", 0.05}, {"V", 1}, {"eta", 0},
                      {"protocol", {{"shear", {{"until", "time"}, {"kt", 1}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}}};
  const auto small = write_scene(dir, "small", s);
  const std::string capsule = std::string(CAPSULE_BINARY_DIR) + "/solver/capsule";
  auto run = [&](const std::string& args) {
    const std::string log = (dir / "log").string();
    const int rc = std::system((capsule + " " + args + " > " + quoted(log) + " 2>&1").c_str());
    std::ifstream in(log);
    return std::make_pair(WEXITSTATUS(rc), std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
  };
  auto [rc, text] = run("check " + quoted(small.string()));
  INFO(text);
  CHECK(rc == 0);
  CHECK(text.find("capsule: memory: ") != std::string::npos);

  // 20000 x 20000 nodes: about 80 GB, beyond the machines this suite runs on.
  s["resolution"] = {{"a", 200}, {"domain", {100, 100}}};
  const Scene huge = Scene::from_json(s, "huge");
  REQUIRE(estimate_memory(huge).total() > physical_memory_bytes());
  const auto big = write_scene(dir, "big", s);
  std::tie(rc, text) = run("check " + quoted(big.string()));
  INFO(text);
  CHECK(rc == 2);
  CHECK(text.find("more than this machine's") != std::string::npos);
  CHECK(text.find(format_bytes(physical_memory_bytes())) != std::string::npos);
  std::tie(rc, text) = run(quoted(big.string()) + " -o " + quoted((dir / "m.h5").string()));
  CHECK(rc == 2);
  CHECK(!std::filesystem::exists(dir / "m.h5.partial"));

  // The estimate follows the arrays: D2Q9 at 160 x 120 is one padded array of 9 double
  // populations (in-place streaming) and 7 double fields.
  const Scene d = Scene::from_json({{"dim", 2}, {"shape", "circle"}, {"Ca", 0.05}, {"E_b", 0.05}, {"V", 1}, {"eta", 0},
                                    {"protocol", {{"shear", {{"until", "time"}, {"kt", 1}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}}},
                                   "default");
  const MemoryEstimate m = estimate_memory(d);
  CHECK(m.fluid > (9 + 7) * 160 * 120 * 8.0);
  CHECK(m.fluid < 1.2 * (9 + 7) * 160 * 120 * 8.0);  // the padding: a few per cent
  CHECK(m.fields == 0);
}
