// The protocol on synthetic D_xy curves with known answers.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <numbers>

#include "solver/run/protocol.hpp"

using capsule::Protocol;
using capsule::Scene;
using nlohmann::json;

namespace {
Scene scene_with(const json& protocol) {
  json j = {{"dim", 2}, {"shape", "circle"}, {"Ca", 0.05}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
            {"protocol", protocol}};
  return Scene::from_json(j, "test");
}
// Feeds D(t) at dt until the protocol ends or t_cap; returns the last time fed.
template <class F>
double drive(Protocol& p, F D, double dt = 0.05, double t_cap = 200) {
  double kt = 0;
  for (int i = 0; !p.finished() && kt < t_cap; ++i) {
    kt = i * dt;
    p.observe(kt, D(kt, p.shear_on()), 0.0, 0.0);
  }
  return kt;
}
}  // namespace

TEST_CASE("shear until time, recover for a time: markers at the right rows", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "time"}, {"kt", 4}}}, {"recover", {{"until", "time"}, {"kt", 3}}}}));
  CHECK(p.shear_factor(1.0) == 1.0);
  double t_stop = -1;
  drive(p, [&](double t, bool on) {
    if (on) return 0.3 * (1 - std::exp(-t));
    if (t_stop < 0) t_stop = t;
    return 0.3 * (1 - std::exp(-4.0)) * std::exp(-(t - 4.0));
  });
  auto m = p.markers();
  CHECK(m["t_stop"] == Approx(4.0));
  CHECK(m["D_stop"] == Approx(0.3 * (1 - std::exp(-4.0))));
  CHECK(m["t_max"] == Approx(4.0));  // monotonic rise: the largest value is at the stop
  CHECK(m["t_end"] == Approx(7.0));
  CHECK(m["t_min"] == Approx(7.0));  // monotonic decay: the smallest value is at the end
  CHECK(p.finished());
  CHECK(p.shear_factor(5.0) == 0.0);
}

TEST_CASE("steady and settled detection use the stated window and tolerance", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "steady"}, {"tolerance", 1e-3}, {"window_kt", 2}}},
                         {"recover", {{"until", "settled"}, {"tolerance", 1e-3}, {"window_kt", 2}, {"window_fraction", 0}}}}));
  double stop_time = -1;
  drive(p, [&](double t, bool on) {
    if (on) return 0.2 * (1 - std::exp(-t));
    if (stop_time < 0) stop_time = t;
    return 0.2 * std::exp(-(t - stop_time));
  });
  auto m = p.markers();
  // D rises as 0.2(1 - e^-t): its range over [t-2, t] is 0.2 e^-t (e^2 - 1) < 1e-3 once
  // t > ln(0.2 (e^2 - 1) / 1e-3) = 7.16, so the stop is at the first output after that.
  CHECK(m["t_stop"] == Approx(7.2).margin(0.051));
  CHECK(m["t_end"] - m["t_stop"] == Approx(std::log(0.2 * (std::exp(2.0) - 1) / 1e-3)).margin(0.1));
  CHECK(m["D_inf"] < 2e-3);
}

TEST_CASE("settled is not fooled by the turning point of a slow, non-monotone recovery", "[protocol]") {
  // A tank-treading biconcave capsule's D_xy falls for ~15 kt after the stop and then rises
  // slowly back toward its undeformed 0.812 (Fig. 30; 0.639 was measured at the stop,
  // 0.5445 at the minimum). Here D = 0.5445 + c (s - 15)^2, s = kt - t_stop, with c such that
  // D(0) = 0.639: over any 2 kt window around s = 15 its range is below 1e-3.
  const double c = (0.639 - 0.5445) / 225.0;
  auto run = [&](double fraction) {
    Protocol p(scene_with({{"shear", {{"until", "time"}, {"kt", 1}}},
                           {"recover", {{"until", "settled"}, {"tolerance", 1e-3}, {"window_kt", 2},
                                        {"window_fraction", fraction}, {"max_kt", 40}}}}));
    drive(p, [&](double t, bool on) { return on ? 0.639 : 0.5445 + c * (t - 1.0 - 15.0) * (t - 1.0 - 15.0); });
    return p;
  };
  // A fixed 2 kt window (the old rule) ends the recovery at the turning point: t_min = t_end,
  // and the late phase (88) would have an empty interval.
  Protocol fixed = run(0.0);
  CHECK(fixed.markers()["t_end"] - 1.0 == Approx(16.0).margin(0.6));
  // The default window (half the time since the stop) sees the fall and the rise, and the
  // recovery runs on to its cap.
  Protocol grown = run(0.5);
  CHECK(grown.markers()["t_end"] - 1.0 == Approx(40.0).margin(1e-6));
  CHECK_THAT(grown.phase_note(), Catch::Contains("max_kt = 40"));
  CHECK(grown.markers()["t_min"] - 1.0 == Approx(15.0).margin(0.06));
}

TEST_CASE("settled with a growing window: an exponential recovery ends when the last half is flat", "[protocol]") {
  // D = 0.2 e^-s: the range over [s/2, s] is 0.2 (e^-s/2 - e^-s) < 1e-3 first near s = 10.6.
  Protocol p(scene_with({{"shear", {{"until", "time"}, {"kt", 1}}},
                         {"recover", {{"until", "settled"}, {"tolerance", 1e-3}, {"window_kt", 2}}}}));
  drive(p, [](double t, bool on) { return on ? 0.2 : 0.2 * std::exp(-(t - 1.0)); });
  double s = 1;
  while (0.2 * (std::exp(-s / 2) - std::exp(-s)) >= 1e-3) s += 1e-4;
  CHECK(p.markers()["t_end"] - 1.0 == Approx(s).margin(0.1));  // two output rows of slack
}

TEST_CASE("two-phase recovery: t_min is the dip before the slow rise (Sec. 4.1.1)", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "time"}, {"kt", 2}}}, {"recover", {{"until", "time"}, {"kt", 10}}}}));
  drive(p, [](double t, bool on) {
    if (on) return 0.9;
    double s = t - 2.0;  // fast dip to 0.6 then slow return to 0.812
    return 0.6 + 0.3 * std::exp(-s / 0.2) + 0.212 * (1 - std::exp(-s / 3.0)) - 0.212 * (1 - std::exp(-s / 3.0)) * std::exp(-s / 0.2);
  });
  auto m = p.markers();
  CHECK(m["t_min"] > 2.2);
  CHECK(m["t_min"] < 3.5);
  CHECK(m["D_min"] < m["D_stop"]);
  CHECK(m["D_min"] < m["D_inf"]);
}

TEST_CASE("angle conditions stop on crossing, not on wrap-around", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "theta"}, {"value", -std::numbers::pi / 3}}},
                         {"recover", {{"until", "time"}, {"kt", 1}}}}));
  // A tumbling inclination falling from pi/4 at 0.5 rad per kt.
  double kt = 0;
  for (int i = 0; p.shear_on() && i < 1000; ++i) {
    kt = 0.05 * i;
    p.observe(kt, 0.3, std::numbers::pi / 4 - 0.5 * kt, 0.0);
  }
  // theta = -pi/3 at kt = (pi/4 + pi/3)/0.5 = 3.665; the first row at or past it is 3.70.
  CHECK(p.markers()["t_stop"] == Approx(3.70).margin(1e-9));

  // The major axis wraps by pi: from -1.5 to +1.5 rad is a wrap, not a crossing of -pi/3
  // (the jump of 3 rad is below the 2 pi wrap of beta but above the pi/2 of an axis).
  Protocol w(scene_with({{"shear", {{"until", "theta"}, {"value", -std::numbers::pi / 3}}},
                         {"recover", {{"until", "time"}, {"kt", 1}}}}));
  w.observe(0.0, 0.3, -1.5, 0.0);
  w.observe(0.05, 0.3, 1.5, 0.0);
  CHECK(w.shear_on());

  Protocol q(scene_with({{"shear", {{"until", "beta"}, {"value", 3.0}}}, {"recover", {{"until", "time"}, {"kt", 1}}}}));
  q.observe(0.0, 0.1, 0.0, 3.1);
  q.observe(0.05, 0.1, 0.0, -3.1);  // wrapped from +pi to -pi: not a crossing of 3.0
  CHECK(q.shear_on());
  q.observe(0.10, 0.1, 0.0, 2.9);   // wrapped back, still no crossing (jump > pi)
  q.observe(0.15, 0.1, 0.0, 3.05);  // 2.9 -> 3.05 crosses 3.0
  CHECK_FALSE(q.shear_on());
}

TEST_CASE("after_kt: an angle crossing counts only once the start-up is over", "[protocol]") {
  // A tumbling inclination theta = pi/4 - 0.5 kt, wrapped into (-pi/2, pi/2]: it crosses
  // pi/6 first at kt = (pi/4 - pi/6)/0.5 = 0.524 (the start-up, Sec. 4.1.2's capsule has not
  // tumbled yet), then once a period pi/0.5 = 6.283 later: kt = 6.807, 13.09, ...
  auto wrap = [](double th) { return th - std::numbers::pi * std::floor((th + std::numbers::pi / 2) / std::numbers::pi); };
  auto stop_at = [&](double after_kt) {
    json shear = {{"until", "theta"}, {"value", std::numbers::pi / 6}};
    if (after_kt > 0) shear["after_kt"] = after_kt;
    Protocol p(scene_with({{"shear", shear}, {"recover", {{"until", "time"}, {"kt", 1}}}}));
    for (int i = 0; p.shear_on() && i < 1000; ++i) p.observe(0.05 * i, 0.3, wrap(std::numbers::pi / 4 - 0.025 * i), 0.0);
    return p.markers()["t_stop"];
  };
  CHECK(stop_at(0) == Approx(0.55).margin(1e-9));   // first row at or past 0.524
  CHECK(stop_at(5) == Approx(6.85).margin(1e-9));   // first row at or past 6.807
  CHECK(stop_at(7) == Approx(13.10).margin(1e-9));  // first row at or past 13.09
}

TEST_CASE("after_kt is refused where it cannot apply, and written only when set", "[protocol]") {
  json j = {{"dim", 2}, {"shape", "circle"}, {"Ca", 0.05}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
            {"protocol", {{"shear", {{"until", "theta"}, {"value", 0.5}, {"after_kt", 60}}},
                          {"recover", {{"until", "time"}, {"kt", 1}}}}}};
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"), Catch::Contains("protocol.shear.after_kt"));
  j["protocol"]["shear"]["after_kt"] = 20;
  CHECK(Scene::from_json(j, "t.json").to_json()["protocol"]["shear"]["after_kt"] == 20.0);
  j["protocol"]["shear"].erase("after_kt");
  CHECK(!Scene::from_json(j, "t.json").to_json()["protocol"]["shear"].contains("after_kt"));
  j["protocol"]["shear"] = {{"until", "steady"}, {"after_kt", 5}};
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"), Catch::Contains("after_kt"));
}

TEST_CASE("max_kt ends a phase whose condition never comes, and says so", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "steady"}, {"max_kt", 3}}}, {"recover", {{"until", "settled"}, {"max_kt", 2}}}}));
  drive(p, [](double t, bool) { return 0.1 * std::sin(3 * t); });
  CHECK(p.finished());
  CHECK(p.markers()["t_stop"] == Approx(3.0));
  CHECK(p.markers()["t_end"] == Approx(5.0));
  CHECK_THAT(p.phase_note(), Catch::Contains("max_kt = 3"));
}

TEST_CASE("oscillatory shear follows sin(pi t / T) (Sec. 5.2.2)", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "time"}, {"kt", 8}, {"oscillatory_period_kt", 4}}},
                         {"recover", {{"until", "time"}, {"kt", 1}}}}));
  CHECK(p.shear_factor(2.0) == Approx(1.0));
  CHECK(p.shear_factor(6.0) == Approx(-1.0));
}

TEST_CASE("a protocol restored from its state continues exactly as the original", "[protocol][restart]") {
  const json spec = {{"shear", {{"until", "steady"}, {"window_kt", 1}, {"tolerance", 1e-3}, {"max_kt", 30}}},
                     {"recover", {{"until", "settled"}, {"window_kt", 1}, {"tolerance", 1e-3}, {"max_kt", 30}}}};
  Protocol a(scene_with(spec)), b(scene_with(spec));
  auto D = [](double t, bool on) { return on ? 0.3 * (1 - std::exp(-t)) : 0.3 * std::exp(-(t - 8)); };
  double kt = 0;
  int i = 0;
  for (; kt < 5; ++i) kt = i * 0.05, a.observe(kt, D(kt, a.shear_on()), 0.1 * i, 0.2 * i);
  b.restore(a.state());
  for (; !a.finished(); ++i) {
    kt = i * 0.05;
    a.observe(kt, D(kt, a.shear_on()), 0.1 * i, 0.2 * i);
    b.observe(kt, D(kt, b.shear_on()), 0.1 * i, 0.2 * i);
    REQUIRE(a.shear_on() == b.shear_on());
  }
  CHECK(b.finished());
  const auto ma = a.markers(), mb = b.markers();
  for (const auto& [k, v] : ma) CHECK(std::memcmp(&v, &mb.at(k), sizeof v) == 0);
  CHECK(a.phase_note() == b.phase_note());
}

TEST_CASE("the protocol's outlook names the phase and when it ends at the latest", "[protocol]") {
  Protocol p(scene_with({{"shear", {{"until", "steady"}, {"max_kt", 20}}}, {"recover", {{"until", "time"}, {"kt", 3}}}}));
  auto o = p.outlook();
  CHECK(o.phase == "shear");
  CHECK(o.phase_end_kt == 20);
  CHECK(o.phase_end_is_cap);
  CHECK(o.member_end_kt == 23);
  Protocol q(scene_with({{"shear", {{"until", "time"}, {"kt", 2}}}, {"recover", {{"until", "time"}, {"kt", 3}}}}));
  for (int i = 0; i <= 40; ++i) q.observe(i * 0.05, 0.1, 0.0, 0.0);
  o = q.outlook();
  CHECK(o.phase == "recover");
  CHECK(o.phase_end_kt == Approx(5.0));
  CHECK(!o.phase_end_is_cap);
}

TEST_CASE("a stretch protocol loads instead of shearing, watches D_axial and releases when it is steady", "[protocol][stretch]") {
  json j = {{"dim", 3}, {"shape", "sphere"}, {"Ca", 0.05}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
            {"protocol", {{"stretch", {{"force", 0.1}, {"until", "steady"}, {"tolerance", 1e-3}, {"window_kt", 1.0}}},
                          {"recover", {{"until", "time"}, {"kt", 2}}}}}};
  Protocol p(Scene::from_json(j, "test"));
  CHECK(p.watched() == "D_axial");
  CHECK(p.shear_factor(0.0) == 0.0);  // the walls stay at rest
  CHECK(p.load_on());
  CHECK(!p.shear_on());
  CHECK(p.outlook().phase == "stretch");
  drive(p, [&](double t, bool) { return p.load_on() ? 2.0 + 0.2 * (1 - std::exp(-t)) : 2.0; });
  const auto m = p.markers();
  // Steady when the range over the last kt, 0.2 e^-t (e - 1), is below 1e-3: from t = 5.840, the row at 5.85.
  CHECK(m.at("t_stop") == Approx(5.85).margin(1e-9));
  CHECK(m.at("t_end") == Approx(m.at("t_stop") + 2.0).margin(1e-9));
  CHECK(p.phase_note().rfind("stretch stopped when D_axial was steady", 0) == 0);
  CHECK(!p.load_on());
}
