// The claims of the dissertation's Secs. 5.2.1-5.2.2 on the shape of the power-law capsule's D_xy
// over time: a settled ellipsoid in shear, the same initial deformation as Kelvin-Voigt in
// oscillatory shear; each a rule with a stated numeric criterion (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/claims/support.hpp"
#include "analysis/dissertation/document_links.hpp"

namespace capsule::analysis::claims {

namespace {

// The largest D_xy of a member between kt from and to, and when.
struct Peak {
  double D = -std::numeric_limits<double>::infinity(), kt = k_nan;
};
Peak peak_between(const io::MemberData& d, double from, double to) {
  Peak p;
  const auto& kt = d.series.at("kt");
  const auto& D = d.series.at("D_xy");
  for (std::size_t i = 0; i < kt.size() && i < D.size(); ++i)
    if (kt[i] >= from - 1e-9 && kt[i] < to - 1e-9 && D[i] > p.D) p.D = D[i], p.kt = kt[i];
  return p;
}

// One member of each case of ch5_oscillatory (the finest level), or why not.
std::vector<ShearMember> oscillatory_members(const DissertationResults& res, const DissertationCampaign& c, std::string& why) {
  std::vector<ShearMember> out;
  for (const char* name : {"kv", "powerlaw_n1", "powerlaw_n064"}) {
    auto ms = shear_members(res, c, name, why);
    if (ms.empty()) part_missing(why, std::string("no case ") + name + " member with a member file");
    else out.push_back(std::move(ms.front()));
  }
  return out;
}


// How a sheared member settles after its first maximum of D_xy: how far it then dips below its
// value at the stop (the undershoot of a damped oscillation, relative to D_stop) and when it last
// lies outside `band` (relative) of D_stop (its settling time). nullopt, with why, without a
// maximum before the stop (a monotone rise: no undershoot, no oscillation).
struct Settling {
  double D_stop = k_nan, undershoot = 0.0, t_settle = k_nan, t_stop = k_nan;
  bool rose_monotonically = false;
};
Settling settling(const io::MemberData& d, double band) {
  const auto& kt = d.series.at("kt");
  const auto& D = d.series.at("D_xy");
  const std::size_t n = std::min(kt.size(), D.size());
  Settling s;
  s.t_stop = std::isfinite(marker(d, "t_stop")) ? marker(d, "t_stop") : (n ? kt[n - 1] : k_nan);
  std::size_t last = 0;
  while (last + 1 < n && kt[last + 1] <= s.t_stop + 1e-9) ++last;
  s.D_stop = n ? D[last] : k_nan;
  std::size_t peak = 0;
  for (std::size_t i = 1; i < last && !peak; ++i)
    if (D[i] >= D[i - 1] && D[i] > D[i + 1]) peak = i;
  if (!peak) {
    s.rose_monotonically = true;
    s.t_settle = k_nan;
    return s;
  }
  double lowest = D[peak];
  s.t_settle = kt[peak];
  for (std::size_t i = peak; i <= last; ++i) {
    lowest = std::min(lowest, D[i]);
    if (std::abs(D[i] - s.D_stop) > band * s.D_stop) s.t_settle = kt[i];
  }
  s.undershoot = std::max(0.0, (s.D_stop - lowest) / s.D_stop);
  return s;
}

std::string settling_text(const Settling& s) {
  return s.rose_monotonically ? std::string("rises without a maximum")
                              : "undershoot " + num(s.undershoot) + ", settled (within 2 %) from kt " + num(s.t_settle) +
                                    " (stop " + num(s.t_stop) + ")";
}

// The interior maxima of D_xy (kt, D), in time order.
std::vector<std::pair<double, double>> maxima(const io::MemberData& d) {
  const auto& kt = d.series.at("kt");
  const auto& D = d.series.at("D_xy");
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 1; i + 1 < std::min(kt.size(), D.size()); ++i)
    if (D[i] > D[i - 1] && D[i] >= D[i + 1]) out.push_back({kt[i], D[i]});
  return out;
}

// The last maximum of D_xy in each of the last two half-waves of the shear of an oscillatory member (the
// flow reverses every T, the scene's oscillatory_period_kt); nullopt, with why, when either half-wave has none.
struct LastPeaks {
  double T = k_nan;
  std::pair<double, double> previous{k_nan, k_nan}, last{k_nan, k_nan};  // (kt, D_xy)
};
std::optional<LastPeaks> last_peaks(const ShearMember& m, std::string& why) {
  LastPeaks p;
  p.T = scene_value(*m.data, "/protocol/shear/oscillatory_period_kt");
  const auto& kt = m.data->series.at("kt");
  if (!(p.T > 0.0) || kt.empty()) {
    part_missing(why, m.member->slug + ": no oscillatory_period_kt in its scene");
    return std::nullopt;
  }
  const double end = std::isfinite(marker(*m.data, "t_stop")) ? std::min(marker(*m.data, "t_stop"), kt.back()) : kt.back();
  // The shear ends at a whole number of half-waves, up to the time step (kt 20.02 for 20).
  const int last_wave = static_cast<int>(std::lround(end / p.T)) - 1;
  for (const auto& [t, D] : maxima(*m.data)) {
    const int wave = static_cast<int>(std::floor(t / p.T));
    if (wave == last_wave) p.last = {t, D};
    else if (wave == last_wave - 1) p.previous = {t, D};
  }
  if (std::isnan(p.last.first) || std::isnan(p.previous.first)) {
    part_missing(why, m.member->slug + ": no maximum of D_xy in each of the last two half-waves");
    return std::nullopt;
  }
  return p;
}
}  // namespace

// Sec. 5.2.1: "The spherical capsule is deformed to an (eventually) stable ellipsoidal shape,
// described by an approximately constant D_xy."
ClaimResult claim_5_2_settled(const DissertationResults& res) {
  constexpr double bound = 0.01;  // the bound "4.2 C steady" takes for a D_xy without swing
  auto [r, c] = open_claim(res, "5.2.1 settled", {{"bound", num(bound)}});
  if (!c) return r;
  std::string why;
  const auto ms = shear_members(res, *c, "n", why);
  if (ms.size() < 3) {
    r.measured = "cannot tell (members missing): " + std::to_string(ms.size()) + " members of case n, need 3" +
                 (why.empty() ? std::string("") : " (" + why + ")");
    return r;
  }
  Parts parts;
  for (const auto& m : ms) {
    const auto& kt = m.data->series.at("kt");
    const auto& D = m.data->series.at("D_xy");
    const double t_stop = std::isfinite(marker(*m.data, "t_stop")) ? marker(*m.data, "t_stop") : kt.back();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < kt.size() && i < D.size(); ++i)
      if (kt[i] >= 0.75 * t_stop && kt[i] <= t_stop) lo = std::min(lo, D[i]), hi = std::max(hi, D[i]);
    parts.add(hi - lo <= bound, "n " + num(scene_value(*m.data, "/power_law/n")) + ": D_xy " + num(lo) + " to " + num(hi) +
                                    " over kt " + num(0.75 * t_stop) + "-" + num(t_stop));
  }
  return parts.finish(r);
}

// Sec. 5.2.2: "Once again, the initial deformation measured by the Taylor deformation parameter agrees
// very well for all three capsules."
ClaimResult claim_5_2_2_initial(const DissertationResults& res) {
  constexpr double bound = 0.1;  // the bound "5.2.1 initial" takes for "nearly identical"
  auto [r, c] = open_claim(res, "5.2.2 initial", {{"bound", num(bound)}});
  if (!c) return r;
  std::string why;
  const auto ms = oscillatory_members(res, *c, why);
  if (ms.size() < 3) {
    r.measured = "cannot tell (members missing): " + why;
    return r;
  }
  std::vector<double> first;
  std::string text;
  for (const auto& m : ms) {
    const double T = scene_value(*m.data, "/protocol/shear/oscillatory_period_kt");
    first.push_back(peak_between(*m.data, 0.0, T).D);
    append_listed(text, m.member->case_name + " " + num(first.back()));
  }
  const double spread = relative_spread(first);
  set(r, spread <= bound, "peak D_xy in the first period: " + text + "; spread " + num(spread));
  return r;
}


// Sec. 5.2.1: "decreasing n changes the capsule's behaviour from stationary tank-treading to undergoing
// damped oscillations prior to tank-treading. For these cases with small n, the Taylor deformation
// parameter oscillates before reaching equilibrium and these oscillations decay more slowly for smaller
// values of n."
ClaimResult claim_5_2_1_damped(const DissertationResults& res) {
  constexpr double bound = 0.02;  // "~" of "3.1 overshoot"
  auto [r, c] = open_claim(res, "5.2.1 damped", {{"bound", num(bound)}});
  if (!c) return r;
  std::string why;
  auto ms = shear_members(res, *c, "n", why);
  std::vector<std::pair<double, Settling>> by_n;
  for (const auto& m : ms) {
    const double n = parameter(*m.member, "power_law.n");
    if (!std::isnan(n)) by_n.push_back({n, settling(*m.data, bound)});
  }
  if (by_n.size() < 3 || !why.empty()) {
    r.measured = "cannot tell (members missing): " + std::to_string(by_n.size()) + " members of case n, need 3" +
                 (why.empty() ? std::string("") : " (" + why + ")");
    return r;
  }
  std::sort(by_n.begin(), by_n.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const auto oscillates = [&](const Settling& s) { return !s.rose_monotonically && s.undershoot > bound; };
  bool ok = !oscillates(by_n.front().second) && oscillates(by_n.back().second);
  std::string text, slower;
  double previous = k_nan;
  for (const auto& [n, s] : by_n) {
    append_listed(text, "n " + num(n) + ": " + settling_text(s));
    if (!oscillates(s)) continue;
    if (!std::isnan(previous) && !(s.t_settle > previous)) slower = "n " + num(n) + " settles no later than the n above it";
    previous = s.t_settle;
  }
  ok = ok && slower.empty();
  set(r, ok, text + (slower.empty() ? std::string("") : "; " + slower));
  return r;
}

// Sec. 5.2.1 (Figs. 62-63): "the general dynamic behaviour between the models remains strikingly similar,
// with both models transitioning from tank-treading to damped oscillations for larger mu_s and K".
ClaimResult claim_5_2_1_both_oscillate(const DissertationResults& res) {
  constexpr double bound = 0.02;
  auto [r, c] = open_claim(res, "5.2.1 both oscillate", {{"bound", num(bound)}});
  if (!c) return r;
  Parts parts;
  for (const auto& [case_name, x] : {std::pair<std::string, std::string>{"K", "power_law.K"}, {"kv", "eta"}}) {
    std::string why;
    auto ms = shear_members(res, *c, case_name, why);
    std::sort(ms.begin(), ms.end(), [&](const ShearMember& a, const ShearMember& b) {
      return parameter(*a.member, x) < parameter(*b.member, x);
    });
    if (ms.size() < 2 || !why.empty()) {
      part_missing(parts.why, "case " + case_name + ": " + std::to_string(ms.size()) + " members, need 2" +
                                  (why.empty() ? std::string("") : " (" + why + ")"));
      continue;
    }
    const Settling low = settling(*ms.front().data, bound), high = settling(*ms.back().data, bound);
    const auto oscillates = [&](const Settling& s) { return !s.rose_monotonically && s.undershoot > bound; };
    parts.add(!oscillates(low) && oscillates(high),
              case_name + " " + num(parameter(*ms.front().member, x)) + ": " + settling_text(low) + "; " + case_name + " " +
                  num(parameter(*ms.back().member, x)) + ": " + settling_text(high));
  }
  return parts.finish(r);
}

// Sec. 5.2.1 (Fig. 65): "increasing K produces the same results for Newtonian (n = 1) membrane viscosity
// in the power law model as are observed for K = 0.01 mu_a and the non-Newtonian n = 0.64".
ClaimResult claim_5_2_1_n_K(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "5.2.1 n and K", {});
  if (!c) return r;
  std::string why;
  std::vector<std::pair<double, double>> K_D;  // n = 1 members: (K, D_stop)
  for (const DissertationMember* m : c->in_case("")) {
    if (parameter(*m, "power_law.n") != 1.0 || !(parameter(*m, "power_law.K") > 0.0)) continue;
    std::string w;
    if (auto s = shear_member(res, *m, w)) K_D.push_back({parameter(*m, "power_law.K"), s->D_stop});
    else part_missing(why, w);
  }
  std::sort(K_D.begin(), K_D.end());
  K_D.erase(std::unique(K_D.begin(), K_D.end(), [](const auto& a, const auto& b) { return a.first == b.first; }), K_D.end());
  if (K_D.size() < 3) {
    r.measured = "cannot tell (no campaign): " + std::to_string(K_D.size()) +
                 " values of K at n = 1 (Fig. 65's sweep), need 3; no shipped campaign sweeps K at n = 1" +
                 (why.empty() ? std::string("") : " (" + why + ")");
    return r;
  }
  bool falls = true;
  std::string text;
  for (std::size_t i = 0; i < K_D.size(); ++i) {
    if (i && !(K_D[i].second < K_D[i - 1].second)) falls = false;
    append_listed(text, "K " + num(K_D[i].first) + ": " + num(K_D[i].second));
  }
  set(r, falls, "n = 1, D_xy at the stop: " + text);
  return r;
}

// Sec. 5.2.2: "On a qualitative level, all three methods have equal responses to flows in both
// directions, after reaching equilibrium."
ClaimResult claim_5_2_2_directions(const DissertationResults& res) {
  constexpr double bound = 0.1;  // the bound "5.2.2 initial" takes for agreement in D_xy
  auto [r, c] = open_claim(res, "5.2.2 directions", {{"bound", num(bound)}});
  if (!c) return r;
  std::string why;
  const auto ms = oscillatory_members(res, *c, why);
  Parts parts;
  parts.why = why;
  for (const auto& m : ms) {
    const auto p = last_peaks(m, parts.why);
    if (!p) continue;
    const double d = std::abs(p->last.second - p->previous.second) / std::max(p->last.second, p->previous.second);
    parts.add(d <= bound, m.member->case_name + ": peak D_xy " + num(p->previous.second) + " (kt " + num(p->previous.first) +
                              ") and " + num(p->last.second) + " (kt " + num(p->last.first) + "), differing by " + num(d));
  }
  return parts.finish(r);
}

// Sec. 5.2.2: "Further, the three models stay approximately within phase."
ClaimResult claim_5_2_2_phase(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "5.2.2 phase", {});
  if (!c) return r;
  std::string why;
  const auto ms = oscillatory_members(res, *c, why);
  std::vector<std::pair<std::string, LastPeaks>> peaks;
  for (const auto& m : ms)
    if (auto p = last_peaks(m, why)) peaks.push_back({m.member->case_name, *p});
  if (peaks.size() < 3 || !why.empty()) {
    r.measured = "cannot tell (members missing): " + why;
    return r;
  }
  const LastPeaks& kv = peaks.front().second;  // case kv
  const double bound = kv.T / 4.0;
  double worst = 0.0;
  std::string text;
  for (std::size_t i = 1; i < peaks.size(); ++i) {
    const double lag_previous = peaks[i].second.previous.first - kv.previous.first,
                 lag_last = peaks[i].second.last.first - kv.last.first;
    worst = std::max({worst, std::abs(lag_previous), std::abs(lag_last)});
    append_listed(text, peaks[i].first + " peaks " + num(lag_previous) + " and " + num(lag_last) + " kt after kv's");
  }
  set(r, worst <= bound, text + " (kv at kt " + num(kv.previous.first) + " and " + num(kv.last.first) + "; bound T/4 = " + num(bound) + " kt)");
  return r;
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter5_shapes_claims() {
  return {once("5.2.1 settled", claim_5_2_settled), once("5.2.1 damped", claim_5_2_1_damped),
          once("5.2.1 both oscillate", claim_5_2_1_both_oscillate), once("5.2.1 n and K", claim_5_2_1_n_K),
          once("5.2.2 initial", claim_5_2_2_initial), once("5.2.2 directions", claim_5_2_2_directions),
          once("5.2.2 phase", claim_5_2_2_phase)};
}

}  // namespace capsule::analysis::claims
