#include "analysis/report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "analysis/artificial_viscosity.hpp"
#include "analysis/bilinear_fit.hpp"
#include "analysis/exponential_fits.hpp"
#include "analysis/member_fits.hpp"
#include "analysis/plot_script.hpp"
#include "analysis/scene_parameter.hpp"
#include "analysis/slices_table.hpp"
#include "analysis/table.hpp"
#include "solver/io/member_file.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

struct MemberAnalysis {
  MemberRef ref;
  std::string status;   // the member file's status, or why there is none
  std::map<std::string, double> parameters;        // found scene parameters
  std::map<std::string, std::string> missing;      // parameter -> why not found
  MemberFits fits;
  std::vector<double> kt, D;                       // for figures
  std::vector<double> gamma_min, gamma_max;        // 3D power-law members: surface shear rate range (Fig. 64)
  std::map<std::string, double> markers;
  MemberSlices slices;                             // 3D members with stored shapes (Figs. 41-53)
  std::string slices_note;                         // why a 3D member's shapes could not be sliced
};

std::string case_label(const std::string& c) { return c.empty() ? "(all)" : c; }

// A slug made safe to name a file: [A-Za-z0-9_.-] kept, anything else becomes '_'.
std::string file_slug(const std::string& slug) {
  std::string out = slug;
  for (char& ch : out)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '.' && ch != '-') ch = '_';
  return out;
}

double parameter(const MemberAnalysis& m, const std::string& name) {
  const auto it = m.parameters.find(name);
  return it == m.parameters.end() ? k_nan : it->second;
}

void write_text(const fs::path& path, const std::string& text, std::vector<std::string>& files) {
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path.string());
  files.push_back(path.string());
}

MemberAnalysis analyse_member(const MemberRef& ref, const AnalysisBlock& block, const std::set<std::string>& wanted) {
  MemberAnalysis m;
  m.ref = ref;
  nlohmann::json scene = ref.scene;
  std::optional<io::MemberData> data;
  if (ref.path.empty() || !fs::exists(ref.path)) {
    m.status = fs::exists(ref.path + ".partial") ? "no final member file (only .partial: running or killed)"
                                                 : "member file missing (not run)";
    m.fits = failed_member(block.fits, m.status);
  } else {
    try {
      data.emplace(io::read_member(ref.path));
      m.status = data->status;
      m.fits = fit_member(*data, block.fits);
      if (const auto it = data->series.find("kt"); it != data->series.end()) m.kt = it->second;
      if (const auto it = data->series.find("D_xy"); it != data->series.end()) m.D = it->second;
      if (const auto lo = data->series.find("gamma_min"), hi = data->series.find("gamma_max");
          lo != data->series.end() && hi != data->series.end())
        m.gamma_min = lo->second, m.gamma_max = hi->second;
      m.markers = data->markers;
      if ((scene.is_null() || scene.empty()) && data->attributes.contains("scene")) scene = data->attributes["scene"];
    } catch (const std::exception& e) {
      m.status = std::string("unreadable: ") + e.what();
      m.fits = failed_member(block.fits, m.status);
    }
  }
  for (const auto& name : wanted) {
    const SceneValue v = scene_parameter(scene, name, block.parameters);
    if (v.found) m.parameters[name] = v.value;
    else m.missing[name] = v.reason;
  }
  if (data && has_3d_shapes(*data)) {
    // Lengths in units of the scene's radius a (resolution.a); member_slices falls back to
    // the volume-equivalent radius when the scene has none.
    const SceneValue a = scene_parameter(scene, "a", block.parameters);
    try {
      m.slices = member_slices(*data, a.found ? a.value : k_nan);
    } catch (const std::exception& e) {
      m.slices_note = std::string("shapes not sliced: ") + e.what();
    }
  }
  return m;
}

// Members ordered by case (first appearance), then by `x`, then by slug.
std::vector<const MemberAnalysis*> ordered(const std::vector<MemberAnalysis>& members, const std::string& x) {
  std::map<std::string, std::size_t> case_rank;
  for (const auto& m : members) case_rank.emplace(m.ref.case_name, case_rank.size());
  std::vector<const MemberAnalysis*> out;
  for (const auto& m : members) out.push_back(&m);
  std::stable_sort(out.begin(), out.end(), [&](const MemberAnalysis* p, const MemberAnalysis* q) {
    const auto cp = case_rank[p->ref.case_name], cq = case_rank[q->ref.case_name];
    if (cp != cq) return cp < cq;
    const double xp = parameter(*p, x), xq = parameter(*q, x);
    if (std::isnan(xp) != std::isnan(xq)) return std::isnan(xq);
    if (xp != xq && !std::isnan(xp)) return xp < xq;
    return p->ref.slug < q->ref.slug;
  });
  return out;
}

std::vector<std::string> fit_keys(const MemberFits& fits) {
  // A fixed, readable order.
  std::vector<std::string> keys;
  for (const char* k : {"response", "recovery", "two_phase_R1", "two_phase_R2", "double_exponential",
                        "double_exponential_free"})
    if (fits.count(k)) keys.push_back(k);
  return keys;
}

Table member_fits_table(const std::vector<MemberAnalysis>& members) {
  Table t;
  t.title = "Per-member fits: fitted k tau with 95 % intervals (Student's t), or why no fit was made";
  t.header = {"case", "member", "fit", "parameter", "value", "std_error", "ci95_low", "ci95_high", "R2",
              "reduced_chi2", "N", "t_begin", "t_end", "converged", "reason"};
  for (const auto* m : ordered(members, "")) {
    for (const auto& key : fit_keys(m->fits)) {
      const FitResult& f = m->fits.at(key);
      if (!f.ok) {
        t.rows.push_back({case_label(m->ref.case_name), m->ref.slug, f.model, "", "", "", "", "", "", "", "", "", "",
                          "", f.reason});
        continue;
      }
      for (const auto& p : f.parameters)
        t.rows.push_back({case_label(m->ref.case_name), m->ref.slug, f.model, p.name, format_number(p.value),
                          format_number(p.std_error), format_number(p.ci_low), format_number(p.ci_high),
                          format_number(f.r_squared), format_number(f.reduced_chi_square), std::to_string(f.n_points),
                          format_number(f.t_begin), format_number(f.t_end), f.converged ? "yes" : "no", ""});
    }
  }
  return t;
}

// Normalisation factor of a time for a member: k tau / (Ca V) (tau_e) or k tau / (Ca eta) (tau_v).
double normaliser(const MemberAnalysis& m, const std::string& normalise, std::string& why) {
  if (normalise == "none") return 1.0;
  const std::string other = normalise == "tau_e" ? "V" : "eta";
  for (const std::string& name : {std::string("Ca"), other})
    if (m.missing.count(name)) {
      why = m.missing.at(name);
      return k_nan;
    }
  const double d = parameter(m, "Ca") * parameter(m, other);
  if (!(d > 0.0)) {
    why = normalise + " undefined: Ca " + other + " = 0";
    return k_nan;
  }
  return d;
}

struct TableSeries {  // for the figure of a table
  std::vector<double> x, y, lo, hi;
};

Table time_table(const TableSpec& spec, const std::vector<MemberAnalysis>& members,
                 std::map<std::string, std::map<std::string, TableSeries>>& series) {
  Table t;
  const std::string unit = spec.normalise == "tau_e"   ? "tau / tau_e = k tau / (Ca V)"
                           : spec.normalise == "tau_v" ? "tau / tau_v = k tau / (Ca eta)"
                                                       : "k tau";
  t.title = spec.name + ": " + unit + " against " + spec.x + " (95 % intervals, Student's t)";
  t.header = {"case", spec.x, "member"};
  for (const auto& c : spec.columns) {
    t.header.push_back(c);
    t.header.push_back(c + " ±95%");
    t.header.push_back(c + " R2");
  }
  // Figure lines: one per case and per value of any other standard parameter that
  // varies within the case (e.g. V on an (eta, V) grid), so no line joins unlike members.
  std::map<std::string, std::set<std::string>> varying;  // case -> parameter names
  for (const std::string name : {"Ca", "E_b", "V", "eta"}) {
    if (name == spec.x) continue;
    std::map<std::string, std::set<double>> values;
    for (const auto& m : members) values[m.ref.case_name].insert(parameter(m, name));
    for (const auto& [c, v] : values)
      if (v.size() > 1) varying[c].insert(name);
  }
  auto line_of = [&](const MemberAnalysis& m) {
    std::string label = m.ref.case_name;
    std::string extra;
    for (const auto& name : varying[m.ref.case_name])
      extra += (extra.empty() ? "" : ", ") + name + " = " + format_number(parameter(m, name));
    if (!extra.empty()) label += (label.empty() ? "" : " ") + ("(" + extra + ")");
    return label;
  };
  for (const auto* m : ordered(members, spec.x)) {
    std::vector<std::string> row{case_label(m->ref.case_name),
                                 m->missing.count(spec.x) ? "n/a: " + m->missing.at(spec.x)
                                                          : format_number(parameter(*m, spec.x)),
                                 m->ref.slug};
    for (const auto& c : spec.columns) {
      const ColumnValue v = column_value(m->fits, c);
      std::string why = v.reason;
      double scale = v.parameter ? normaliser(*m, spec.normalise, why) : k_nan;
      if (!v.parameter || std::isnan(scale)) {
        row.insert(row.end(), {"n/a: " + why, "", ""});
        continue;
      }
      const double value = v.parameter->value / scale;
      const double hw = v.parameter->half_width() / scale;
      row.insert(row.end(), {format_number(value), format_number(hw), format_number(v.fit->r_squared)});
      if (!m->missing.count(spec.x)) {
        auto& s = series[line_of(*m)][c];
        s.x.push_back(parameter(*m, spec.x));
        s.y.push_back(value);
        s.lo.push_back(v.parameter->ci_low / scale);
        s.hi.push_back(v.parameter->ci_high / scale);
      }
    }
    t.rows.push_back(row);
  }
  return t;
}

// A parameter's value when every member of the group agrees, else NaN.
double common_value(const std::vector<const MemberAnalysis*>& group, const std::string& name) {
  double v = k_nan;
  for (const auto* m : group) {
    const double x = parameter(*m, name);
    if (std::isnan(x)) return k_nan;
    if (std::isnan(v)) v = x;
    else if (v != x) return k_nan;
  }
  return v;
}

nlohmann::json json_number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

// A member file under the campaign's results folder (the report folder's parent) is named
// relative to that folder, so shipped results read the same from a clone in any folder;
// one elsewhere keeps the path it was given.
std::string recorded_member_path(const std::string& member_path, const fs::path& report_dir) {
  if (member_path.empty()) return member_path;
  const fs::path root = fs::weakly_canonical(fs::absolute(report_dir)).parent_path();
  const fs::path file = fs::weakly_canonical(fs::absolute(member_path));
  const fs::path rel = file.lexically_relative(root);
  if (rel.empty() || *rel.begin() == "..") return member_path;
  return rel.generic_string();
}

}  // namespace

ReportSummary write_report(const ReportRequest& request) {
  const std::string where = request.campaign_file.empty() ? request.campaign_name : request.campaign_file;
  const AnalysisBlock block = parse_analysis_block(request.analysis, where);
  if (request.out_dir.empty()) throw std::invalid_argument("write_report: empty out_dir");
  const fs::path out(request.out_dir);
  fs::create_directories(out);
  ReportSummary summary;

  std::set<std::string> wanted{"Ca", "E_b", "V", "eta"};
  for (const auto& t : block.tables) wanted.insert(t.x);
  std::vector<MemberAnalysis> members;
  for (const auto& ref : request.members) members.push_back(analyse_member(ref, block, wanted));

  nlohmann::json fits_json;
  fits_json["campaign"] = request.campaign_name;
  fits_json["campaign_file"] = request.campaign_file;
  fits_json["analysis"] = request.analysis;
  fits_json["members"] = nlohmann::json::array();
  for (const auto& m : members) {
    nlohmann::json j{{"id", m.ref.id}, {"slug", m.ref.slug}, {"case", m.ref.case_name},
                     {"path", recorded_member_path(m.ref.path, out)},
                     {"status", m.status}};
    j["parameters"] = nlohmann::json::object();
    for (const auto& [k, v] : m.parameters) j["parameters"][k] = json_number(v);
    j["fits"] = nlohmann::json::object();
    for (const auto& [k, f] : m.fits) j["fits"][k] = to_json(f);
    if (!m.slices.empty()) j["slices"] = {{"file", "slices_" + file_slug(m.ref.slug) + ".csv"}, {"unit", m.slices.unit}};
    if (!m.slices_note.empty()) j["slices_note"] = m.slices_note;
    fits_json["members"].push_back(j);
  }

  auto append = [&](const std::vector<std::string>& files) {
    summary.files.insert(summary.files.end(), files.begin(), files.end());
  };
  append(member_fits_table(members).write(out.string(), "member_fits"));
  // Central slices of 3D members' stored shapes (Figs. 41-53), beside the member table.
  for (const auto& m : members)
    if (!m.slices.empty())
      write_text(out / ("slices_" + file_slug(m.ref.slug) + ".csv"), slices_csv(m.slices), summary.files);

  // Characteristic-time tables.
  nlohmann::json figure_tables = nlohmann::json::array();
  fits_json["tables"] = nlohmann::json::array();
  for (const auto& spec : block.tables) {
    std::map<std::string, std::map<std::string, TableSeries>> series;
    append(time_table(spec, members, series).write((out / "tables").string(), spec.name));
    fits_json["tables"].push_back({{"name", spec.name}, {"x", spec.x}, {"columns", spec.columns},
                                   {"normalise", spec.normalise}});
    nlohmann::json ft{{"name", spec.name}, {"x", spec.x}};
    ft["ylabel"] = spec.normalise == "tau_e"   ? "$\\tau/\\tau_e$"
                   : spec.normalise == "tau_v" ? "$\\tau/\\tau_v$"
                                               : "$k\\tau$";
    ft["cases"] = nlohmann::json::object();
    for (const auto& [c, cols] : series) {
      nlohmann::json cj{{"columns", nlohmann::json::object()}};
      for (const auto& [col, s] : cols) cj["columns"][col] = {{"x", s.x}, {"y", s.y}, {"lo", s.lo}, {"hi", s.hi}};
      ft["cases"][c] = cj;
    }
    figure_tables.push_back(ft);
  }

  // Bilinear model (95)-(96) per case and target, and artificial viscosities (97)-(98).
  fits_json["bilinear"] = nlohmann::json::array();
  if (block.bilinear) {
    Table bt;
    bt.title = "Bilinear model (95)-(96): k tau = a eta + b V + c per case (95 % intervals, Student's t)";
    bt.header = {"case", "target", "Ca", "E_b", "a", "a ±95%", "b", "b ±95%", "c", "c ±95%", "R2", "N", "b/a",
                 "b/a std_error", "reason"};
    Table at;
    at.title = "Artificial viscosity: V* = V + (a/b) eta (98) and eta* = (b/a)(V - V_base) (97)";
    at.header = {"case", "target", "member", "V", "eta", "k tau", "a/b", "V* (98)", "eta* (97)"};
    std::vector<std::string> cases;
    for (const auto& m : members)
      if (std::find(cases.begin(), cases.end(), m.ref.case_name) == cases.end()) cases.push_back(m.ref.case_name);
    for (const auto& c : cases) {
      std::vector<const MemberAnalysis*> group;
      for (const auto& m : members)
        if (m.ref.case_name == c) group.push_back(&m);
      for (const auto& target : block.bilinear->targets) {
        std::vector<double> eta, V, y;
        std::vector<std::string> used, excluded;
        for (const auto* m : group) {
          const ColumnValue v = column_value(m->fits, target);
          const double e = parameter(*m, "eta"), vv = parameter(*m, "V");
          if (!v.parameter || std::isnan(e) || std::isnan(vv)) {
            excluded.push_back(m->ref.slug + ": " +
                               (!v.parameter ? v.reason : std::string("eta or V not found in the scene")));
            continue;
          }
          eta.push_back(e);
          V.push_back(vv);
          y.push_back(v.parameter->value);
          used.push_back(m->ref.slug);
        }
        const FitResult fit = fit_bilinear(eta, V, y);
        const double Ca = common_value(group, "Ca"), Eb = common_value(group, "E_b");
        nlohmann::json bj{{"case", c}, {"target", target}, {"Ca", json_number(Ca)}, {"E_b", json_number(Eb)},
                          {"fit", to_json(fit)}, {"members", used}, {"excluded", excluded}};
        std::vector<std::string> row{case_label(c), target, format_number(Ca), format_number(Eb)};
        if (!fit.ok) {
          row.insert(row.end(), {"", "", "", "", "", "", "", std::to_string(y.size()), "", "", fit.reason});
        } else {
          const Ratio ba = ratio_b_over_a(fit), ab = ratio_a_over_b(fit);
          bj["b_over_a"] = {{"value", json_number(ba.value)}, {"std_error", json_number(ba.std_error)}};
          bj["a_over_b"] = {{"value", json_number(ab.value)}, {"std_error", json_number(ab.std_error)}};
          for (const auto& p : fit.parameters) {
            row.push_back(format_number(p.value));
            row.push_back(format_number(p.half_width()));
          }
          row.insert(row.end(), {format_number(fit.r_squared), std::to_string(fit.n_points), format_number(ba.value),
                                 format_number(ba.std_error), fit.converged ? "" : "Ceres did not report convergence"});
          for (std::size_t i = 0; i < used.size(); ++i) {
            const double V_star = artificial_V(ab.value, V[i], eta[i]);
            std::string eta_star;
            if (block.bilinear->V_base && eta[i] == 0.0)
              eta_star = format_number(artificial_eta(ba.value, V[i], *block.bilinear->V_base));
            at.rows.push_back({case_label(c), target, used[i], format_number(V[i]), format_number(eta[i]),
                               format_number(y[i]), format_number(ab.value), format_number(V_star), eta_star});
          }
        }
        bt.rows.push_back(row);
        fits_json["bilinear"].push_back(bj);
      }
    }
    if (cases.empty())
      for (const auto& target : block.bilinear->targets)
        bt.rows.push_back({case_label(""), target, "", "", "", "", "", "", "", "", "", "0", "", "",
                           "no members to fit"});
    append(bt.write(out.string(), "bilinear"));
    append(at.write(out.string(), "artificial_viscosity"));
  }

  write_text(out / "fits.json", fits_json.dump(2) + "\n", summary.files);

  // Figures.
  if (!block.figures) {
    summary.figures_skipped = true;
    summary.figures_note = "figures off in the analysis block";
    return summary;
  }
  const fs::path fig_dir = out / "figures";
  fs::create_directories(fig_dir);
  nlohmann::json fig{{"tables", figure_tables}, {"members", nlohmann::json::array()}, {"slices", nlohmann::json::array()}};
  for (const auto& m : members) {
    if (m.slices.empty()) continue;
    nlohmann::json sj = slices_figure_json(m.slices);
    sj["slug"] = file_slug(m.ref.slug);
    sj["title"] = case_label(m.ref.case_name) + " / " + m.ref.slug + ": central slices at theta = 0";
    fig["slices"].push_back(sj);
  }
  for (const auto& m : members) {
    if (m.kt.empty() || m.kt.size() != m.D.size()) continue;
    nlohmann::json mj{{"slug", file_slug(m.ref.slug)}, {"kt", m.kt}, {"D_xy", m.D}, {"curves", nlohmann::json::array()}};
    mj["title"] = case_label(m.ref.case_name) + " / " + m.ref.slug + " (" + m.status + ")";
    if (m.gamma_min.size() == m.kt.size() && m.gamma_max.size() == m.kt.size() && !m.gamma_min.empty())
      mj["gamma"] = {{"min", m.gamma_min}, {"max", m.gamma_max}};
    mj["markers"] = nlohmann::json::object();
    for (const auto& [k, v] : m.markers)
      if (std::isfinite(v)) mj["markers"][k] = v;
    for (const auto& key : fit_keys(m.fits)) {
      const FitResult& f = m.fits.at(key);
      if (!f.ok) continue;
      std::vector<double> t, d;
      for (double x : m.kt)
        if (x >= f.t_begin && x <= f.t_end) {
          t.push_back(x);
          d.push_back(evaluate_fit(f, x));
        }
      std::string label = f.model;
      for (const auto& p : f.parameters) label += ", " + p.name + " = " + format_number(p.value);
      mj["curves"].push_back({{"label", label}, {"kt", t}, {"D", d}});
    }
    fig["members"].push_back(mj);
  }
  const fs::path data_path = fig_dir / "figure_data.json";
  const fs::path script_path = fig_dir / "plot_report.py";
  write_text(data_path, fig.dump() + "\n", summary.files);
  write_text(script_path, plot_script_text(), summary.files);
  const std::string note = run_plot_script(script_path.string(), data_path.string(), fig_dir.string());
  if (!note.empty()) {
    summary.figures_skipped = true;
    summary.figures_note = note;
  } else {
    for (const auto& e : fs::directory_iterator(fig_dir))
      if (e.path().extension() == ".png") summary.files.push_back(e.path().string());
    summary.figures_note = "figures written to " + fig_dir.string();
  }
  return summary;
}

}  // namespace capsule::analysis
