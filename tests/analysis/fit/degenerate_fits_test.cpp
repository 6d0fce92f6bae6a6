// Fits that cannot be made must say why and carry no number (analysis/README.md "What each fit fits").
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "analysis/fit/bilinear_fit.hpp"
#include "analysis/fit/exponential_fits.hpp"
#include "analysis/fit/member_fits.hpp"
#include "solver/io/member_file.hpp"

using namespace capsule::analysis;
using Catch::Matchers::Contains;

namespace {
constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();
std::vector<double> grid(double t0, double t1, double dt) {
  std::vector<double> t;
  for (double x = t0; x <= t1 + 1e-12; x += dt) t.push_back(x);
  return t;
}
void check_failed(const FitResult& f, const std::string& why) {
  CHECK_FALSE(f.ok);
  CHECK_THAT(f.reason, Contains(why));
  CHECK(f.parameters.empty());
  // Serialised, a failure holds the reason and no number.
  const auto j = to_json(f);
  CHECK_FALSE(j.contains("parameters"));
  CHECK(j.at("reason").get<std::string>() == f.reason);
}
}  // namespace

TEST_CASE("Degenerate series give a reason, not a number", "[analysis]") {
  const auto kt = grid(0.0, 10.0, 0.1);
  SECTION("constant series") {
    const std::vector<double> D(kt.size(), 0.25);
    check_failed(fit_recovery(kt, D, 0.25, 5.0, 10.0), "constant");
    check_failed(fit_response(kt, D, 0.25, 5.0), "constant");
  }
  SECTION("two points") {
    const std::vector<double> t{5.0, 5.1}, D{0.3, 0.29};
    check_failed(fit_recovery(t, D, 0.3, 5.0, 5.1), "too few points (2");
  }
  SECTION("NaN in the series") {
    std::vector<double> D;
    for (double t : kt) D.push_back(0.3 * std::exp(-t));
    D[60] = nan_v;
    check_failed(fit_recovery(kt, D, 0.3, 5.0, 10.0), "non-finite D_xy at kt = 6");
  }
  SECTION("marker not reached") {
    std::vector<double> D;
    for (double t : kt) D.push_back(0.3 * std::exp(-t));
    check_failed(fit_recovery(kt, D, 0.3, nan_v, 10.0), "marker t_stop not reached");
    check_failed(fit_two_phase_initial(kt, D, 0.3, nan_v, 0.0, 5.0), "marker D_min not reached");
  }
  SECTION("no recovery phase: the interval is empty") {
    std::vector<double> D;
    for (double t : kt) D.push_back(0.3 * (1 - std::exp(-t)));
    check_failed(fit_recovery(kt, D, 0.3, 10.0, 10.0), "empty interval");
  }
  SECTION("zero amplitude") {
    std::vector<double> D;
    for (double t : kt) D.push_back(0.5 + 0.01 * std::sin(t));
    check_failed(fit_double_exponential(kt, D, 0.5, 0.5, 0.0, 10.0), "zero amplitude");
  }
  SECTION("a model that does not describe its data is refused with its R^2") {
    // A biconcave capsule starts at D = 0.812, dips and comes back: (85), which starts at
    // D = 0, cannot describe it (R^2 = -80 was once printed as a number).
    std::vector<double> D;
    for (double t : kt) D.push_back(0.812 - 0.3 * std::sin(3.14159265358979 * t / 10.0) + 0.001 * t);
    const FitResult f = fit_response(kt, D, D.back(), 10.0);
    check_failed(f, "does not describe the data: R^2 = ");
    CHECK(f.r_squared < 0.0);
  }
  SECTION("an instant drop: k tau below the output spacing is refused") {
    // D = D_stop at t_stop and 0 right after: (86) is best matched by k tau -> 0, which
    // the data cannot resolve, so the fit is refused instead of reporting 1e-9.
    std::vector<double> D;
    for (double t : kt) D.push_back(t < 4.95 ? 0.3 : 0.0);
    for (std::size_t i = 0; i < kt.size(); ++i)
      if (std::abs(kt[i] - 5.0) < 1e-9) D[i] = 0.3;
    {
      const FitResult f = fit_recovery(kt, D, 0.3, 5.0, 10.0);
      CHECK_FALSE(f.ok);
      CHECK_THAT(f.reason, Contains("lower bound") || Contains("not resolved"));
    }
  }
}

TEST_CASE("Bilinear fit: too few members, NaN and collinear designs give reasons", "[analysis]") {
  check_failed(fit_bilinear({0, 1, 2}, {1, 1, 2}, {0.4, 0.5, 0.6}), "too few members (3");
  check_failed(fit_bilinear({0, 1, 2, 3, 4}, {1, 1, 2, 2, nan_v}, {0.4, 0.5, 0.6, 0.7, 0.8}), "non-finite");
  // Every member at V = 1: b and c cannot be separated (rank-deficient Jacobian).
  check_failed(fit_bilinear({0, 1, 2, 3, 4, 5}, {1, 1, 1, 1, 1, 1}, {0.4, 0.42, 0.45, 0.46, 0.49, 0.5}),
               "rank deficient");
}

TEST_CASE("A member marked unstable gives a stated reason for every fit", "[analysis]") {
  const auto dir = std::filesystem::temp_directory_path() / ("capsule_analysis_unstable_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "member.h5").string();
  {
    capsule::io::MemberWriter w(path);
    w.set_scene({{"Ca", 0.05}});
    for (int i = 0; i < 40; ++i) {
      const double t = 0.1 * i;
      w.append({{"kt", t}, {"D_xy", 0.3 * (1 - std::exp(-t))}, {"theta", 0.5}, {"shear_on", 1.0}});
    }
    w.set_markers({{"t_max", 3.9}, {"D_max", 0.29}, {"t_stop", nan_v}, {"D_stop", nan_v}, {"t_min", nan_v},
                   {"D_min", nan_v}, {"t_end", nan_v}, {"D_inf", nan_v}});
    w.finish("unstable at kt = 3.9: non-finite velocity");
  }
  const auto member = capsule::io::read_member(path);
  const MemberFits fits = fit_member(member, {"response", "recovery", "two_phase", "double_exponential"});
  REQUIRE(fits.size() == 5);
  for (const auto& [name, f] : fits) {
    INFO(name);
    check_failed(f, "member not complete: unstable at kt = 3.9");
  }
  std::filesystem::remove_all(dir);
}
