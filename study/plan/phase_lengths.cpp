#include "study/plan/phase_lengths.hpp"

#include <algorithm>
#include <cmath>

#include "solver/io/member_file.hpp"
#include "study/plan/shipped_phase_lengths.hpp"
#include "solver/scene/choices.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

double number_at(const nlohmann::json& j, const nlohmann::json::json_pointer& p, double fallback) {
  return j.contains(p) && j.at(p).is_number() ? j.at(p).get<double>() : fallback;
}

std::string text_at(const nlohmann::json& j, const nlohmann::json::json_pointer& p) {
  return j.contains(p) && j.at(p).is_string() ? j.at(p).get<std::string>() : std::string();
}

// The stopping rule of a phase (the cap aside: it bounds the expectation, whoever's neighbour
// it is): members are neighbours only when theirs is the same.
std::string stopping_rule(const nlohmann::json& scene, const char* phase) {
  const nlohmann::json::json_pointer p(std::string("/protocol/") + phase);
  if (!scene.contains(p)) return "";
  const auto& x = scene.at(p);
  const auto number = [&](const char* key) {  // 2 and 2.0 are one window
    return x.contains(key) && x.at(key).is_number() ? nlohmann::json(x.at(key).get<double>()).dump() : std::string("-");
  };
  return x.value("until", std::string()) + " " + number("window_kt") + " " + number("tolerance");
}

// The first phase: the optical-tweezers stretch where the scene has one, else the shear.
const char* first_phase(const nlohmann::json& scene) {
  return scene.contains(nlohmann::json::json_pointer("/protocol/stretch")) ? "stretch" : "shear";
}

}  // namespace

// What sets a capsule's relaxation, read once per member: the logarithms of Ca and V, eta,
// E_b, the power law and G, and the discrete choices.
PhaseLengths::Physics PhaseLengths::physics_of(const nlohmann::json& s) {
  using P = nlohmann::json::json_pointer;
  const auto log1p_of = [&](const char* key, double scale) {
    return std::log1p(scale * std::max(0.0, number_at(s, P(key), 0.0)));
  };
  Physics f;
  f.dim = s.value("dim", 0);
  f.log_Ca = std::log(std::max(1e-12, number_at(s, P("/Ca"), 0.05)));
  f.log_V = std::log(std::max(1e-12, number_at(s, P("/V"), 1)));
  f.eta = log1p_of("/eta", 1);
  f.E_b = log1p_of("/E_b", 20);
  const bool power_law = number_at(s, P("/power_law/K"), 0) > 0;
  f.power_n = power_law ? number_at(s, P("/power_law/n"), 1) : 1.0;
  f.power_K = log1p_of("/power_law/K", 1);
  f.G = number_at(s, P("/eta"), 0) > 0 ? std::log1p(number_at(s, P("/G"), 0)) : 0.0;
  f.c0 = number_at(s, P("/c0"), 0);
  f.shape = text_at(s, P("/shape"));
  f.law = text_at(s, P("/law"));
  f.reference_case = text_at(s, P("/reference_case"));
  f.sls_reading = text_at(s, P("/conventions/sls_viscosity"));
  // A stretch's loading and a shear are different phases: never each other's neighbours.
  f.rule[0] = std::string(first_phase(s)) + " " + stopping_rule(s, first_phase(s));
  f.rule[1] = stopping_rule(s, "recover");
  return f;
}

// Distance between two members' physics: differences of the logarithms of the numbers that
// set a capsule's relaxation and a fixed step for each differing choice. The weights were read
// off the shipped results, where they predict the phase ends of one campaign from the others
// (docs/findings/performance.md "Time estimates against measured runs"); log Ca weighs 0.3,
// since expected_kt scales a neighbour's length to the target's Ca.
double PhaseLengths::distance(const Physics& a, const Physics& b) {
  double d = 0.3 * std::abs(a.log_Ca - b.log_Ca) + std::abs(a.log_V - b.log_V) + std::abs(a.eta - b.eta) +
             std::abs(a.E_b - b.E_b) + 3.0 * std::abs(a.power_n - b.power_n) + std::abs(a.power_K - b.power_K) +
             0.3 * std::abs(a.G - b.G) + 0.3 * std::abs(a.c0 - b.c0);
  if (a.shape != b.shape) d += 0.5;
  if (a.law != b.law) d += 0.5;
  if (a.reference_case != b.reference_case) d += 0.5;
  if (a.sls_reading != b.sls_reading) d += 0.3;
  return d;
}

void PhaseLengths::add(const nlohmann::json& scene, double shear_kt, double recover_kt) {
  if (!scene.is_object() || !std::isfinite(shear_kt) || !std::isfinite(recover_kt)) return;
  records_.push_back({physics_of(scene), {shear_kt, recover_kt}});
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

bool PhaseLengths::Physics::operator==(const Physics& o) const {
  return dim == o.dim && log_Ca == o.log_Ca && log_V == o.log_V && eta == o.eta && E_b == o.E_b &&
         power_n == o.power_n && power_K == o.power_K && G == o.G && c0 == o.c0 && shape == o.shape &&
         law == o.law && reference_case == o.reference_case && sls_reading == o.sls_reading &&
         rule[0] == o.rule[0] && rule[1] == o.rule[1];
}

const PhaseLengths& PhaseLengths::shipped() {
  static const PhaseLengths table = [] {
    PhaseLengths t;
    const auto records = nlohmann::json::parse(shipped_phase_lengths_json());
    for (const auto& r : records) t.add(r.at("scene"), r.at("shear_kt").get<double>(), r.at("recover_kt").get<double>());
    return t;
  }();
  return table;
}

PhaseLengths PhaseLengths::known(const fs::path& results_dir) {
  PhaseLengths lengths = from_results(results_dir);
  lengths.merge(shipped());
  return lengths;
}

bool PhaseLengths::same_records(const PhaseLengths& other) const {
  if (records_.size() != other.records_.size()) return false;
  std::vector<bool> used(other.records_.size(), false);
  for (const auto& r : records_) {
    bool found = false;
    for (std::size_t i = 0; i < other.records_.size() && !found; ++i) {
      const auto& q = other.records_[i];
      if (!used[i] && q.physics == r.physics && q.kt[0] == r.kt[0] && q.kt[1] == r.kt[1]) used[i] = found = true;
    }
    if (!found) return false;
  }
  return true;
}

void PhaseLengths::merge(const PhaseLengths& other) {
  const std::size_t own = records_.size();
  for (const auto& r : other.records_) {
    const auto same = [&r](const Record& q) { return q.physics == r.physics && q.kt[0] == r.kt[0] && q.kt[1] == r.kt[1]; };
    if (std::none_of(records_.begin(), records_.begin() + static_cast<long>(own), same)) records_.push_back(r);
  }
}

std::optional<double> PhaseLengths::expected_kt(const nlohmann::json& scene, bool recovery) const {
  const char* phase = recovery ? "recover" : first_phase(scene);
  const nlohmann::json::json_pointer p(std::string("/protocol/") + phase);
  if (!scene.contains(p)) return std::nullopt;
  const auto until = choice_from_name<StopCondition>(scene.at(p).value("until", ""));
  if (until != StopCondition::steady && until != StopCondition::settled) return std::nullopt;
  const Physics target = physics_of(scene);
  const int k = recovery ? 1 : 0;
  // A neighbour at another Ca: the part of its length past the steadiness window scaled by the
  // ratio of the Ca, since the capsule's elastic relaxation time is mu a / E_s = Ca / k.
  const double window = scene.at(p).value("window_kt", 0.0);
  std::vector<std::pair<double, double>> near;  // distance, length
  for (const auto& r : records_) {
    if (r.physics.dim != target.dim || r.physics.rule[k] != target.rule[k]) continue;
    const double beyond = std::max(0.0, r.kt[k] - window) * std::exp(target.log_Ca - r.physics.log_Ca);
    near.emplace_back(distance(r.physics, target), std::max(0.1, std::min(r.kt[k], window) + beyond));
  }
  if (near.empty()) return std::nullopt;
  const std::size_t n = std::min<std::size_t>(3, near.size());
  std::partial_sort(near.begin(), near.begin() + static_cast<long>(n), near.end());
  double weight = 0, sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 1.0 / (0.05 + near[i].first);
    weight += w;
    sum += w * std::log(near[i].second);
  }
  return std::min(std::exp(sum / weight), scene.at(p).value("max_kt", 1e300));
}

}  // namespace capsule::study
