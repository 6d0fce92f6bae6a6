// Stability of a sweep (block "stability"): each member's status (complete / unstable at
// kt = X: reason / stopped), a map of statuses per pair of swept parameters, and the
// limits: per parameter, along each line of members that differ only in it, the values at
// which members went unstable. stability/members.*, stability/map_<p>_<q>.*, stability/limits.*.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "analysis/report/report_section.hpp"
#include "analysis/report/scene_parameter.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

struct StabilityStatus {
  std::string kind;    // complete | unstable | stopped | running | no result
  double kt = k_nan;   // kt of blow-up (unstable only)
  std::string reason;  // the status text after "unstable at kt = X: " / "stopped: ", or why no result
};

StabilityStatus classify(const std::string& status) {
  StabilityStatus s;
  const std::string unstable = "unstable at kt = ";
  if (status == "complete") {
    s.kind = "complete";
  } else if (status.rfind(unstable, 0) == 0) {
    s.kind = "unstable";
    const std::string rest = status.substr(unstable.size());
    char* end = nullptr;
    const double kt = std::strtod(rest.c_str(), &end);
    if (end != rest.c_str() && std::isfinite(kt)) s.kt = kt;
    const auto colon = rest.find(": ");
    s.reason = colon == std::string::npos ? rest : rest.substr(colon + 2);
  } else if (status.rfind("stopped", 0) == 0) {
    s.kind = "stopped";
    s.reason = status.size() > 9 ? status.substr(9) : "";
  } else if (status == "running") {
    s.kind = "running";
  } else {
    s.kind = "no result";
    s.reason = status;
  }
  return s;
}

// The status as a table cell: "complete", "unstable at kt = 2.5: NaN in the fluid", ...
std::string cell_text(const StabilityStatus& s) {
  if (s.kind == "unstable")
    return "unstable at kt = " + (std::isfinite(s.kt) ? format_number(s.kt) : std::string("?")) + ": " + s.reason;
  if (s.kind == "stopped") return "stopped: " + s.reason;
  if (s.kind == "no result") return "no result: " + s.reason;
  return s.kind;
}

struct Point {
  const MemberAnalysis* member;
  std::vector<std::string> cases;
  StabilityStatus status;
};

bool has(const Point& p, const std::string& name) { return p.member->parameters.count(name) > 0; }

std::string value_cell(const Point& p, const std::string& name) {
  return has(p, name) ? format_number(parameter(*p.member, name)) : "n/a: " + p.member->missing.at(name);
}

// Every member's status and swept values (stability/members.*, fits.json's "members" and "counts").
void write_members(const std::vector<Point>& points, const std::vector<std::string>& names, const fs::path& dir,
                   nlohmann::json& sj, ReportOutputs& outputs) {
  Table mt;
  mt.title = "Stability: status of every member (kt of blow-up for unstable members)";
  mt.header = {"case", "member"};
  mt.header.insert(mt.header.end(), names.begin(), names.end());
  mt.header.insert(mt.header.end(), {"status", "kt of blow-up", "reason"});
  std::map<std::string, int> counts;
  for (const auto& p : points) {
    std::vector<std::string> row{cases_label(p.cases), p.member->ref.slug};
    nlohmann::json pj{{"member", p.member->ref.slug}, {"cases", p.cases}, {"status", p.member->status},
                      {"kind", p.status.kind}, {"kt", json_number(p.status.kt)}, {"parameters", nlohmann::json::object()}};
    for (const auto& n : names) {
      row.push_back(value_cell(p, n));
      pj["parameters"][n] = json_number(parameter(*p.member, n));
    }
    row.insert(row.end(), {p.status.kind, std::isfinite(p.status.kt) ? format_number(p.status.kt) : "",
                           p.status.reason});
    mt.rows.push_back(row);
    sj["members"].push_back(pj);
    ++counts[p.status.kind];
  }
  if (points.empty()) mt.rows.push_back(std::vector<std::string>(mt.header.size(), ""));
  if (points.empty()) mt.rows.back()[0] = "(no members)";
  outputs.write_table(mt, dir, "members");
  sj["counts"] = counts;
}

// One cell of a map: the statuses of the members at (x, y), each with its count; each member
// also a point of the figure.
std::string map_cell(const std::vector<Point>& points, const std::string& p, const std::string& q, double x, double y,
                     nlohmann::json& fig) {
  std::map<std::string, int> here;  // cell text -> members
  std::vector<std::string> order;
  for (const auto& pt : points) {
    if (!has(pt, p) || !has(pt, q) || parameter(*pt.member, p) != x || parameter(*pt.member, q) != y) continue;
    const std::string text = cell_text(pt.status);
    if (here[text]++ == 0) order.push_back(text);
    const char* kind = pt.status.kind == "complete" ? "complete" : pt.status.kind == "unstable" ? "unstable" : "other";
    fig[kind]["x"].push_back(x);
    fig[kind]["y"].push_back(y);
    if (pt.status.kind == "unstable") fig["unstable"]["kt"].push_back(json_number(pt.status.kt));
  }
  std::string cell;
  for (const auto& text : order)
    cell += (cell.empty() ? "" : "; ") + text + (here[text] > 1 ? " (x" + std::to_string(here[text]) + ")" : "");
  return cell.empty() ? "-" : cell;
}

// The map of one pair of parameters: rows = values of the first, columns = values of the second
// (stability/map_<p>_<q>.*, and its figure).
void write_map(const std::vector<Point>& points, const std::string& p, const std::string& q, const fs::path& dir,
               nlohmann::json& sj, ReportOutputs& outputs) {
  std::set<double> pv, qv;
  std::size_t without = 0;
  for (const auto& pt : points) {
    if (!has(pt, p) || !has(pt, q)) {
      ++without;
      continue;
    }
    pv.insert(parameter(*pt.member, p));
    qv.insert(parameter(*pt.member, q));
  }
  Table t;
  t.title = "Stability map: status of the members at each (" + p + ", " + q + "), other parameters as swept" +
            (without ? " (" + std::to_string(without) + " members without " + p + " or " + q + " left out)" : "");
  t.header = {p + " \\ " + q};
  for (const double y : qv) t.header.push_back(format_number(y));
  nlohmann::json fig{{"name", "stability_" + file_slug(p) + "_" + file_slug(q)}, {"x", p}, {"y", q}};
  for (const char* kind : {"complete", "unstable", "other"}) fig[kind] = {{"x", nlohmann::json::array()}, {"y", nlohmann::json::array()}};
  fig["unstable"]["kt"] = nlohmann::json::array();
  for (const double x : pv) {
    std::vector<std::string> row{format_number(x)};
    for (const double y : qv) row.push_back(map_cell(points, p, q, x, y, fig));
    t.rows.push_back(row);
  }
  if (t.rows.empty()) t.rows.push_back({"n/a: no member has both " + p + " and " + q});
  outputs.write_table(t, dir, "map_" + file_slug(p) + "_" + file_slug(q));
  sj["maps"].push_back({{"x", p}, {"y", q}, {"file", "stability/map_" + file_slug(p) + "_" + file_slug(q)}});
  outputs.figure_data["stability"].push_back(fig);
}

// Members that differ only in one parameter (every other scene value held fixed).
struct Line {
  nlohmann::json rest;
  std::vector<const Point*> points;
};

std::vector<Line> lines_of(const std::vector<Point>& points, const std::string& name, const ReportContext& context) {
  std::vector<Line> lines;
  std::map<std::string, std::size_t> index;
  for (const auto& pt : points) {
    if (!has(pt, name)) continue;
    const SceneValue v = scene_parameter(pt.member->scene, name, context.block.parameters);
    const nlohmann::json rest = scene_without(pt.member->scene, v.pointer);
    const auto [it, fresh] = index.emplace(rest.dump(), lines.size());
    if (fresh) lines.push_back({rest, {}});
    lines[it->second].points.push_back(&pt);
  }
  return lines;
}

// A line's stable range and the values at which members went unstable (a row of
// stability/limits.*, an entry of fits.json's "limits"); `fixed` says what it holds fixed.
void limit_row(Line& line, const std::string& name, const std::string& fixed, Table& lt, nlohmann::json& sj) {
  std::stable_sort(line.points.begin(), line.points.end(), [&](const Point* a, const Point* b) {
    return parameter(*a->member, name) < parameter(*b->member, name);
  });
  double stable_lo = k_nan, stable_hi = k_nan, unstable_lo = k_nan, unstable_hi = k_nan;
  std::string unstable_list, note;
  nlohmann::json unstable_json = nlohmann::json::array();
  for (const Point* pt : line.points) {
    const double x = parameter(*pt->member, name);
    if (pt->status.kind == "complete") {
      if (std::isnan(stable_lo)) stable_lo = x;
      stable_hi = x;
    } else if (pt->status.kind == "unstable") {
      if (std::isnan(unstable_lo)) unstable_lo = x;
      unstable_hi = x;
      // The edge as the solver named it: where, when and why (the health check that failed).
      unstable_list += (unstable_list.empty() ? "" : ", ") + format_number(x) + " (kt = " +
                       (std::isfinite(pt->status.kt) ? format_number(pt->status.kt) : std::string("?")) +
                       (pt->status.reason.empty() ? std::string() : ": " + pt->status.reason) + ")";
      unstable_json.push_back({{"value", x}, {"kt", json_number(pt->status.kt)}, {"cause", pt->status.reason}});
    } else {
      note += (note.empty() ? "" : "; ") + format_number(x) + ": " + cell_text(pt->status);
    }
  }
  auto num = [](double v, const char* none) { return std::isfinite(v) ? format_number(v) : std::string(none); };
  lt.rows.push_back({name, fixed, std::to_string(line.points.size()), num(stable_lo, "none stable"),
                     num(stable_hi, "none stable"), num(unstable_lo, "none unstable"),
                     num(unstable_hi, "none unstable"), unstable_list.empty() ? "none" : unstable_list, note});
  sj["limits"].push_back({{"parameter", name}, {"held_fixed", fixed}, {"members", line.points.size()},
                          {"stable_from", json_number(stable_lo)}, {"stable_to", json_number(stable_hi)},
                          {"smallest_unstable", json_number(unstable_lo)},
                          {"largest_unstable", json_number(unstable_hi)}, {"unstable", unstable_json}});
}

// Limits: per parameter, along each line of members that differ only in it, the values at
// which some member went unstable (stability/limits.*).
void write_limits(const std::vector<Point>& points, const std::vector<std::string>& names, const ReportContext& context,
                  const fs::path& dir, nlohmann::json& sj, ReportOutputs& outputs) {
  Table lt;
  lt.title = "Stability limits: per parameter, along each line of members that differ only in it";
  lt.header = {"parameter", "held fixed", "members", "stable from", "stable to", "smallest unstable",
               "largest unstable", "unstable at (kt of blow-up: cause)", "note"};
  for (const auto& name : names) {
    std::vector<Line> lines = lines_of(points, name, context);
    std::vector<nlohmann::json> rests;
    for (const auto& l : lines) rests.push_back(l.rest);
    const std::size_t rows_before = lt.rows.size();
    for (std::size_t li = 0; li < lines.size(); ++li) {
      if (lines[li].points.size() < 2) continue;  // one member is no sweep of this parameter
      std::string fixed = differing_leaves(rests, li);
      if (fixed.empty()) fixed = cases_label(lines[li].points.front()->cases);
      limit_row(lines[li], name, fixed, lt, sj);
    }
    if (lt.rows.size() == rows_before)
      lt.rows.push_back({name, "", "", "", "", "", "", "",
                         "no two members differ only in " + name + ": no line to read a limit from"});
  }
  outputs.write_table(lt, dir, "limits");
}

class StabilitySection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    if (!context.block.stability) return;
    const auto& names = context.block.stability->parameters;
    const fs::path dir = out_dir / "stability";
    std::vector<Point> points;
    for (const auto& d : distinct_members(context.members)) points.push_back({d.member, d.cases, classify(d.member->status)});
    nlohmann::json sj{{"parameters", names}, {"members", nlohmann::json::array()}, {"maps", nlohmann::json::array()},
                      {"limits", nlohmann::json::array()}};
    write_members(points, names, dir, sj, outputs);
    outputs.figure_data["stability"] = nlohmann::json::array();
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = i + 1; j < names.size(); ++j) write_map(points, names[i], names[j], dir, sj, outputs);
    write_limits(points, names, context, dir, sj, outputs);
    outputs.fits["stability"] = sj;
  }
};

}  // namespace

std::unique_ptr<ReportSection> stability_section() { return std::make_unique<StabilitySection>(); }

}  // namespace capsule::analysis
