// The lattice solver's convergence at CI size: the small-deformation limit of a neo-Hookean
// sphere, D_xy / Ca -> 25/4 (Barthes-Biesel and Rallison 1981, Ca = mu k a / E_s with
// G_s = E_s / 3), on the ladder a = 5, 6, 7 (mesh level 3) with the default roma3 kernel and
// the stresslet's marker inset. Without the inset the error was first order in 1/a and +17 /
// +11 % at a = 5 / 7 (the smeared shell's hydrodynamic radius,
// docs/findings/immersed_boundary_error_budget.md); with it, measured 2026-12-05: D/Ca 6.340 /
// 6.306 / 6.287 (+1.4 / +0.9 / +0.6 %), three-level observed order about 2.5.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <vector>

#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

// D_xy / Ca averaged over kt 0.9-1.2: the response is steady from kt ~ 0.5 (its time scale is
// 12.5 Ca = 0.06), and the average removes the lattice's pinning flicker (0.05 % of D).
// refine: the fluid refined about the capsule (resolution.refine, margin 0.6); double: the
// uniform lattice in double precision, as the refined fluid runs.
double steady_ratio(double a, bool refine = false, bool double_precision = false, double kt_end = 1.2) {
  const double Ca = 0.005;
  nlohmann::json j = {{"dim", 3}, {"shape", "sphere"}, {"Ca", Ca}, {"E_b", 0}, {"V", 1}, {"eta", 0},
                      {"resolution", {{"a", a}, {"mesh_level", 3}}},
                      {"protocol", {{"shear", {{"until", "time"}, {"kt", kt_end}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}},
                      {"output", {{"interval_kt", 0.1}}}};
  if (refine) j["resolution"]["refine"] = {{"margin", 0.6}};
  if (double_precision) j["resolution"]["precision"] = "double";
  const Scene scene = Scene::from_json(j, "small_deformation.json");
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("small_deformation_a" + std::to_string(int(a)) + (refine ? "_refined" : "") + ".h5"))
                               .string();
  {
    io::MemberWriter out(path);
    out.finish(run_simulation3d(scene, out, true));
  }
  const io::MemberData d = io::read_member(path);
  std::filesystem::remove(path);
  REQUIRE(d.status == "complete");
  const auto& kt = d.series.at("kt");
  const auto& D = d.series.at("D_xy");
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < kt.size(); ++i)
    if (kt[i] > kt_end - 0.35) sum += D[i], ++n;
  REQUIRE(n >= 3);
  return sum / n / Ca;
}

}  // namespace

TEST_CASE("convergence: the small-deformation limit on a = 5, 6, 7 falls towards 25/4 faster than first order", "[capsule3d]") {
  const double exact = 25.0 / 4.0;
  std::vector<double> e;
  for (double a : {5.0, 6.0, 7.0}) e.push_back(steady_ratio(a) / exact - 1.0);
  // Order p from e(a) = c a^-p on three levels: (5^-p - 6^-p) / (6^-p - 7^-p) = the measured
  // ratio of the differences (the left side grows with p; bisection).
  const double ratio = (e[0] - e[1]) / (e[1] - e[2]);
  auto r_of = [](double p) { return (std::pow(5.0, -p) - std::pow(6.0, -p)) / (std::pow(6.0, -p) - std::pow(7.0, -p)); };
  double lo = 0.1, hi = 6.0;
  for (int i = 0; i < 60; ++i) (r_of(0.5 * (lo + hi)) < ratio ? lo : hi) = 0.5 * (lo + hi);
  const double p = 0.5 * (lo + hi);
  INFO("D/Ca errors " << e[0] << ", " << e[1] << ", " << e[2] << ": observed order " << p);
  // The error falls monotonically, each level within 2 % of theory (the remedy's target at
  // a = 7), and faster than the first order of the markers on a: a first-order error of the
  // same size at a = 5 would leave +1.0 % at a = 7. 1.3 leaves room for the pinning flicker.
  CHECK(e[0] > e[1]);
  CHECK(e[1] > e[2]);
  CHECK(std::abs(e[0]) < 0.02);
  CHECK(std::abs(e[2]) < 0.01);
  CHECK(p > 1.3);
}

TEST_CASE("convergence: the refined sphere's small-deformation ladder a = 4, 5, 6 converges with its gap to the uniform lattice", "[capsule3d][refine]") {
  // resolution.refine at each a (the fine lattice's; the block 0.6 a beyond the markers),
  // against the uniform lattice at the same a in the same (double) precision, sheared to kt 0.9
  // (steady from kt ~ 0.5 at this Ca; the average over kt > 0.55). A refined member is the
  // uniform member at a with a coarse far field plus the interface's own error, which at this
  // small deformation is not small against D. Measured 2026-12-08 (this test): refined -
  // uniform +2.78 / +0.73 / +0.49 % of D/Ca at a = 4 / 5 / 6 (+0.34 % at a = 7, kt 1.2), the
  // refined errors against 25/4 +3.98 / +2.14 / +1.43 %; at a = 4 the block's face is 2.4 fine
  // spacings from the markers, where the kernel reaches 2 (docs/findings/refinement.md "The
  // capsule on the fine level"). The bounds: the gap falls with a, faster than first order,
  // below 1 % from a = 5 on, and the refined ladder converges.
  const double exact = 25.0 / 4.0;
  const std::vector<double> as = {4.0, 5.0, 6.0};
  std::vector<double> e, gap;
  for (double a : as) {
    const double refined = steady_ratio(a, true, false, 0.9), uniform = steady_ratio(a, false, true, 0.9);
    e.push_back(refined / exact - 1.0);
    gap.push_back(refined / uniform - 1.0);
  }
  auto order = [&](const std::vector<double>& x) {
    const double ratio = (x[0] - x[1]) / (x[1] - x[2]);
    auto r_of = [&](double p) {
      return (std::pow(as[0], -p) - std::pow(as[1], -p)) / (std::pow(as[1], -p) - std::pow(as[2], -p));
    };
    double lo = 0.1, hi = 6.0;
    for (int i = 0; i < 60; ++i) (r_of(0.5 * (lo + hi)) < ratio ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  const double p = order(e), p_gap = std::log(gap[0] / gap[2]) / std::log(as[2] / as[0]);
  INFO("refined D/Ca errors " << e[0] << ", " << e[1] << ", " << e[2] << ": observed order " << p << "; refined - uniform "
                              << gap[0] << ", " << gap[1] << ", " << gap[2] << ": order " << p_gap);
  WARN("refined ladder: D/Ca errors " << e[0] << ", " << e[1] << ", " << e[2] << " (order " << p << "); refined - uniform "
                                      << gap[0] << ", " << gap[1] << ", " << gap[2] << " (order " << p_gap << ")");
  CHECK(gap[0] > gap[1]);
  CHECK(gap[1] > gap[2]);
  CHECK(gap[1] < 0.01);
  CHECK(gap[2] < 0.01);
  CHECK(p_gap > 1.3);
  CHECK(e[0] > e[1]);
  CHECK(e[1] > e[2]);
  CHECK(p > 1.3);
}
