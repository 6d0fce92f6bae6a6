#pragma once
// What every claim of the dissertation comparison is built from: a claim's text (claims.md) and
// campaign, the members of a case as a series of (parameter, fitted time), the checks that turn
// missing members into "cannot tell", and the members whose shear stop never came. Each chapter's claims are in
// chapter2.cpp ... chapter5.cpp beside this file, registered at the end of each (registry.hpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "analysis/report/report_context.hpp"
#include "analysis/report/resolution_ladder.hpp"
#include "analysis/report/scene_parameter.hpp"
#include "analysis/dissertation/table2_compare.hpp"
#include "analysis/dissertation/claim_texts.hpp"
#include "analysis/dissertation/claims.hpp"
#include "solver/scene/choices.hpp"

namespace capsule::analysis::claims {

// Undeformed D_xy of the biconcave capsules (docs/conventions.md "D_xy").
constexpr double k_D_biconcave_2d = 0.812;
constexpr double k_D_biconcave_3d = 0.51;

inline std::string num(double x) { return short_number(x); }

inline double parameter(const DissertationMember& m, const std::string& name) {
  const auto it = m.parameters.find(name);
  return it == m.parameters.end() ? k_nan : it->second;
}

struct Point {
  double x = 0.0, y = 0.0;
  const DissertationMember* member = nullptr;
};

// One fitted time of the members of a case against a parameter, sorted by x, with the
// members that gave no number and why.
struct Series {
  std::vector<Point> points;
  std::vector<std::string> gaps;
  std::vector<double> xs() const {
    std::vector<double> v;
    for (const auto& p : points) v.push_back(p.x);
    return v;
  }
  std::vector<double> ys() const {
    std::vector<double> v;
    for (const auto& p : points) v.push_back(p.y);
    return v;
  }
  std::string listing(const std::string& x_name) const {
    std::string s;
    for (const auto& p : points) s += (s.empty() ? "" : ", ") + x_name + " " + num(p.x) + ": " + num(p.y);
    return s;
  }
};

using Keep = std::function<bool(const DissertationMember&)>;
// Why a member cannot stand for the text's point ("" when it can): it is listed among the gaps.
using Skip = std::function<std::string(const DissertationMember&)>;

inline Series series(const DissertationCampaign& c, const std::string& case_name, const std::string& x, const std::string& column,
              const Keep& keep = {}, const Skip& skip = {}) {
  Series s;
  for (const DissertationMember* m : c.in_case(case_name)) {
    if (keep && !keep(*m)) continue;
    if (skip) {
      if (const std::string why = skip(*m); !why.empty()) {
        s.gaps.push_back(m->slug + ": " + why);
        continue;
      }
    }
    const double xv = parameter(*m, x);
    const ColumnValue v = column_value(m->fits, column);
    if (std::isnan(xv)) s.gaps.push_back(m->slug + ": " + x + " not recorded");
    else if (!v.parameter) s.gaps.push_back(m->slug + ": " + v.reason);
    else s.points.push_back({xv, v.parameter->value, m});
  }
  std::sort(s.points.begin(), s.points.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
  return s;
}

// The claim `key` of analysis/dissertation/claims.md, its {placeholders} filled from `fills`.
using Fills = std::map<std::string, std::string>;
inline ClaimResult claim(const std::string& key, const Fills& fills = {}) {
  const ClaimText& t = claim_text(key);
  ClaimResult r;
  r.key = key;
  r.section = fill_placeholders(t.section, fills, key);
  r.statement = fill_placeholders(t.statement, fills, key);
  r.campaign = fill_placeholders(t.tested_by, fills, key);
  r.criterion = fill_placeholders(t.criterion, fills, key);
  r.reread = fill_placeholders(t.reread, fills, key);
  return r;
}

inline std::string first_gaps(const std::vector<std::string>& gaps) {
  std::string s;
  for (std::size_t i = 0; i < gaps.size() && i < 3; ++i) s += (i ? "; " : "") + gaps[i];
  if (gaps.size() > 3) s += "; and " + std::to_string(gaps.size() - 3) + " more";
  return s;
}

// A member file's marker (/markers: D_max, D_stop, D_inf, t_stop, ...; docs/guide/member-files.md "Layout"); NaN when it is not recorded.
inline double marker(const io::MemberData& data, const std::string& name) {
  const auto it = data.markers.find(name);
  return it == data.markers.end() ? k_nan : it->second;
}

// False (and r.measured says why) when the campaign is not there.
inline bool have_campaign(ClaimResult& r, const DissertationCampaign& c) {
  if (c.found) return true;
  r.measured = "cannot tell: " + c.missing;
  return false;
}

// The claim `key` (claim()) and the campaign its "Tested by" names first; campaign is null, and
// r.measured says why, when that campaign was not shipped.
struct OpenClaim {
  ClaimResult r;
  const DissertationCampaign* campaign = nullptr;
};
inline OpenClaim open_claim(const DissertationResults& res, const std::string& key, const Fills& fills = {}) {
  OpenClaim o{claim(key, fills)};
  const std::string& tested_by = o.r.campaign;
  const DissertationCampaign& c = res.campaign(tested_by.substr(0, tested_by.find_first_of(" ,(")));
  if (have_campaign(o.r, c)) o.campaign = &c;
  return o;
}

// False (and r.measured says why) when the series has fewer than n points.
inline bool have_points(ClaimResult& r, const Series& s, std::size_t n, const std::string& what) {
  if (s.points.size() >= n) return true;
  r.measured = "cannot tell (members missing): " + std::to_string(s.points.size()) + " " + what + ", need " +
               std::to_string(n);
  if (!s.gaps.empty()) r.measured += " (" + first_gaps(s.gaps) + ")";
  return false;
}

inline void set(ClaimResult& r, bool ok, const std::string& measured) {
  r.verdict = ok ? Verdict::agrees : Verdict::differs;
  r.measured = measured;
}

// The claim's rule run on the text's own numbers (`numbers` names them and what the rule gives).
inline void set_text(ClaimResult& r, bool passes, const std::string& numbers) {
  r.text_passes = passes ? TextPasses::yes : TextPasses::no;
  r.text_numbers = numbers;
}

// Cannot tell for one of several parts: appends its reason and returns false.
inline bool part_missing(std::string& why, const std::string& reason) {
  why += (why.empty() ? "" : "; ") + reason;
  return false;
}

// A claim judged in several parts (one per case or per parameter): each part that has its
// members adds whether it holds and its numbers; each that lacks them adds the reason. The
// claim agrees when every part holds, and cannot tell while any part lacks members.
struct Parts {
  bool ok = true;
  std::string text, why;

  void add(bool holds, const std::string& numbers) {
    ok = ok && holds;
    text += (text.empty() ? "" : "; ") + numbers;
  }
  // False (and the reason kept) when the series has fewer than n points.
  bool enough(const Series& s, std::size_t n, const std::string& case_name, const std::string& x, const std::string& column) {
    if (s.points.size() >= n) return true;
    return part_missing(why, "case " + case_name + ": " + std::to_string(s.points.size()) + " values of " + x + " with " +
                                 bare_time(column) + ", need " + std::to_string(n) +
                                 (s.gaps.empty() ? "" : " (" + first_gaps(s.gaps) + ")"));
  }
  ClaimResult finish(ClaimResult r) const {
    if (!why.empty()) r.measured = "cannot tell (members missing): " + why + (text.empty() ? "" : "; so far " + text);
    else set(r, ok, text);
    return r;
  }
};

// The members left out of a series, as a suffix of its numbers.
inline std::string not_counted(const Series& s) {
  return s.gaps.empty() ? std::string("") : " [not counted: " + first_gaps(s.gaps) + "]";
}

// Both fitted times of a Chapter 3 member, k tau_s (86) and k tau_r (85), of one case against
// x: `judge` tells whether a time's series holds and writes its numbers. Cannot tell when
// either time has fewer than `needed` values of x.
using TimeJudge = std::function<bool(const Series&, std::string& numbers)>;
inline ClaimResult judge_both_times(ClaimResult r, const DissertationCampaign& c, const std::string& case_name,
                                    const std::string& x, std::size_t needed, const TimeJudge& judge) {
  bool ok = true;
  std::string text;
  for (const char* column : {"response.k_tau_s", "recovery.k_tau_r"}) {
    const Series s = series(c, case_name, x, column);
    if (!have_points(r, s, needed, "values of " + x + " with " + bare_time(column))) return r;
    std::string numbers;
    ok = judge(s, numbers) && ok;
    text += (text.empty() ? "" : "; ") + bare_time(column) + ": " + numbers + " (" + s.listing(x) + ")";
  }
  set(r, ok, text);
  return r;
}

// k tau_s and k tau_r of a case against x, with at least n values each; nullopt, r.measured saying
// why, otherwise.
struct BothTimes {
  Series response, recovery;
};
inline std::optional<BothTimes> both_times(ClaimResult& r, const DissertationCampaign& c, const std::string& case_name,
                                    const std::string& x, std::size_t n) {
  BothTimes t{series(c, case_name, x, "response.k_tau_s"), series(c, case_name, x, "recovery.k_tau_r")};
  if (!have_points(r, t.response, n, "values of " + x + " with k tau_s") ||
      !have_points(r, t.recovery, n, "values of " + x + " with k tau_r"))
    return std::nullopt;
  return t;
}

// How a member's shear was to end: on an inclination (until "theta"), a phase angle ("beta")
// or otherwise, with its target value, its cap max_kt and the t_stop it recorded. nullopt
// when the member file is not there to tell.
struct ShearStop {
  std::string until;
  double value = k_nan, cap = k_nan, t_stop = k_nan;
};
inline std::optional<ShearStop> shear_stop(const DissertationResults& res, const DissertationMember& m) {
  std::string why;
  const auto data = res.member_data(m, why, true);
  if (!data) return std::nullopt;
  const nlohmann::json& scene = data->attributes.contains("scene") ? data->attributes["scene"] : nlohmann::json();
  ShearStop s;
  if (scene.is_object() && scene.contains("protocol") && scene["protocol"].contains("shear")) {
    const nlohmann::json& shear = scene["protocol"]["shear"];
    s.until = shear.value("until", "");
    s.value = shear.value("value", k_nan);
    s.cap = shear.value("max_kt", k_nan);
  }
  const auto t = data->markers.find("t_stop");
  if (t != data->markers.end()) s.t_stop = t->second;
  return s;
}

// Secs. 4.1.1-4.1.2 fit recoveries that start at an inclination (theta = -pi/3, pi/6) or a
// phase angle (beta = 0.49): a member whose shear was to end there but ran to its cap max_kt
// recovers from another state and does not stand for the text's point. "" when its stop came,
// when the shear ends otherwise, or when the member file is not there to tell (its fits.json
// entry is judged as recorded).
inline std::string missed_stop(const ShearStop& s) {
  const auto until = choice_from_name<StopCondition>(s.until);
  if (until != StopCondition::theta && until != StopCondition::beta) return "";
  const std::string target = s.until + " = " + num(s.value);
  if (std::isnan(s.t_stop)) return "the shear never stopped (no t_stop); it was to stop at " + target;
  // The shear's last row lies within a step of its cap.
  if (!std::isnan(s.cap) && s.t_stop >= s.cap - 1e-6 * std::max(1.0, s.cap))
    return "the shear ran to its cap kt " + num(s.cap) + " without reaching " + target + ", so the recovery is not the text's";
  return "";
}
inline std::string missed_stop(const DissertationResults& res, const DissertationMember& m) {
  const auto s = shear_stop(res, m);
  return s ? missed_stop(*s) : "";
}

// Sec. 4.1.2's ensemble (Figs. 33-38) is of capsules stopped at theta = -pi/3 after a tumble; a
// member stopped at another inclination (theta = pi/6, Figs. 31-32) is reported beside it, not
// counted. Also leaves out a member whose stop never came (missed_stop).
inline std::string outside_tumbling_ensemble(const DissertationResults& res, const DissertationMember& m) {
  const auto s = shear_stop(res, m);  // the member file is read once for both checks
  if (!s) return "";
  if (std::string why = missed_stop(*s); !why.empty()) return why;
  if (choice_from_name<StopCondition>(s->until) == StopCondition::theta && std::abs(s->value + std::numbers::pi / 3) > 1e-6)
    return "stopped at theta = " + num(s->value) + ", not the ensemble's -pi/3 (reported, not counted)";
  return "";
}

// A 2D biconcave capsule that folds as it tumbles has a non-convex outline whose chords through
// the centroid, and so D_xy (37), jump as the chord along the major axis leaves a lobe: no
// smooth model fits such a series. Says so when D_xy jumps by more than 0.2 within one output
// interval at a rate above 5 per kt (ten times the fastest recovery the text reports: 0.4 of
// D_xy over 3 tau_R1 = 0.85 kt) in the first kt after the stop; "" otherwise.
inline std::string folded_note(const DissertationResults& res, const DissertationMember& m) {
  std::string why;
  const auto data = res.member_data(m, why, true);
  if (!data || !data->series.count("kt") || !data->series.count("D_xy") || !data->markers.count("t_stop")) return "";
  const auto& kt = data->series.at("kt");
  const auto& D = data->series.at("D_xy");
  const double t_stop = data->markers.at("t_stop");
  double jump = 0.0, at = k_nan, D_stop = k_nan;
  for (std::size_t i = 1; i < kt.size() && i < D.size(); ++i) {
    if (kt[i - 1] < t_stop - 1e-9 || kt[i] > t_stop + 1.0) continue;
    if (std::isnan(D_stop)) D_stop = D[i - 1];
    const double d = std::abs(D[i] - D[i - 1]), dt = kt[i] - kt[i - 1];
    if (d > 0.2 && dt > 0 && d / dt > 5.0 && d > jump) jump = d, at = kt[i] - t_stop;
  }
  if (jump == 0.0) return "";
  return " (D_xy " + num(D_stop) + " at the stop jumps by " + num(jump) + " at kt_stop + " + num(at) +
         ": a folded outline, whose chords (37) are discontinuous)";
}

inline Skip missed_stop_in(const DissertationResults& res) {
  return [&res](const DissertationMember& m) { return missed_stop(res, m); };
}
inline Skip outside_tumbling_ensemble_in(const DissertationResults& res) {
  return [&res](const DissertationMember& m) { return outside_tumbling_ensemble(res, m); };
}

inline bool is_refused_for_r2(const FitResult& f) { return !f.ok && f.reason.rfind("the model does not describe the data", 0) == 0; }

// ---------------------------------------------------------------- Chapter 3 (circle, sphere)

// A member file's scene value at a JSON pointer (power_law.K, ...), NaN when absent.
inline double scene_value(const io::MemberData& d, const std::string& pointer) {
  if (!d.attributes.contains("scene")) return k_nan;
  const SceneValue v = scene_parameter(d.attributes["scene"], "value", {{"value", pointer}});
  return v.found ? v.value : k_nan;
}

struct ShearMember {
  const DissertationMember* member = nullptr;
  std::optional<io::MemberData> data;
  double D_at_1 = k_nan, D_stop = k_nan;
};

// A member's D_xy(kt) and its stop time (the file read once); nullopt, with the reason added to
// `why` (part_missing), when the file or its series is missing or it has no row after the stop.
struct Curve {
  std::vector<double> kt, D;
  double t_stop = k_nan;
  std::size_t stop_row = 0;  // the first row at or after the stop
};
inline std::optional<Curve> member_curve(const DissertationResults& res, const DissertationMember& m, std::string& why,
                                         bool accept_unstable = false) {
  std::string reason;
  const auto data = res.member_data(m, reason, accept_unstable);
  if (!data || !data->series.count("kt") || !data->series.count("D_xy")) {
    part_missing(why, m.slug + ": " + (data ? "no kt / D_xy series" : reason));
    return std::nullopt;
  }
  Curve c{data->series.at("kt"), data->series.at("D_xy"), marker(*data, "t_stop")};
  while (c.stop_row < c.kt.size() && c.kt[c.stop_row] < c.t_stop) ++c.stop_row;
  if (c.stop_row + 2 >= c.kt.size()) {
    part_missing(why, m.slug + ": no recovery rows");
    return std::nullopt;
  }
  return c;
}

// Calls judge(member, curve) for each member of a case whose curve can be read and that `skip`
// does not leave out (the unreadable ones are added to parts.why); returns how many it judged.
template <class Judge>
std::size_t judge_curves(const DissertationResults& res, const DissertationCampaign& c, const std::string& case_name,
                         Parts& parts, bool accept_unstable, const Skip& skip, Judge judge) {
  std::size_t n = 0;
  for (const DissertationMember* m : c.in_case(case_name)) {
    if (skip && !skip(*m).empty()) continue;
    const auto curve = member_curve(res, *m, parts.why, accept_unstable);
    if (!curve) continue;
    ++n;
    judge(*m, *curve);
  }
  return n;
}

// A member's D_xy at kt 1 and at the stop (its last row without a t_stop); nullopt with `why`
// set when the file or its kt / D_xy series is missing.
inline std::optional<ShearMember> shear_member(const DissertationResults& res, const DissertationMember& m, std::string& why) {
  ShearMember s;
  s.member = &m;
  s.data = res.member_data(m, why);
  if (!s.data) return std::nullopt;
  const auto kt_it = s.data->series.find("kt"), d_it = s.data->series.find("D_xy");
  if (kt_it == s.data->series.end() || d_it == s.data->series.end()) {
    why = m.slug + ": no kt / D_xy series";
    return std::nullopt;
  }
  const auto& kt = kt_it->second;
  const auto& D = d_it->second;
  s.D_at_1 = interpolate_series(kt, D, 1.0);
  const double t_stop = s.data->markers.count("t_stop") ? s.data->markers.at("t_stop") : k_nan;
  s.D_stop = std::isfinite(t_stop) ? interpolate_series(kt, D, t_stop) : k_nan;
  if (std::isnan(s.D_stop) && !D.empty() && !std::isfinite(t_stop)) s.D_stop = D.back();
  return s;
}

inline std::vector<ShearMember> shear_members(const DissertationResults& res, const DissertationCampaign& c, const std::string& case_name,
                                       std::string& why) {
  std::vector<ShearMember> out;
  for (const DissertationMember* m : c.in_case(case_name)) {
    std::string w;
    if (auto s = shear_member(res, *m, w)) out.push_back(std::move(*s));
    else why += (why.empty() ? "" : "; ") + w;
  }
  return out;
}

// Exponent of a fitted time against one parameter of a case, judged against [lo, hi] (>= 3 values).
inline void exponent_part(Parts& parts, const DissertationCampaign& c, const std::string& case_name, const std::string& x,
                          const std::string& column, double lo, double hi, const Skip& skip, const Keep& keep = {}) {
  const Series s = series(c, case_name, x, column, keep, skip);
  if (!parts.enough(s, 3, case_name, x, column)) return;
  const LineFit f = fit_power(s.xs(), s.ys());
  parts.add(f.ok && f.slope >= lo && f.slope <= hi, x + " exponent " + num(f.slope) + " (" + s.listing(x) + ")" + not_counted(s));
}

// Sec. 5.2: "this power law method ... is independent of the Lagrangian grid" (Fig. 59).
// D_xy at the stop of a case's members differs by at most `bound` of its mean over `key`'s
// values (at least `needed` members): mesh independence (Figs. 10, 59), G independence (Fig. 12).
// `over` names the values in the criterion ("the mesh levels").
struct SpreadRule {
  std::string key, case_name, key_pointer, key_label;  // key: the claim in claims.md
  double bound = 0.0;
  std::size_t needed = 3;
};
inline ClaimResult judge_spread(const DissertationResults& res, const SpreadRule& rule) {
  auto [r, c] = open_claim(res, rule.key, {{"bound", num(rule.bound)}, {"needed", std::to_string(rule.needed)}});
  if (!c) return r;
  const auto& key_label = rule.key_label;
  std::string why;
  const auto ms = shear_members(res, *c, rule.case_name, why);
  if (ms.size() < rule.needed) {
    r.measured = "cannot tell (members missing): " + std::to_string(ms.size()) + " " + key_label +
                 " values with a member file, need " + std::to_string(rule.needed) +
                 (why.empty() ? std::string("") : " (" + why + ")");
    return r;
  }
  std::vector<double> D;
  std::string text;
  for (const auto& m : ms) {
    D.push_back(m.D_stop);
    text += (text.empty() ? "" : ", ") + key_label + " " + num(scene_value(*m.data, rule.key_pointer)) + ": " + num(m.D_stop);
  }
  const double spread = relative_spread(D);
  set(r, spread <= rule.bound, "spread " + num(spread) + "; D_xy at the stop: " + text);
  return r;
}

}  // namespace capsule::analysis::claims
