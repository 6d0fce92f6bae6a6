#include "analysis/dissertation/results.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "analysis/report/analysis_block.hpp"
#include "analysis/report/resolution_ladder.hpp"
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

void mark_coarse_members(DissertationCampaign& c, int level) {
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
    const auto spacing_of = [&](const DissertationMember* m) { return ladder_spacing(spacing, m->parameters.at(key)); };
    std::map<std::string, std::vector<DissertationMember*>> levels;  // point -> its members with the key
    for (auto& m : c.members) {
      const auto it = m.parameters.find(key);
      if (it == m.parameters.end() || std::isnan(ladder_spacing(spacing, it->second))) continue;
      levels[point(m)].push_back(&m);
    }
    for (auto& [p, ms] : levels) {
      std::stable_sort(ms.begin(), ms.end(), [&](auto* a, auto* b) { return spacing_of(a) < spacing_of(b); });
      // The distinct levels, finest first; the judged member is the first at the level asked for.
      std::vector<double> distinct;
      for (auto* m : ms)
        if (distinct.empty() || spacing_of(m) > distinct.back()) distinct.push_back(spacing_of(m));
      if (distinct.size() > 1) c.several_levels = true;
      const double judged_spacing = distinct[std::min<std::size_t>(static_cast<std::size_t>(std::max(level, 0)), distinct.size() - 1)];
      const DissertationMember* judged = nullptr;
      for (auto* m : ms)
        if (spacing_of(m) == judged_spacing) {
          judged = m;
          break;
        }
      for (auto* m : ms) {
        if (spacing_of(m) == judged_spacing) continue;
        m->coarse = true;
        if (spacing_of(m) > judged_spacing) m->finer = judged->slug;
      }
    }
  }
}

void judge_bilinear_at_level(DissertationCampaign& c, int level) {
  if (!c.fits.contains("bilinear") || !c.fits["bilinear"].is_array()) return;
  std::map<std::pair<std::string, std::string>, int> count;  // (case, target) -> fits
  for (const auto& e : c.fits["bilinear"]) ++count[{e.value("case", ""), e.value("target", "")}];
  for (const auto& [k, n] : count)
    if (n > 1) c.several_levels = true;
  if (level < 1) return;
  nlohmann::json kept = nlohmann::json::array();
  std::set<std::pair<std::string, std::string>> dropped;
  for (const auto& e : c.fits["bilinear"]) {
    const std::pair<std::string, std::string> k{e.value("case", ""), e.value("target", "")};
    if (count[k] > 1 && dropped.insert(k).second) continue;  // the finest, listed first
    kept.push_back(e);
  }
  c.fits["bilinear"] = kept;
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

DissertationResults::DissertationResults(std::string results_dir, int level, std::string campaign_prefix)
    : dir_(std::move(results_dir)), level_(level), prefix_(std::move(campaign_prefix)) {}

std::set<std::string> DissertationResults::take_campaigns_read() const {
  std::set<std::string> out;
  out.swap(read_);
  return out;
}

const DissertationCampaign& DissertationResults::campaign(const std::string& name) const {
  read_.insert(name);
  if (const auto it = campaigns_.find(name); it != campaigns_.end()) return it->second;
  DissertationCampaign c;
  c.name = prefix_ + name;
  const fs::path root = fs::path(dir_) / c.name;
  const fs::path path = root / "report" / "fits.json";
  std::ifstream f(path);
  if (!f) {
    c.missing = "campaign " + c.name + " not run (no " + path.string() + ")";
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
  mark_coarse_members(c, level_);
  judge_bilinear_at_level(c, level_);
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
