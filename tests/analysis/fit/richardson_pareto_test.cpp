// Richardson extrapolation with the observed order, and the Pareto selection of settings,
// on synthetic data whose answer is known.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "analysis/fit/pareto.hpp"
#include "analysis/fit/richardson.hpp"

using namespace capsule::analysis;
using Catch::Matchers::Contains;

namespace {
std::vector<LadderLevel> series(double q0, double C, double p, const std::vector<double>& h) {
  std::vector<LadderLevel> out;
  for (double x : h) out.push_back({x, q0 + C * std::pow(x, p)});
  return out;
}
}  // namespace

TEST_CASE("Richardson recovers a known order and limit from exact series", "[analysis][ladder]") {
  // The values carry only rounding (~1e-16 relative on q ~ 0.3); the differences between
  // levels are >= 8e-3, so the ratio of differences is good to ~1e-14 and p (divided by a
  // log ratio >= 0.34) to ~1e-13. 1e-10 on p and 1e-12 on q0 leave a thousandfold margin.
  const double q0 = 0.3;
  struct Case {
    const char* what;
    double p, C;
    std::vector<double> h;
  };
  const std::vector<Case> cases{
      {"p = 1, uniform ratio 2 (a = 5, 10, 20)", 1.0, 0.8, {1.0 / 5, 1.0 / 10, 1.0 / 20}},
      {"p = 2, uniform ratio 2", 2.0, -0.8, {1.0 / 5, 1.0 / 10, 1.0 / 20}},
      {"p = 1, non-uniform (a = 5, 7, 10)", 1.0, -0.8, {1.0 / 5, 1.0 / 7, 1.0 / 10}},
      {"p = 2, non-uniform (a = 5, 7, 10)", 2.0, 0.8, {1.0 / 10, 1.0 / 5, 1.0 / 7}},  // any order in
      {"p = 1.5, mesh levels 2^-2, 2^-3, 2^-4", 1.5, 0.5, {0.25, 0.125, 0.0625}},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    const RichardsonResult r = richardson(series(q0, c.C, c.p, c.h), 1.0);
    REQUIRE(r.ok);
    CHECK(r.order_observed);
    CHECK(r.order == Approx(c.p).margin(1e-10));
    CHECK(r.extrapolated == Approx(q0).margin(1e-12));
    const double h_min = *std::min_element(c.h.begin(), c.h.end());
    CHECK(r.finest == Approx(q0 + c.C * std::pow(h_min, c.p)).margin(1e-15));
    CHECK(r.error_estimate == Approx(std::abs(c.C) * std::pow(h_min, c.p)).margin(1e-12));
  }
}

TEST_CASE("Richardson uses the three finest levels and refuses what it cannot do", "[analysis][ladder]") {
  // A coarse level far off the model does not change the result: only the finest three count.
  auto levels = series(0.3, 0.8, 1.0, {1.0 / 7, 1.0 / 10, 1.0 / 14});
  levels.push_back({1.0 / 4, 5.0});
  const RichardsonResult r = richardson(levels, 1.0);
  REQUIRE(r.ok);
  CHECK(r.levels == 4);
  CHECK(r.order == Approx(1.0).margin(1e-10));

  const RichardsonResult one = richardson({{0.1, 0.3}}, 1.0);
  CHECK_FALSE(one.ok);
  CHECK(one.finest == 0.3);
  CHECK_THAT(one.reason, Contains("one level"));

  // Two levels: the order is assumed (stated), the error estimate is |finest - extrapolated|
  // at that order, as with three levels.
  const RichardsonResult two = richardson({{0.1, 0.31}, {0.2, 0.32}}, 1.0);
  REQUIRE(two.ok);
  CHECK_FALSE(two.order_observed);
  CHECK(two.order == 1.0);
  CHECK(two.extrapolated == Approx(0.30).margin(1e-14));  // 0.31 - (0.32 - 0.31) / (2 - 1)
  CHECK(two.error_estimate == Approx(0.01).margin(1e-14));  // h ratio 2, p = 1: |q1 - q0| = |q1 - q2|
  CHECK_THAT(two.reason, Contains("order assumed p = 1"));
  // a = 5 and 7 (h = 1/5, 1/7): |q1 - q0| = |q1 - q2| / ((7/5)^p - 1), 2.5 |q1 - q2| at p = 1.
  const RichardsonResult a57 = richardson({{1.0 / 7, 0.40}, {1.0 / 5, 0.44}}, 1.0);
  REQUIRE(a57.ok);
  CHECK(a57.extrapolated == Approx(0.30).margin(1e-12));
  CHECK(a57.error_estimate == Approx(0.10).margin(1e-12));
  const RichardsonResult a57p2 = richardson({{1.0 / 7, 0.40}, {1.0 / 5, 0.44}}, 2.0);
  CHECK(a57p2.error_estimate == Approx(0.04 / (49.0 / 25.0 - 1.0)).margin(1e-12));

  const RichardsonResult zigzag = richardson({{0.1, 0.30}, {0.2, 0.32}, {0.4, 0.31}}, 1.0);
  CHECK_FALSE(zigzag.ok);
  CHECK(zigzag.reason == "not monotone: no order");
  // Monotone but the differences grow towards fine h: no positive order.
  const RichardsonResult diverging = richardson({{0.1, 0.30}, {0.2, 0.32}, {0.4, 0.33}}, 1.0);
  CHECK_FALSE(diverging.ok);
  CHECK_THAT(diverging.reason, Contains("not converging"));
  CHECK_THROWS_AS(richardson({{0.1, 0.3}, {0.1, 0.4}}, 1.0), std::invalid_argument);
}

TEST_CASE("Pareto selection picks the non-dominated settings and the cheapest within a bound", "[analysis][accuracy]") {
  // cost (core-s), relative error
  const std::vector<CostError> p{
      {10, 0.20},   // 0: cheapest: on the front
      {20, 0.05},   // 1: front
      {25, 0.08},   // 2: dominated by 1
      {40, 0.012},  // 3: front
      {40, 0.015},  // 4: dominated by 3 (same cost, larger error)
      {80, 0.004},  // 5: front
      {90, 0.004},  // 6: dominated by 5 (same error, dearer)
      {std::nan(""), 0.001},  // 7: no cost: takes no part
  };
  CHECK(pareto_front(p) == std::vector<std::size_t>{0, 1, 3, 5});
  CHECK(cheapest_within(p, 0.01) == std::optional<std::size_t>(5));
  CHECK(cheapest_within(p, 0.02) == std::optional<std::size_t>(3));
  CHECK(cheapest_within(p, 0.05) == std::optional<std::size_t>(1));
  CHECK_FALSE(cheapest_within(p, 0.001).has_value());
  CHECK(pareto_front({}).empty());
}
