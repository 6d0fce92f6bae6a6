// Members against published curves D(kt) (block "published"; Figs. 7 and 9 compare the
// solver with Ramanujan and Pozrikidis 1998 this way): per curve and matching member, D_xy and
// D_extent interpolated at the curve's points during the shear, their bias and largest
// difference against the digitising error, and the last point side by side.
// published/published.md/.csv/.tex, fits.json "published", figure "published".
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "analysis/report/published_curves.hpp"
#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

struct Differences {
  std::size_t points = 0;
  double bias = k_nan, max_abs = k_nan, rms = k_nan;
};

// member - curve at the curve's points that lie in [begin, end].
Differences differences(const PublishedCurve& c, const std::vector<double>& kt, const std::vector<double>& D,
                        double begin, double end) {
  Differences d;
  double sum = 0, sum2 = 0, largest = 0;
  for (std::size_t i = 0; i < c.kt.size(); ++i) {
    if (c.kt[i] < begin || c.kt[i] > end) continue;
    const double m = interpolate_series(kt, D, c.kt[i]);
    if (!std::isfinite(m)) continue;
    const double diff = m - c.D[i];
    sum += diff;
    sum2 += diff * diff;
    largest = std::max(largest, std::abs(diff));
    ++d.points;
  }
  if (d.points == 0) return d;
  d.bias = sum / static_cast<double>(d.points);
  d.rms = std::sqrt(sum2 / static_cast<double>(d.points));
  d.max_abs = largest;
  return d;
}

bool matches(const DistinctMember& dm, const PublishedSpec& spec) {
  if (!spec.case_name.empty() &&
      std::find(dm.cases.begin(), dm.cases.end(), spec.case_name) == dm.cases.end())
    return false;
  for (const auto& [name, value] : spec.where) {
    const double v = parameter(*dm.member, name);
    if (!std::isfinite(v) || std::abs(v - value) > 1e-9 * std::max(1.0, std::abs(value))) return false;
  }
  return true;
}

std::string where_text(const PublishedSpec& spec) {
  std::string s = spec.case_name.empty() ? "" : "case " + spec.case_name;
  for (const auto& [name, value] : spec.where) s += (s.empty() ? "" : ", ") + name + " = " + format_number(value);
  return s.empty() ? "every member" : s;
}

// A complete member against a curve over the member's shear (the curves are shear from rest:
// the member's recovery is not theirs).
struct Comparison {
  double begin = k_nan, end = k_nan;
  Differences dxy, dext;
  bool has_extent = false;
  double kt_last = k_nan, d_curve = k_nan, d_xy = k_nan, d_ext = k_nan;  // at the last curve point the member reaches
  std::string note, within;
};

Comparison compare(const PublishedCurve& curve, const MemberAnalysis& m) {
  Comparison c;
  const auto stop = m.markers.find("t_stop");
  c.end = std::min(m.kt.back(), stop != m.markers.end() && std::isfinite(stop->second) ? stop->second : m.kt.back());
  c.begin = m.kt.front();
  c.dxy = differences(curve, m.kt, m.D, c.begin, c.end);
  c.has_extent = m.D_extent.size() == m.kt.size();
  if (c.has_extent) c.dext = differences(curve, m.kt, m.D_extent, c.begin, c.end);
  for (std::size_t i = curve.kt.size(); i-- > 0;)
    if (curve.kt[i] <= c.end && curve.kt[i] >= c.begin) {
      c.kt_last = curve.kt[i];
      c.d_curve = curve.D[i];
      break;
    }
  c.d_xy = interpolate_series(m.kt, m.D, c.kt_last);
  c.d_ext = c.has_extent ? interpolate_series(m.kt, m.D_extent, c.kt_last) : k_nan;
  const double end = c.end;
  const std::size_t beyond = static_cast<std::size_t>(
      std::count_if(curve.kt.begin(), curve.kt.end(), [end](double x) { return x > end; }));
  if (beyond > 0)
    c.note = std::to_string(beyond) + (beyond == 1 ? " curve point" : " curve points") +
             " after the member's shear ended at kt = " + format_number(end) +
             " (curve to kt = " + format_number(curve.kt.back()) + ")";
  if (c.dxy.points > 0) {
    c.within = c.dxy.max_abs <= curve.digitising_error ? "yes" : "no";
    if (c.has_extent && c.dext.points > 0 && c.within == "no" && c.dext.max_abs <= curve.digitising_error)
      c.within = "D_extent only";
  }
  return c;
}

// The comparison as a row of the table and as its fits.json entry `e`.
void record(const PublishedCurve& curve, const MemberAnalysis& m, const Comparison& c, Table& t, nlohmann::json& e) {
  t.rows.push_back({curve.name, curve.source, m.ref.slug,
                    c.dxy.points ? format_number(c.begin) + " - " + format_number(std::min(c.end, curve.kt.back())) : "",
                    std::to_string(c.dxy.points), format_number(c.dxy.bias), format_number(c.dxy.max_abs),
                    format_number(c.dext.max_abs), format_number(c.kt_last), format_number(c.d_curve),
                    format_number(c.d_xy), format_number(c.d_ext), format_number(c.d_xy / c.d_curve - 1.0), c.within,
                    c.note});
  e["points"] = c.dxy.points;
  e["bias_D_xy"] = json_number(c.dxy.bias);
  e["max_abs_D_xy"] = json_number(c.dxy.max_abs);
  e["rms_D_xy"] = json_number(c.dxy.rms);
  e["max_abs_D_extent"] = json_number(c.dext.max_abs);
  e["kt_last"] = json_number(c.kt_last);
  e["D_curve_last"] = json_number(c.d_curve);
  e["D_xy_last"] = json_number(c.d_xy);
  e["D_extent_last"] = json_number(c.d_ext);
  e["within_digitising_error"] = c.within;
  if (!c.note.empty()) e["note"] = c.note;
}

// Every member the spec names against its curve: rows of the table, fits.json entries, and the
// curve's figure with the members' series.
nlohmann::json compare_curve(const PublishedSpec& spec, const std::vector<DistinctMember>& members, Table& t,
                             nlohmann::json& entries) {
  const PublishedCurve curve = published_curve(spec.curve);
  nlohmann::json fig = {{"curve", curve.name}, {"ref_kt", curve.kt}, {"ref_D", curve.D},
                        {"members", nlohmann::json::array()}};
  bool any = false;
  for (const auto& dm : members) {
    if (!matches(dm, spec)) continue;
    any = true;
    const MemberAnalysis& m = *dm.member;
    nlohmann::json e = {{"curve", curve.name}, {"source", curve.source}, {"member", m.ref.slug},
                        {"cases", dm.cases}, {"digitising_error", curve.digitising_error}};
    if (m.status != "complete" || m.kt.empty() || m.D.size() != m.kt.size()) {
      const std::string why = m.status != "complete" ? incomplete_reason(m) : "member has no kt or D_xy series";
      e["reason"] = why;
      t.rows.push_back({curve.name, curve.source, m.ref.slug, "", "", "", "", "", "", "", "", "", "", "", why});
      entries.push_back(e);
      continue;
    }
    const Comparison c = compare(curve, m);
    record(curve, m, c, t, e);
    entries.push_back(e);
    nlohmann::json fm = {{"label", m.ref.slug}, {"kt", m.kt}, {"D_xy", m.D}, {"end", c.end}};
    if (c.has_extent) fm["D_extent"] = m.D_extent;
    fig["members"].push_back(fm);
  }
  if (!any) {
    const std::string why = "no member with " + where_text(spec);
    t.rows.push_back({curve.name, curve.source, "", "", "", "", "", "", "", "", "", "", "", "", why});
    entries.push_back({{"curve", curve.name}, {"reason", why}});
  }
  return fig;
}

class PublishedSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    if (context.block.published.empty()) return;
    Table t;
    t.title = "Members against published curves D(kt) during the shear: member - curve at the curve's points "
              "(linear interpolation of the member's series); the curves' digitising error is about +-0.005";
    t.header = {"curve", "source", "member", "kt compared", "points", "bias D_xy", "max |dD_xy|", "max |dD_extent|",
                "kt last", "D curve", "D_xy", "D_extent", "D_xy / curve - 1", "within digitising error", "note"};
    nlohmann::json entries = nlohmann::json::array();
    nlohmann::json figure = nlohmann::json::array();
    const auto members = distinct_members(context.members);
    for (const auto& spec : context.block.published) figure.push_back(compare_curve(spec, members, t, entries));
    fs::create_directories(out_dir / "published");
    outputs.write_table(t, out_dir / "published", "published");
    outputs.fits["published"] = entries;
    outputs.figure_data["published"] = figure;
  }
};

}  // namespace

std::unique_ptr<ReportSection> published_section() { return std::make_unique<PublishedSection>(); }

}  // namespace capsule::analysis
