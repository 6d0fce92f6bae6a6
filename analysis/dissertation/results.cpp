#include "analysis/dissertation/results.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "analysis/report/analysis_block.hpp"
#include "analysis/fit/resolution_ladder.hpp"
#include "analysis/report/table.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

std::vector<const DissertationMember*> DissertationCampaign::in_case_all_levels(const std::string& case_name) const {
  std::vector<const DissertationMember*> out;
  std::set<std::string> seen;
  for (const auto& m : members)
    if ((case_name.empty() || m.case_name == case_name) && seen.insert(m.slug).second) out.push_back(&m);
  return out;
}

std::vector<const DissertationMember*> DissertationCampaign::in_case(const std::string& case_name) const {
  std::vector<const DissertationMember*> out;
  for (const DissertationMember* m : in_case_all_levels(case_name))
    if (!m->coarse) out.push_back(m);
  return out;
}

std::string DissertationCampaign::judged_levels() const {
  std::string out;
  const auto judged = in_case("");
  for (const auto& [key, spacing] : ladder_keys) {
    std::map<double, int> count;  // level -> judged members there
    for (const DissertationMember* m : judged)
      if (const auto it = m->parameters.find(key); it != m->parameters.end()) ++count[it->second];
    std::string levels;
    // finest first
    std::vector<std::pair<double, int>> sorted(count.begin(), count.end());
    std::sort(sorted.begin(), sorted.end(), [&](const auto& p, const auto& q) {
      return ladder_spacing(spacing, p.first) < ladder_spacing(spacing, q.first);
    });
    for (const auto& [level, n] : sorted)
      levels += (levels.empty() ? "" : ", ") + format_number(level) + " (" + std::to_string(n) +
                (n == 1 ? " member)" : " members)");
    out += (out.empty() ? "" : "; ") + key + ": " + (levels.empty() ? "no member records it" : levels);
  }
  return out;
}

void mark_coarse_members(DissertationCampaign& c) {
  for (auto& m : c.members) m.coarse = false, m.finer.clear();
  for (const auto& [key, spacing] : c.ladder_keys) {
    // A physical point: the case and every recorded parameter but the ladder keys.
    const auto point = [&](const DissertationMember& m) {
      std::ostringstream s;
      s.precision(17);
      s << m.case_name;
      for (const auto& [k, v] : m.parameters)
        if (!c.ladder_keys.count(k)) s << '|' << k << '=' << v;
      return s.str();
    };
    std::map<std::string, const DissertationMember*> finest;  // point -> its finest member
    for (const auto& m : c.members) {
      const auto it = m.parameters.find(key);
      if (it == m.parameters.end() || std::isnan(ladder_spacing(spacing, it->second))) continue;
      const DissertationMember*& f = finest[point(m)];
      if (!f || ladder_spacing(spacing, it->second) < ladder_spacing(spacing, f->parameters.at(key))) f = &m;
    }
    for (auto& m : c.members) {
      const auto it = m.parameters.find(key);
      if (it == m.parameters.end()) continue;
      const auto f = finest.find(point(m));
      if (f == finest.end() || f->second == &m) continue;
      if (ladder_spacing(spacing, f->second->parameters.at(key)) < ladder_spacing(spacing, it->second)) {
        m.coarse = true;
        m.finer = f->second->slug;
      }
    }
  }
}

std::string resolve_member_file(const std::string& campaign_root, const std::string& recorded) {
  if (recorded.empty()) return "";
  const fs::path p(recorded);
  if (p.is_relative()) {
    const fs::path q = fs::path(campaign_root) / p;
    return fs::exists(q) ? q.string() : "";
  }
  if (fs::exists(p)) return p.string();
  const fs::path moved = fs::path(campaign_root) / "members" / p.parent_path().filename() / p.filename();
  return fs::exists(moved) ? moved.string() : "";
}

DissertationResults::DissertationResults(std::string results_dir) : dir_(std::move(results_dir)) {}

const DissertationCampaign& DissertationResults::campaign(const std::string& name) const {
  if (const auto it = campaigns_.find(name); it != campaigns_.end()) return it->second;
  DissertationCampaign c;
  c.name = name;
  const fs::path root = fs::path(dir_) / name;
  const fs::path path = root / "report" / "fits.json";
  std::ifstream f(path);
  if (!f) {
    c.missing = "campaign " + name + " not run (no " + path.string() + ")";
    return campaigns_.emplace(name, std::move(c)).first->second;
  }
  try {
    f >> c.fits;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not valid JSON: " + e.what());
  }
  c.found = true;
  if (c.fits.contains("analysis") && c.fits["analysis"].is_object()) {
    try {
      const AnalysisBlock block = parse_analysis_block(c.fits["analysis"], path.string());
      for (const auto& l : block.ladders) c.ladder_keys[l.key] = l.spacing;
      if (block.bilinear && !block.bilinear->ladder.empty()) c.ladder_keys[block.bilinear->ladder] = block.bilinear->spacing;
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path.string() + ": its analysis block: " + e.what());
    }
  }
  for (const auto& j : c.fits.value("members", nlohmann::json::array())) {
    DissertationMember m;
    m.id = j.value("id", "");
    m.slug = j.value("slug", "");
    m.case_name = j.value("case", "");
    m.status = j.value("status", "");
    m.recorded_path = j.value("path", "");
    // Named copies: items() of a temporary would dangle inside the loop.
    const nlohmann::json parameters = j.value("parameters", nlohmann::json::object());
    const nlohmann::json fits = j.value("fits", nlohmann::json::object());
    for (const auto& [k, v] : parameters.items())
      if (v.is_number()) m.parameters[k] = v.get<double>();
    for (const auto& [k, v] : fits.items()) m.fits[k] = fit_result_from_json(v);
    m.file = resolve_member_file(root.string(), m.recorded_path);
    c.members.push_back(std::move(m));
  }
  mark_coarse_members(c);
  return campaigns_.emplace(name, std::move(c)).first->second;
}

std::optional<io::MemberData> DissertationResults::member_data(const DissertationMember& m, std::string& why,
                                                         bool accept_unstable) const {
  if (m.file.empty()) {
    why = "member file of " + m.slug + " missing (" + (m.recorded_path.empty() ? "no path recorded" : m.recorded_path) + ")";
    return std::nullopt;
  }
  try {
    io::MemberData d = io::read_member(m.file);
    if (!d.complete() && !(accept_unstable && d.unstable())) {
      why = m.slug + " not complete: " + d.status;
      return std::nullopt;
    }
    return d;
  } catch (const std::exception& e) {
    why = m.slug + ": unreadable member file: " + e.what();
    return std::nullopt;
  }
}

}  // namespace capsule::analysis
