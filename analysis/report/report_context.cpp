#include "analysis/report/report_context.hpp"

#include "analysis/report/report_section.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>

#include "analysis/report/scene_parameter.hpp"
#include "analysis/report/table.hpp"
#include "solver/io/member_file.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

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
      if (data->complete())
        if (const std::string wrong = io::missing_series(*data); !wrong.empty()) throw std::runtime_error(wrong);
      m.status = data->status;
      m.fits = fit_member(*data, block.fits);
      if (const auto it = data->series.find("kt"); it != data->series.end()) m.kt = it->second;
      if (const auto it = data->series.find("D_xy"); it != data->series.end()) m.D = it->second;
      if (const auto it = data->series.find("D_extent"); it != data->series.end()) m.D_extent = it->second;
      if (const auto it = data->series.find("theta"); it != data->series.end()) m.theta = it->second;
      if (const auto ax = data->series.find("D_axial"), tr = data->series.find("D_transverse");
          ax != data->series.end() && tr != data->series.end() && ax->second.size() == tr->second.size()) {
        m.lambda.resize(ax->second.size());
        for (std::size_t i = 0; i < m.lambda.size(); ++i) m.lambda[i] = ax->second[i] / tr->second[i];
      }
      if (const auto lo = data->series.find("gamma_min"), hi = data->series.find("gamma_max");
          lo != data->series.end() && hi != data->series.end())
        m.gamma_min = lo->second, m.gamma_max = hi->second;
      for (const auto& e : block.experiments)
        for (const auto& q : e.compare)
          if (const auto it = data->series.find(q.series); it != data->series.end()) m.series[q.series] = it->second;
      m.markers = data->markers;
      const auto& a = data->attributes;
      if (a.contains("wall_seconds") && a["wall_seconds"].is_number()) m.wall_seconds = a["wall_seconds"].get<double>();
      if (a.contains("threads") && a["threads"].is_number()) m.threads = a["threads"].get<long>();
      if ((scene.is_null() || scene.empty()) && a.contains("scene")) scene = a["scene"];
    } catch (const std::exception& e) {
      m.status = std::string("unreadable: ") + e.what();
      m.fits = failed_member(block.fits, m.status);
    }
  }
  m.scene = scene;
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

}  // namespace

std::vector<MemberAnalysis> analyse_members(const ReportRequest& request, const AnalysisBlock& block,
                                            const std::set<std::string>& wanted) {
  std::vector<MemberAnalysis> members;
  for (const auto& ref : request.members) members.push_back(analyse_member(ref, block, wanted));
  return members;
}

std::string case_label(const std::string& c) { return c.empty() ? "(all)" : c; }

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
  std::vector<std::string> keys;
  for (const char* k : {"response", "recovery", "two_phase_R1", "two_phase_R2", "double_exponential",
                        "double_exponential_free", "extensional_recovery"})
    if (fits.count(k)) keys.push_back(k);
  return keys;
}

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

std::vector<DistinctMember> distinct_members(const std::vector<MemberAnalysis>& members) {
  std::vector<DistinctMember> out;
  std::map<std::string, std::size_t> index;  // id (else path) -> position in out
  for (const auto& m : members) {
    const std::string key = m.ref.id.empty() ? "path:" + m.ref.path : m.ref.id;
    const auto [it, fresh] = index.emplace(key, out.size());
    if (fresh) out.push_back({&m, {}});
    auto& cases = out[it->second].cases;
    if (std::find(cases.begin(), cases.end(), m.ref.case_name) == cases.end()) cases.push_back(m.ref.case_name);
  }
  return out;
}

std::string cases_label(const std::vector<std::string>& cases) {
  std::string out;
  for (const auto& c : cases) {
    if (!out.empty()) out += '/';
    out += case_label(c);
  }
  return out.empty() ? case_label("") : out;
}

namespace {
void leaves(const nlohmann::json& j, const std::string& prefix, std::map<std::string, std::string>& out) {
  if (j.is_object() && !j.empty()) {
    for (const auto& [key, value] : j.items()) leaves(value, prefix.empty() ? key : prefix + "." + key, out);
  } else {
    out[prefix] = j.dump();
  }
}
}  // namespace

std::map<std::string, std::string> scene_leaves(const nlohmann::json& scene) {
  std::map<std::string, std::string> out;
  leaves(scene, "", out);
  // The keys a canonical scene leaves out while they hold their default, with that default.
  if (const auto* d = omitted_scene_defaults(scene))
    for (const auto& [key, value] : *d) out.emplace(key, value.dump());
  return out;
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_number()) return format_number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

std::string differing_leaves(const std::vector<nlohmann::json>& scenes, std::size_t i) {
  std::vector<std::map<std::string, std::string>> all;
  for (const auto& s : scenes) all.push_back(scene_leaves(s));
  std::set<std::string> keys;
  for (const auto& l : all)
    for (const auto& [k, v] : l) keys.insert(k);
  std::string out;
  for (const auto& k : keys) {
    std::set<std::string> values;
    for (const auto& l : all) values.insert(l.count(k) ? l.at(k) : "(absent)");
    if (values.size() < 2) continue;
    const std::string short_key = k.substr(k.rfind('.') == std::string::npos ? 0 : k.rfind('.') + 1);
    std::string text = "(absent)";
    if (all[i].count(k)) text = value_text(nlohmann::json::parse(all[i].at(k)));
    out += (out.empty() ? "" : ", ") + short_key + " = " + text;
  }
  return out;
}

void record_varying_parameters(std::vector<MemberAnalysis>& members) {
  std::vector<std::map<std::string, std::string>> all;
  std::set<std::string> keys;
  for (const auto& m : members) {
    all.push_back(m.scene.is_object() ? scene_leaves(m.scene) : std::map<std::string, std::string>{});
    for (const auto& [k, v] : all.back()) keys.insert(k);
  }
  for (const auto& key : keys) {
    std::set<std::string> values;
    bool numeric = true;
    for (const auto& l : all) {
      const auto it = l.find(key);
      if (it == l.end()) continue;
      values.insert(it->second);
      const nlohmann::json v = nlohmann::json::parse(it->second);
      numeric = numeric && v.is_number();
    }
    if (values.size() < 2 || !numeric) continue;
    for (std::size_t i = 0; i < members.size(); ++i)
      if (const auto it = all[i].find(key); it != all[i].end())
        members[i].parameters.emplace(key, nlohmann::json::parse(it->second).get<double>());
  }
}

std::string incomplete_reason(const MemberAnalysis& m) {
  if (m.status == "complete") return "";
  for (const char* start : {"member file missing", "no final member file", "unreadable"})
    if (m.status.rfind(start, 0) == 0) return m.status;
  return "member not complete: " + m.status;
}

double interpolate_series(const std::vector<double>& t, const std::vector<double>& y, double at) {
  if (t.empty() || y.size() != t.size() || !(at >= t.front() && at <= t.back())) return k_nan;
  const std::size_t j = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), at) - t.begin());
  if (j == 0) return y[0];
  return y[j - 1] + (y[j] - y[j - 1]) * (at - t[j - 1]) / (t[j] - t[j - 1]);
}

nlohmann::json json_number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

void write_text(const fs::path& path, const std::string& text, std::vector<std::string>& files) {
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path.string());
  files.push_back(path.string());
}

void ReportOutputs::write_table(const Table& table, const fs::path& dir, const std::string& stem) {
  const auto written = table.write(dir.string(), stem);
  files.insert(files.end(), written.begin(), written.end());
}

void ReportOutputs::write_text(const fs::path& path, const std::string& text) {
  capsule::analysis::write_text(path, text, files);
}

}  // namespace capsule::analysis
