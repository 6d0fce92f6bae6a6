#include "study/plan/phase_lengths.hpp"

#include <algorithm>
#include <cmath>

#include "solver/io/member_file.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

double number_at(const nlohmann::json& j, const nlohmann::json::json_pointer& p, double fallback) {
  return j.contains(p) && j.at(p).is_number() ? j.at(p).get<double>() : fallback;
}

std::string text_at(const nlohmann::json& j, const nlohmann::json::json_pointer& p) {
  return j.contains(p) && j.at(p).is_string() ? j.at(p).get<std::string>() : std::string();
}

// The stopping rule of a phase: members are neighbours only when theirs is the same (the cap
// aside: it bounds the expectation, whoever's neighbour it is).
bool same_rule(const nlohmann::json& a, const nlohmann::json& b, const char* phase) {
  const nlohmann::json::json_pointer p(std::string("/protocol/") + phase);
  if (!a.contains(p) || !b.contains(p)) return false;
  const auto& x = a.at(p);
  const auto& y = b.at(p);
  for (const char* key : {"until", "window_kt", "tolerance"})
    if (x.value(key, nlohmann::json()) != y.value(key, nlohmann::json())) return false;
  return true;
}

// Distance between two members' physics: differences of the logarithms of the numbers that
// set a capsule's relaxation (Ca, V, eta, E_b, the power law, G), and a fixed step for each
// differing choice (dimension excluded: never neighbours). The weights were read off the
// shipped results, where they predict the phase ends of one campaign from the others
// (docs/findings/performance.md "Time estimates against measured runs").
double distance(const nlohmann::json& a, const nlohmann::json& b) {
  using P = nlohmann::json::json_pointer;
  const auto log_of = [](const nlohmann::json& s, const char* key, double fallback) {
    return std::log(std::max(1e-12, number_at(s, P(key), fallback)));
  };
  const auto log1p_of = [](const nlohmann::json& s, const char* key, double scale) {
    return std::log1p(scale * std::max(0.0, number_at(s, P(key), 0.0)));
  };
  const auto power_n = [&](const nlohmann::json& s) { return number_at(s, P("/power_law/K"), 0) > 0 ? number_at(s, P("/power_law/n"), 1) : 1.0; };
  const auto eta_G = [&](const nlohmann::json& s) { return number_at(s, P("/eta"), 0) > 0 ? std::log1p(number_at(s, P("/G"), 0)) : 0.0; };
  double d = std::abs(log_of(a, "/Ca", 0.05) - log_of(b, "/Ca", 0.05)) + std::abs(log_of(a, "/V", 1) - log_of(b, "/V", 1)) +
             std::abs(log1p_of(a, "/eta", 1) - log1p_of(b, "/eta", 1)) + std::abs(log1p_of(a, "/E_b", 20) - log1p_of(b, "/E_b", 20)) +
             3.0 * std::abs(power_n(a) - power_n(b)) + std::abs(log1p_of(a, "/power_law/K", 1) - log1p_of(b, "/power_law/K", 1)) +
             0.3 * std::abs(eta_G(a) - eta_G(b)) + 0.3 * std::abs(number_at(a, P("/c0"), 0) - number_at(b, P("/c0"), 0));
  for (const auto& [key, step] : {std::pair{"/shape", 0.5}, {"/law", 0.5}, {"/reference_case", 0.5},
                                  {"/conventions/sls_viscosity", 0.3}})
    if (text_at(a, P(key)) != text_at(b, P(key))) d += step;
  return d;
}

}  // namespace

void PhaseLengths::add(const nlohmann::json& scene, double shear_kt, double recover_kt) {
  if (!scene.is_object() || !std::isfinite(shear_kt) || !std::isfinite(recover_kt)) return;
  records_.push_back({scene, {shear_kt, recover_kt}});
}

PhaseLengths PhaseLengths::from_results(const fs::path& results_dir) {
  PhaseLengths lengths;
  std::error_code ec;
  if (!fs::is_directory(results_dir, ec)) return lengths;
  for (const auto& campaign : fs::directory_iterator(results_dir, ec)) {
    const fs::path members = campaign.path() / "members";
    if (!fs::is_directory(members, ec)) continue;
    for (const auto& member : fs::directory_iterator(members, ec)) {
      const fs::path h5 = member.path() / "member.h5";
      if (!fs::exists(h5, ec)) continue;
      try {
        const io::MemberStatus s = io::read_member_status(h5.string());
        if (s.status == "complete") lengths.add(s.scene, s.t_stop, s.t_end - s.t_stop);
      } catch (const std::exception&) {
        // unreadable: not a measurement
      }
    }
  }
  return lengths;
}

std::optional<double> PhaseLengths::expected_kt(const nlohmann::json& scene, bool recovery) const {
  const char* phase = recovery ? "recover" : "shear";
  const nlohmann::json::json_pointer p(std::string("/protocol/") + phase);
  if (!scene.contains(p)) return std::nullopt;
  const std::string until = scene.at(p).value("until", "");
  if (until != "steady" && until != "settled") return std::nullopt;
  std::vector<std::pair<double, double>> near;  // distance, length
  for (const auto& r : records_) {
    if (r.scene.value("dim", 0) != scene.value("dim", -1) || !same_rule(r.scene, scene, phase)) continue;
    near.emplace_back(distance(r.scene, scene), std::max(0.1, r.kt[recovery ? 1 : 0]));
  }
  if (near.empty()) return std::nullopt;
  const std::size_t k = std::min<std::size_t>(3, near.size());
  std::partial_sort(near.begin(), near.begin() + static_cast<long>(k), near.end());
  double weight = 0, sum = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const double w = 1.0 / (0.05 + near[i].first);
    weight += w;
    sum += w * std::log(near[i].second);
  }
  return std::min(std::exp(sum / weight), scene.at(p).value("max_kt", 1e300));
}

}  // namespace capsule::study
