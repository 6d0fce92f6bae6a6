#include "solver/scene/stretch_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "common/json_text.hpp"
#include "solver/scene/physical_cell.hpp"
#include "solver/scene/user_hints.hpp"
#include "solver/common/short_text.hpp"

namespace capsule {
namespace {

using nlohmann::json;

const std::vector<std::string> known_keys = {"force",     "force_pN", "patch_fraction", "contact_diameter",
                                             "contact_diameter_um", "until", "kt", "tolerance",
                                             "window_kt", "max_kt"};

// protocol.stretch's keys, each refusal naming the file, the key and the allowed range.
class StretchReader {
 public:
  StretchReader(const json& j, std::string source) : j_(j), source_(std::move(source)) {
    if (!j_.is_object()) fail("", "expected a JSON object", "an object {...}");
    for (auto it = j_.begin(); it != j_.end(); ++it)
      if (std::find(known_keys.begin(), known_keys.end(), it.key()) == known_keys.end()) {
        std::string list;
        for (const auto& k : known_keys) list += (list.empty() ? "" : ", ") + k;
        fail(it.key(), unknown_key_problem(it.key(), known_keys), list);
      }
  }
  [[noreturn]] void fail(const std::string& key, const std::string& problem, const std::string& allowed) const {
    throw SceneError(source_ + ": " + message_text(key.empty() ? "protocol.stretch" : "protocol.stretch." + key) +
                     ": " + problem + (allowed.empty() ? "" : " (allowed: " + allowed + ")"));
  }
  bool has(const std::string& key) const { return j_.contains(key); }
  // A number in [lo, hi] (open ends where asked); a missing key is `fallback`, or refused without one.
  double number(const std::string& key, std::optional<double> fallback, double lo, double hi, bool lo_open,
                bool hi_open) const {
    const std::string range = std::string(lo_open ? "(" : "[") + number_text(lo) + ", " + number_text(hi) + (hi_open ? ")" : "]");
    if (!has(key)) {
      if (!fallback) fail(key, "missing required key", range);
      return *fallback;
    }
    const json& v = j_.at(key);
    if (!v.is_number()) fail(key, "expected a number, got " + message_value(v), range);
    const double x = v.get<double>();
    if (!std::isfinite(x) || (lo_open ? x <= lo : x < lo) || (hi_open ? x >= hi : x > hi))
      fail(key, "value " + number_text(x) + " out of range", range);
    return x == 0.0 ? 0.0 : x;
  }
  StopCondition until() const {
    const std::string allowed = "time | steady";
    if (!has("until")) fail("until", "missing required key", allowed);
    const json& v = j_.at("until");
    const std::optional<StopCondition> c = v.is_string() ? choice_from_name<StopCondition>(v.get<std::string>()) : std::nullopt;
    if (c != StopCondition::time && c != StopCondition::steady) fail("until", "unknown value " + message_value(v), allowed);
    return *c;
  }

 private:
  const json& j_;
  std::string source_;
};

// The one key of two (or three) that may be given; refused when more than one is.
void at_most_one(const StretchReader& r, const std::vector<std::string>& keys) {
  std::vector<std::string> given;
  for (const auto& k : keys)
    if (r.has(k)) given.push_back(k);
  if (given.size() > 1) {
    std::string list;
    for (const auto& k : keys) list += (list.empty() ? "" : " or ") + k;
    r.fail(given[1], "given together with " + given[0], "one of " + list);
  }
}

// The rule that ends the loading: a time, or steady D_axial (its range over window_kt below tolerance).
PhaseSpec read_loading_phase(const StretchReader& r) {
  PhaseSpec p;
  p.until = r.until();
  p.kt = p.until == StopCondition::time ? r.number("kt", std::nullopt, 0.0, 1e4, true, false) : r.number("kt", 0.0, 0.0, 0.0, false, false);
  p.tolerance = r.number("tolerance", 1e-3, 0.0, 1.0, true, false);
  p.window_kt = r.number("window_kt", 2.0, 0.0, 100.0, true, false);
  p.max_kt = r.number("max_kt", 50.0, 0.0, 1e4, true, false);
  if (p.until == StopCondition::time && p.kt > p.max_kt) p.max_kt = p.kt;
  return p;
}

}  // namespace

double dimensionless_force(const Scene& scene, double force_pN) {
  const PhysicalGroups g = physical_groups(*scene.physical, scene.law, scene.conventions.sls_viscosity);
  return force_pN * 1e-12 / (g.E_s * scene.physical->radius_um * 1e-6);
}

StretchLoad read_stretch(const json& j, const std::string& source, const Scene& scene, PhaseSpec& phase) {
  const StretchReader r(j, source);
  if (scene.dim != 3)
    r.fail("", "the stretch protocol pulls a 3D membrane", "a stretch protocol with dim 3 only");
  const bool physical = scene.physical.has_value();
  at_most_one(r, {"force", "force_pN"});
  at_most_one(r, {"patch_fraction", "contact_diameter", "contact_diameter_um"});
  for (const char* key : {"force_pN", "contact_diameter_um"})
    if (!physical && r.has(key)) r.fail(key, "a value in physical units needs the scene's physical block", "no " + std::string(key) + " without physical");
  StretchLoad load;
  if (r.has("force_pN")) {
    load.force_pN = r.number("force_pN", std::nullopt, 0.0, 1e5, false, false);
    load.force_in_pN = true;
    load.force = dimensionless_force(scene, load.force_pN);
  } else {
    load.force = r.number("force", std::nullopt, 0.0, 1e3, false, false);
  }
  if (r.has("contact_diameter_um")) {
    const double radius = scene.physical->radius_um;
    load.contact_diameter_um = r.number("contact_diameter_um", std::nullopt, 0.0, 2.0 * radius, true, false);
    load.contact_diameter = load.contact_diameter_um / radius;
  } else if (r.has("contact_diameter")) {
    load.contact_diameter = r.number("contact_diameter", std::nullopt, 0.0, 2.0, true, false);
  } else {
    load.patch_fraction = r.number("patch_fraction", 0.02, 0.0, 0.5, true, true);
  }
  phase = read_loading_phase(r);
  return load;
}

json stretch_json(const StretchLoad& load, const PhaseSpec& phase) {
  json j = {{"until", choice_name(phase.until)}, {"kt", phase.kt}, {"tolerance", phase.tolerance},
            {"window_kt", phase.window_kt}, {"max_kt", phase.max_kt}};
  // The force and the patch as the scene gave them (the other form follows from them).
  if (load.force_in_pN) j["force_pN"] = load.force_pN;
  else j["force"] = load.force;
  if (load.contact_diameter_um > 0) j["contact_diameter_um"] = load.contact_diameter_um;
  else if (load.contact_diameter > 0) j["contact_diameter"] = load.contact_diameter;
  else j["patch_fraction"] = load.patch_fraction;
  return j;
}

}  // namespace capsule
