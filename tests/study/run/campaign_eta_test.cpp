// The running members' share of `study run`'s ETA: a member whose phase ends on a condition
// reports the time to its cap, an upper bound that made the campaign's ETA swing by hours
// (a settled recovery capped at kt 56 that ends near kt 9); the ETA expects it at its
// expected end instead, at its own measured speed.
#include <catch2/catch.hpp>

#include "study/run/campaign_progress.hpp"

using namespace capsule::study;

namespace {

// A 3D member: shear and recovery end on conditions, capped at kt 56 in all; expected at kt 9;
// 15 000 steps per kt.
CostEstimate capped_member() {
  CostEstimate c;
  c.kt_span = 56.0;
  c.kt_is_bound = true;
  c.expected_kt = 9.0;
  c.steps_per_kt = 15000.0;
  return c;
}

MemberProgress running_at(double kt, double steps_per_second, double eta_to_cap, bool cap) {
  MemberProgress p;
  p.present = true;
  p.kt = kt;
  p.steps_per_second = steps_per_second;
  p.eta_member_seconds = eta_to_cap;
  p.member_end_is_cap = cap;
  return p;
}

SpeedCalibration lengths_measured(double length_factor) {
  SpeedCalibration s;
  s.length_factor = length_factor;
  return s;
}

}  // namespace

TEST_CASE("a running member that ends on a condition is expected at its expected end, at its own speed", "[study]") {
  const CostEstimate c = capped_member();
  // At kt 6 of an expected 9, 300 steps/s: 3 kt x 15 000 / 300 = 150 s, not the 2500 s to the cap.
  CHECK(running_member_seconds_left(running_at(6.0, 300.0, 2500.0, true), c, lengths_measured(1.0), 999.0) == Approx(150.0));
  // Phases that ran 1.5x longer than expected so far stretch the expected end to kt 13.5.
  CHECK(running_member_seconds_left(running_at(6.0, 300.0, 2500.0, true), c, lengths_measured(1.5), 999.0) == Approx(375.0));
  // Never beyond the member's own time to its cap.
  CHECK(running_member_seconds_left(running_at(6.0, 300.0, 100.0, true), c, lengths_measured(1.0), 999.0) == Approx(100.0));
  CHECK(running_member_seconds_left(running_at(6.0, 300.0, 2500.0, true), c, lengths_measured(20.0), 999.0) == Approx(2500.0));
  // Past its expected end: nothing more is expected.
  CHECK(running_member_seconds_left(running_at(10.0, 300.0, 2500.0, true), c, lengths_measured(1.0), 999.0) == Approx(0.0));
}

TEST_CASE("a running member with a set end, or no measured speed yet, keeps its own ETA or the model's", "[study]") {
  const CostEstimate c = capped_member();
  // A set duration: its own ETA is exact.
  CHECK(running_member_seconds_left(running_at(6.0, 300.0, 700.0, false), c, lengths_measured(1.0), 999.0) == Approx(700.0));
  // No speed measured yet (the first progress line): its own ETA, or the model's where it has none.
  CHECK(running_member_seconds_left(running_at(0.0, 0.0, 2500.0, true), c, lengths_measured(1.0), 999.0) == Approx(2500.0));
  CHECK(running_member_seconds_left(running_at(0.0, 0.0, -1.0, true), c, lengths_measured(1.0), 999.0) == Approx(999.0));
}
