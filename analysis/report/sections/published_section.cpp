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
    for (const auto& spec : context.block.published) {
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
        // The shear only: the curves are shear from rest (the member's recovery is not theirs).
        const auto stop = m.markers.find("t_stop");
        const double end = std::min(m.kt.back(), stop != m.markers.end() && std::isfinite(stop->second)
                                                     ? stop->second
                                                     : m.kt.back());
        const double begin = m.kt.front();
        const Differences dxy = differences(curve, m.kt, m.D, begin, end);
        const bool has_extent = m.D_extent.size() == m.kt.size();
        const Differences dext = has_extent ? differences(curve, m.kt, m.D_extent, begin, end) : Differences{};
        // The last curve point the member reaches.
        double kt_last = k_nan, d_curve = k_nan;
        for (std::size_t i = curve.kt.size(); i-- > 0;)
          if (curve.kt[i] <= end && curve.kt[i] >= begin) {
            kt_last = curve.kt[i];
            d_curve = curve.D[i];
            break;
          }
        const double d_xy = interpolate_series(m.kt, m.D, kt_last);
        const double d_ext = has_extent ? interpolate_series(m.kt, m.D_extent, kt_last) : k_nan;
        std::string note;
        const std::size_t beyond = static_cast<std::size_t>(
            std::count_if(curve.kt.begin(), curve.kt.end(), [end](double x) { return x > end; }));
        if (beyond > 0)
          note = std::to_string(beyond) + (beyond == 1 ? " curve point" : " curve points") +
                 " after the member's shear ended at kt = " +
                 format_number(end) + " (curve to kt = " + format_number(curve.kt.back()) + ")";
        std::string within;
        if (dxy.points > 0) {
          within = dxy.max_abs <= curve.digitising_error ? "yes" : "no";
          if (has_extent && dext.points > 0 && within == "no" && dext.max_abs <= curve.digitising_error)
            within = "D_extent only";
        }
        t.rows.push_back({curve.name, curve.source, m.ref.slug,
                          dxy.points ? format_number(begin) + " - " + format_number(std::min(end, curve.kt.back())) : "",
                          std::to_string(dxy.points), format_number(dxy.bias), format_number(dxy.max_abs),
                          format_number(dext.max_abs), format_number(kt_last), format_number(d_curve),
                          format_number(d_xy), format_number(d_ext), format_number(d_xy / d_curve - 1.0), within,
                          note});
        e["points"] = dxy.points;
        e["bias_D_xy"] = json_number(dxy.bias);
        e["max_abs_D_xy"] = json_number(dxy.max_abs);
        e["rms_D_xy"] = json_number(dxy.rms);
        e["max_abs_D_extent"] = json_number(dext.max_abs);
        e["kt_last"] = json_number(kt_last);
        e["D_curve_last"] = json_number(d_curve);
        e["D_xy_last"] = json_number(d_xy);
        e["D_extent_last"] = json_number(d_ext);
        e["within_digitising_error"] = within;
        if (!note.empty()) e["note"] = note;
        entries.push_back(e);
        nlohmann::json fm = {{"label", m.ref.slug}, {"kt", m.kt}, {"D_xy", m.D}, {"end", end}};
        if (has_extent) fm["D_extent"] = m.D_extent;
        fig["members"].push_back(fm);
      }
      if (!any) {
        const std::string why = "no member with " + where_text(spec);
        t.rows.push_back({curve.name, curve.source, "", "", "", "", "", "", "", "", "", "", "", "", why});
        entries.push_back({{"curve", curve.name}, {"reason", why}});
      }
      figure.push_back(fig);
    }
    fs::create_directories(out_dir / "published");
    outputs.write_table(t, out_dir / "published", "published");
    outputs.fits["published"] = entries;
    outputs.figure_data["published"] = figure;
  }
};

}  // namespace

std::unique_ptr<ReportSection> published_section() { return std::make_unique<PublishedSection>(); }

}  // namespace capsule::analysis
