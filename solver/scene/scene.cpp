#include "solver/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "solver/ib/hydrodynamic_radius.hpp"
#include "common/json_text.hpp"
#include "solver/scene/refined_block_extent.hpp"
#include "solver/scene/run_bounds.hpp"
#include "solver/scene/stretch_scene.hpp"
#include "solver/scene/user_hints.hpp"
#include "solver/common/short_text.hpp"

namespace capsule {
namespace {

using nlohmann::json;

// -0.0 read as 0.0: the canonical text (and so the member id) of a scene must not depend on
// the sign of a zero, which changes nothing the solver computes.
double unsigned_zero(double x) { return x == 0.0 ? 0.0 : x; }

// Reads one JSON object, remembering which keys were used so the rest can be refused. A key
// the object does not know is refused first, before any missing or bad value (a misspelt
// "Eb" is named as such, with the key it is near, not reported as a missing "E_b").
class ObjectReader {
 public:
  ObjectReader(const json& j, std::string source, std::string path, std::vector<std::string> known)
      : j_(j), source_(std::move(source)), path_(std::move(path)), known_(std::move(known)) {
    if (!j_.is_object()) fail("", "expected a JSON object", "an object {...}");
    for (auto it = j_.begin(); it != j_.end(); ++it)
      if (std::find(known_.begin(), known_.end(), it.key()) == known_.end()) refuse_key(it.key());
  }

  [[noreturn]] void fail(const std::string& key, const std::string& problem,
                         const std::string& allowed) const {
    std::string where = path_.empty() ? key : (key.empty() ? path_ : path_ + "." + key);
    if (where.empty()) where = "(top level)";
    throw SceneError(source_ + ": " + message_text(where) + ": " + problem +
                     (allowed.empty() ? "" : " (allowed: " + allowed + ")"));
  }

  bool has(const std::string& key) {
    used_.insert(key);
    return j_.contains(key);
  }

  // A number in [lo, hi]; lo_open / hi_open make that end exclusive.
  double number(const std::string& key, std::optional<double> fallback, double lo, double hi,
                bool lo_open = false, bool hi_open = false) {
    std::string range = std::string(lo_open ? "(" : "[") + number_text(lo) + ", " + number_text(hi) + (hi_open ? ")" : "]");
    if (!has(key)) {
      if (!fallback) fail(key, "missing required key", range);
      return *fallback;
    }
    const json& v = j_.at(key);
    if (!v.is_number()) fail(key, "expected a number, got " + message_value(v), range);
    double x = v.get<double>();
    if (!std::isfinite(x) || (lo_open ? x <= lo : x < lo) || (hi_open ? x >= hi : x > hi))
      fail(key, "value " + number_text(x) + " out of range", range);
    return unsigned_zero(x);
  }

  int integer(const std::string& key, int fallback, int lo, int hi) {
    std::string range = "integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!has(key)) return fallback;
    const json& v = j_.at(key);
    if (!v.is_number() || std::floor(v.get<double>()) != v.get<double>())
      fail(key, "expected an integer, got " + message_value(v), range);
    double x = v.get<double>();
    if (x < lo || x > hi) fail(key, "value " + number_text(x) + " out of range", range);
    return static_cast<int>(x);
  }

  // A choice among `allowed` (names from the choice's table, in this order); a missing key is
  // `fallback`, or refused when there is none.
  template <class E>
  E choice(const std::string& key, std::optional<E> fallback, const std::vector<E>& allowed) {
    std::string list;
    for (const E a : allowed) list += (list.empty() ? "" : " | ") + choice_name(a);
    if (!has(key)) {
      if (!fallback) fail(key, "missing required key", list);
      return *fallback;
    }
    const json& v = j_.at(key);
    if (!v.is_string()) fail(key, "expected a string, got " + message_value(v), list);
    const std::optional<E> e = choice_from_name<E>(v.get<std::string>());
    for (const E a : allowed)
      if (e == a) return a;
    fail(key, "unknown value " + message_value(v), list);
  }

  std::vector<double> numbers(const std::string& key, std::vector<double> fallback, double lo,
                              double hi, std::size_t min_n, std::size_t max_n) {
    std::string range = std::to_string(min_n) + ".." + std::to_string(max_n) + " numbers in [" +
                        number_text(lo) + ", " + number_text(hi) + "]";
    if (!has(key)) return fallback;
    const json& v = j_.at(key);
    if (!v.is_array()) fail(key, "expected an array, got " + message_value(v), range);
    if (v.size() < min_n || v.size() > max_n)
      fail(key, "expected " + std::to_string(min_n) + ".." + std::to_string(max_n) +
                    " entries, got " + std::to_string(v.size()), range);
    std::vector<double> out;
    for (const auto& e : v) {
      if (!e.is_number()) fail(key, "expected numbers, got " + message_value(e), range);
      double x = e.get<double>();
      if (!std::isfinite(x) || x < lo || x > hi) fail(key, "value " + number_text(x) + " out of range", range);
      out.push_back(unsigned_zero(x));
    }
    return out;
  }

  // A nested object; missing -> empty object unless required.
  json object(const std::string& key, bool required) {
    if (!has(key)) {
      if (required) fail(key, "missing required key", "an object {...}");
      return json::object();
    }
    return j_.at(key);
  }

  std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const std::string& source() const { return source_; }

  // Refuses any key not read: a misspelt key must never be silently ignored.
  void refuse_unknown() const {
    for (auto it = j_.begin(); it != j_.end(); ++it)
      if (!used_.count(it.key())) refuse_key(it.key());
  }

 private:
  [[noreturn]] void refuse_key(const std::string& key) const {
    std::string list;
    for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
    fail(key, unknown_key_problem(key, known_), list);
  }

  const json& j_;
  std::string source_, path_;
  std::vector<std::string> known_;
  std::set<std::string> used_;
};

PhaseSpec read_phase(const json& j, const std::string& source, const std::string& path, bool shear) {
  using enum StopCondition;
  ObjectReader r(j, source, path,
                 shear ? std::vector<std::string>{"until", "kt", "value", "after_kt", "tolerance", "window_kt", "max_kt",
                                                  "oscillatory_period_kt"}
                       : std::vector<std::string>{"until", "kt", "value", "tolerance", "window_kt", "window_fraction",
                                                  "max_kt"});
  PhaseSpec p;
  p.until = shear ? r.choice<StopCondition>("until", std::nullopt, {time, steady, theta, beta})
                  : r.choice<StopCondition>("until", std::nullopt, {time, settled});
  if (p.until == time) {
    p.kt = r.number("kt", std::nullopt, shear ? 0.0 : 0.0, 1e4, shear, false);
  } else {
    p.kt = r.number("kt", 0.0, 0.0, 0.0);  // only meaningful for until time
  }
  if (p.until == theta || p.until == beta) {
    p.value = r.number("value", std::nullopt, -10.0, 10.0);
    p.after_kt = r.number("after_kt", 0.0, 0.0, 1e4);
  } else {
    p.value = r.number("value", 0.0, 0.0, 0.0);
  }
  p.tolerance = r.number("tolerance", 1e-3, 0.0, 1.0, true);
  p.window_kt = r.number("window_kt", 2.0, 0.0, 100.0, true);
  p.max_kt = r.number("max_kt", 50.0, 0.0, 1e4, true);
  if (p.until == time && p.kt > p.max_kt) p.max_kt = p.kt;
  if (p.after_kt >= p.max_kt)
    r.fail("after_kt", "the stop condition would never be tested before max_kt = " + std::to_string(p.max_kt),
           "[0, max_kt)");
  if (shear) {
    p.oscillatory_period_kt = r.number("oscillatory_period_kt", 0.0, 0.0, 1e4);
    r.refuse_unknown();
  } else {
    // A turning point of a slow recovery (a tank-treading biconcave capsule's D_xy falls for
    // ~15 kt, then rises for ~75 kt, Fig. 30) is stationary over any fixed short window; a
    // window that grows with the time since the stop is not fooled by it.
    p.window_fraction = p.until == settled ? r.number("window_fraction", 0.5, 0.0, 1.0) : r.number("window_fraction", 0.0, 0.0, 0.0);
    r.refuse_unknown();
  }
  return p;
}

// Keys the model of the other dimension reads are put back to their defaults, so the
// canonical scene -- and with it the member id -- does not depend on values this model
// ignores. 2D (simulation2d.cpp) reads none of C, G, c0, volume_penalty, power_law.n,
// mesh_level or snapshots (K > 0 and a delta other than peskin4 or cosine are refused
// above); 3D reads no segments.
void ignore_other_dimension(Scene& s) {
  const Scene defaults;
  if (s.dim == 2) {
    s.C = defaults.C;
    s.G = defaults.G;
    s.c0 = defaults.c0;
    s.volume_penalty = defaults.volume_penalty;
    s.power_law.n = defaults.power_law.n;
    s.resolution.mesh_level = defaults.resolution.mesh_level;
    s.output.snapshots = defaults.output.snapshots;
  } else {
    s.resolution.segments = defaults.resolution.segments;
  }
}

// dim and physics_version: what the rest of the scene's defaults depend on.
void read_dim_and_version(ObjectReader& r, const json& j, Scene& s) {
  s.dim = r.integer("dim", 0, 2, 3);
  if (!r.has("dim")) r.fail("dim", "missing required key", "2 | 3");
  // The physics the scene runs: this solver's (the default), or version 5's defaults, so that
  // a campaign run before version 6 keeps its members' ids and numbers until it is rerun.
  if (r.has("physics_version")) {
    const json& v = j.at("physics_version");
    const std::string text = v.is_string() ? v.get<std::string>()
                             : v.is_number_integer() ? std::to_string(v.get<long long>()) : std::string();
    const std::optional<PhysicsVersion> version = choice_from_name<PhysicsVersion>(text);
    if (!version)
      r.fail("physics_version", "physics version " + message_value(v) + " is not one this solver runs",
             std::string("\"") + capsule::physics_version + "\" (this solver's) or \"5\"");
    s.physics_version = *version;
  }
  // The dissertation's numerics (numerics_preset.hpp): defaults only, on this solver's physics.
  s.numerics = r.choice<Numerics>("numerics", Numerics::toolkit, {Numerics::toolkit, Numerics::dissertation});
  if (s.numerics == Numerics::dissertation && s.physics_version != PhysicsVersion::current)
    r.fail("numerics", "the dissertation's numerics are a preset of this solver's physics, not of version 5's",
           std::string("\"toolkit\" with physics_version \"5\", or physics_version \"") + capsule::physics_version + "\"");
}

// The defaults of the scene's dimension, physics version and numerics.
SceneDefaults defaults_for(const Scene& s) {
  return s.numerics == Numerics::dissertation ? dissertation_scene_defaults(s.dim, s.shape)
                                              : scene_defaults(s.physics_version, s.dim);
}

// The capsule: shape, law and the dimensionless groups (34)-(36), (60)-(67), (84).
void read_capsule(ObjectReader& r, Scene& s) {
  if (s.dim == 2) {
    s.shape = r.choice<Shape>("shape", std::nullopt, {Shape::circle, Shape::biconcave});
    s.law = r.choice<MembraneLaw>("law", MembraneLaw::hooke, {MembraneLaw::hooke});
  } else {
    s.shape = r.choice<Shape>("shape", std::nullopt, {Shape::sphere, Shape::biconcave});
    s.law = r.choice<MembraneLaw>("law", s.shape == Shape::sphere ? MembraneLaw::neo_hookean : MembraneLaw::skalak,
                                  {MembraneLaw::neo_hookean, MembraneLaw::skalak});
  }
  s.C = r.number("C", 15.0, 0.0, 1e3, true);
  s.Re = r.number("Re", s.numerics == Numerics::dissertation ? dissertation_Re(s.dim, s.shape) : 0.05, 0.0, 10.0, true);
  // With a physical block these four come from it (read_physical); NaN marks "not given".
  const std::optional<double> from_physical =
      r.has("physical") ? std::optional<double>(std::nan("")) : std::nullopt;
  s.Ca = r.number("Ca", from_physical, 0.0, 10.0, true);
  s.E_b = r.number("E_b", from_physical, 0.0, 10.0);
  s.V = r.number("V", from_physical, 0.0, 100.0, true);
  s.eta = r.number("eta", from_physical, 0.0, 1e3);
  s.G = r.number("G", 50.0, 0.0, 1e4, true);
  s.c0 = r.number("c0", 0.0, -10.0, 10.0);
  using enum ReferenceCase;
  if (s.dim == 3) {
    s.reference_case = r.choice<ReferenceCase>("reference_case", none, {none, A, B, C});
    if (s.reference_case != none && s.shape != Shape::biconcave)
      r.fail("reference_case", "case " + choice_name(s.reference_case) + " needs shape \"biconcave\"",
             "none for a sphere");
  } else {
    s.reference_case = r.choice<ReferenceCase>("reference_case", none, {none});
  }
  s.volume_penalty = r.number("volume_penalty", 0.0, 0.0, 1e6);
}

// physical: a 3D cell in physical units, converted once to the groups (34)-(36) and the Reynolds
// number the lattice runs at (solver/scene/physical_cell.hpp, docs/guide/physical_units.md).
// A group the scene also gives must be the one the block gives (the canonical scene has both).
void read_physical(ObjectReader& r, Scene& s) {
  if (!r.has("physical")) return;
  const json block = r.object("physical", true);
  ObjectReader p(block, r.source(), "physical",
                 {"radius_um", "shear_modulus_uN_per_m", "bending_modulus_J", "bending_modulus_kT", "temperature_K",
                  "plasma_viscosity_mPa_s", "cytoplasm_viscosity_mPa_s", "membrane_viscosity_uN_s_per_m",
                  "shear_rate_per_s", "density_kg_per_m3"});
  if (s.dim != 3)
    p.fail("", "physical units are for the 3D cell (a 2D capsule's moduli are per unit length of a ring)",
           "no physical block in 2D");
  PhysicalCell c;
  c.radius_um = p.number("radius_um", std::nullopt, 0.0, 1e3, true);
  c.shear_modulus_uN_per_m = p.number("shear_modulus_uN_per_m", std::nullopt, 0.0, 1e6, true);
  if (p.has("bending_modulus_J") && p.has("bending_modulus_kT"))
    p.fail("bending_modulus_kT", "the bending modulus is given twice", "bending_modulus_J or bending_modulus_kT");
  c.bending_modulus_J = p.number("bending_modulus_J", 0.0, 0.0, 1e-12);
  c.bending_modulus_kT = p.number("bending_modulus_kT", 0.0, 0.0, 1e8);
  c.temperature_K = p.number("temperature_K", c.bending_modulus_kT > 0 ? std::nullopt : std::optional<double>(0.0),
                             0.0, 1e4, true);
  c.plasma_viscosity_mPa_s = p.number("plasma_viscosity_mPa_s", std::nullopt, 0.0, 1e6, true);
  c.cytoplasm_viscosity_mPa_s = p.number("cytoplasm_viscosity_mPa_s", c.plasma_viscosity_mPa_s, 0.0, 1e6, true);
  c.membrane_viscosity_uN_s_per_m = p.number("membrane_viscosity_uN_s_per_m", 0.0, 0.0, 1e6);
  c.shear_rate_per_s = p.number("shear_rate_per_s", std::nullopt, 0.0, 1e7, true);
  c.density_kg_per_m3 = p.number("density_kg_per_m3", 1000.0, 0.0, 1e5, true);
  p.refuse_unknown();
  const PhysicalGroups g = physical_groups(c, s.law, s.conventions.sls_viscosity);
  const auto take = [&](const std::string& key, double& field, double derived, double lo, double hi, bool lo_open) {
    const std::string range = std::string(lo_open ? "(" : "[") + number_text(lo) + ", " + number_text(hi) + "]";
    if (!std::isfinite(derived) || (lo_open ? derived <= lo : derived < lo) || derived > hi)
      p.fail("", "the cell gives " + key + " = " + number_text(derived) + ", outside the solver's range",
             key + " in " + range + ": change the moduli, viscosities, radius or shear rate");
    if (!std::isnan(field) && std::abs(field - derived) > 1e-12 * std::abs(derived))
      r.fail(key, key + " = " + number_text(field) + " is not the physical block's " + number_text(derived),
             "leave " + key + " out with a physical block, or give the value it gives");
    field = derived;
  };
  take("Ca", s.Ca, g.Ca, 0.0, 10.0, true);
  take("E_b", s.E_b, g.E_b, 0.0, 10.0, false);
  take("V", s.V, g.V, 0.0, 100.0, true);
  take("eta", s.eta, g.eta, 0.0, 1e3, false);
  if (g.Re > 10.0)
    p.fail("shear_rate_per_s", "the cell's own Reynolds number rho k a^2 / mu_a = " + number_text(g.Re) +
                                   " is above the solver's range",
           "rho k a^2 / mu_a <= 10");
  s.Re = lattice_Re(g, s.Re);
  s.physical = c;
}

// power_law: (102) and where it acts.
void read_power_law(ObjectReader& r, Scene& s, const SceneDefaults& defaults) {
  using enum PowerLawModel;
  json pl = r.object("power_law", false);
  ObjectReader p(pl, r.source(), r.child_path("power_law"), {"K", "n", "model"});
  s.power_law.K = p.number("K", 0.0, 0.0, 1e3);
  s.power_law.n = p.number("n", 1.0, 0.0, 3.0, true);
  // membrane by default (physics version 6): it converges with a and does not move with the
  // fluid's tau, where the text's shell (103)-(104) does both (docs/findings/accuracy_and_stability.md).
  s.power_law.model = p.choice<PowerLawModel>("model", defaults.power_law_model, {fluid_shell, membrane});
  // The 2D driver refuses it (simulation2d.cpp); `capsule check` and `study plan` must too.
  if (s.dim == 2 && s.power_law.K > 0)
    p.fail("K", "the power-law membrane viscosity (Sec. 5.2) is a 3D model; in 2D use eta (Kelvin-Voigt)",
           "0 in 2D");
  // The membrane reading is the standard linear solid's Maxwell element with a power-law
  // viscosity: it replaces the Kelvin-Voigt eta, it is not added to it.
  if (s.power_law.model == membrane && s.power_law.K > 0 && s.eta > 0)
    p.fail("model", "\"membrane\" puts the power law in the membrane's own viscous element, which eta = " +
                        std::to_string(s.eta) + " already sets",
           "eta = 0 with model \"membrane\", or model \"fluid_shell\"");
  if (s.power_law.model == membrane && s.power_law.K > 0 && !(s.G > 0))
    p.fail("model", "\"membrane\" needs the Maxwell modulus G = E_m / E_s > 0", "G > 0");
  if (!(s.power_law.K > 0)) s.power_law.model = defaults.power_law_model;  // no power law: the key means nothing
  p.refuse_unknown();
}

// conventions: the dissertation's readings beside the physical ones (docs/conventions.md).
void read_conventions(ObjectReader& r, Scene& s) {
  json conv = r.object("conventions", false);
  ObjectReader c(conv, r.source(), r.child_path("conventions"), {"sls_viscosity", "E_b_2d", "biconcave_2d"});
  // Under the dissertation's numerics the text's readings are the defaults of the dimension they apply to.
  const bool text = s.numerics == Numerics::dissertation;
  s.conventions.sls_viscosity = c.choice<SlsViscosity>(
      "sls_viscosity", text && s.dim == 3 ? SlsViscosity::dissertation : SlsViscosity::physical,
      {SlsViscosity::physical, SlsViscosity::dissertation});
  s.conventions.E_b_2d = c.choice<BendingConvention2d>(
      "E_b_2d", text && s.dim == 2 && s.shape == Shape::biconcave ? BendingConvention2d::dissertation
                                                                 : BendingConvention2d::dimensionless,
      {BendingConvention2d::dimensionless, BendingConvention2d::dissertation});
  if (s.dim == 2 && s.conventions.sls_viscosity != SlsViscosity::physical)
    c.fail("sls_viscosity", "the standard linear solid is the 3D membrane's", "\"physical\" in 2D");
  if (s.dim == 3 && s.conventions.E_b_2d != BendingConvention2d::dimensionless)
    c.fail("E_b_2d", "the 2D bending convention does not apply to a 3D scene", "\"dimensionless\" in 3D");
  s.conventions.biconcave_2d = c.choice<BiconcaveSize2d>(
      "biconcave_2d", text && s.dim == 2 && s.shape == Shape::biconcave ? BiconcaveSize2d::dissertation : BiconcaveSize2d::equivalent,
                                             {BiconcaveSize2d::equivalent, BiconcaveSize2d::dissertation});
  if (s.conventions.biconcave_2d != BiconcaveSize2d::equivalent && (s.dim != 2 || s.shape != Shape::biconcave))
    c.fail("biconcave_2d", "the size reading of (24)-(25) applies to the 2D biconcave capsule only",
           "\"equivalent\" unless dim is 2 and shape is \"biconcave\"");
  c.refuse_unknown();
}

// resolution: the lattice (a, domain, membrane discretisation, tau).
void read_lattice(ObjectReader& q, const json& block, int dim, Scene::Resolution& res, const SceneDefaults& defaults) {
  res.a = q.number("a", defaults.a, 2.0, 200.0);
  res.domain = q.numbers("domain", defaults.domain, 3.0, 100.0, dim, dim);
  res.segments = q.integer("segments", 140, 16, 100000);
  res.mesh_level = q.integer("mesh_level", 4, 0, 6);
  if (q.has("tau")) {
    const json& t = block.at("tau");
    const std::string allowed = "0 (chosen by the solver) or [0.505, 10]";
    if (!t.is_number()) q.fail("tau", "expected a number, got " + message_value(t), allowed);
    if (t.get<double>() != 0.0 && (t.get<double>() < 0.505 || t.get<double>() > 10.0))
      q.fail("tau", "relaxation time " + message_value(t) + " cannot be run stably", allowed);
    res.tau = unsigned_zero(t.get<double>());
  }
}

// resolution: the IB delta, the fluid's precision and the membrane update (20).
void read_delta_and_update(ObjectReader& q, int dim, Scene::Resolution& res, const SceneDefaults& defaults) {
  using enum ib::Delta;
  // 3D: Roma, Peskin and Berger's 3-point delta by default (physics version 6): with the
  // stresslet's marker inset it has the smaller finite-Ca error of the two measured deltas at
  // 27 nodes a stencil instead of 64 (docs/findings/immersed_boundary_error_budget.md).
  res.delta = q.choice<ib::Delta>("kernel", defaults.delta, {peskin4, roma3, linear2, cosine, keys4});
  // The 2D driver's approximate Kelvin-Voigt step uses the self-mobility sum phi^2 = (3/8)^2 at a
  // node, which peskin4 and the text's cosine (18) share (simulation2d.cpp); the others are 3D only.
  if (dim == 2 && res.delta != peskin4 && res.delta != cosine)
    q.fail("kernel", "kernel \"" + choice_name(res.delta) + "\" is 3D only", "\"peskin4\" or \"cosine\" in 2D");
  // 3D single by default (campaigns/precision_*.json: steady D_xy and fitted times within 1e-4
  // relative of double, the fluid about 2x faster); 2D double (cheap, its campaigns ran so).
  res.precision = q.choice<lbm::Precision>("precision", defaults.precision,
                                         {lbm::Precision::double_precision, lbm::Precision::single_precision});
  using enum ib::MembraneUpdate;
  res.membrane_update =
      q.choice<ib::MembraneUpdate>("membrane_update", euler, {euler, previous_velocity, adams_bashforth2});
  if (dim == 2 && res.membrane_update != euler)
    q.fail("membrane_update", "membrane update \"" + choice_name(res.membrane_update) + "\" is 3D only", "\"euler\" in 2D");
}

// resolution.marker_inset: markers inside the radius (the immersed boundary's hydrodynamic
// radius is larger than its markers': capsule rigid-sphere,
// docs/findings/immersed_boundary_error_budget.md). 3D default the stresslet's rule
// (solver/ib/hydrodynamic_radius.hpp) where the delta's shell was measured, else 0; 2D 0; a
// number sets it in lattice units.
void read_marker_inset(ObjectReader& q, const json& block, int dim, Scene::Resolution& res, const SceneDefaults& defaults) {
  using enum MarkerInsetRule;
  res.marker_inset_rule = defaults.marker_inset_rule == stresslet && ib::stresslet_radius_gap(res.delta) ? stresslet : given;
  res.marker_inset = 0.0;
  if (q.has("marker_inset")) {
    const json& m = block.at("marker_inset");
    if (m.is_string() && choice_from_name<MarkerInsetRule>(m.get<std::string>()) == stresslet) {
      res.marker_inset_rule = stresslet;
    } else if (m.is_number()) {
      res.marker_inset_rule = given;
      res.marker_inset = q.number("marker_inset", 0.0, 0.0, 2.0);
    } else {
      q.fail("marker_inset", "marker inset " + message_value(m) + " is neither a number nor a rule",
             "\"stresslet\" or a number in [0, 2]");
    }
  }
  if (res.marker_inset_rule == stresslet) {
    const std::string delta = choice_name(res.delta);
    const auto gap = dim == 3 ? ib::stresslet_radius_gap(res.delta) : ib::stresslet_radius_gap_2d(res.delta);
    if (!gap)
      q.fail("marker_inset", std::string("the stresslet's inset is measured for the kernels ") +
                                 (dim == 3 ? "peskin4, roma3 and keys4" : "peskin4") + " in " + std::to_string(dim) +
                                 "D, not \"" + delta + "\"",
             "a number in [0, 2] with kernel \"" + delta + "\"");
    res.marker_inset = ib::stresslet_marker_inset(*gap, res.a);
    if (!(res.marker_inset >= 0.0))
      q.fail("marker_inset", "the stresslet's inset has no solution at a = " + std::to_string(res.a) + " with kernel " + delta,
             "a >= " + std::to_string(ib::stresslet_inset_min_radius(*gap)) + ", or a number in [0, 2]");
  }
  if (res.marker_inset > 0.25 * res.a)
    q.fail("marker_inset", "marker inset " + std::to_string(res.marker_inset) + " is more than a quarter of a", "[0, a/4]");
}

// resolution: the 2D Kelvin-Voigt step (31) and the 3D fluid's relaxation rates.
void read_viscous_steps(ObjectReader& q, int dim, Scene::Resolution& res, const SceneDefaults& defaults) {
  using enum KelvinVoigtStep;
  // exact_mobility by default in 2D (physics version 6): stable at any eta, and the eta <= 12
  // members move by less than 0.5 % (docs/findings/kelvin_voigt_2d.md).
  res.kelvin_voigt_step = q.choice<KelvinVoigtStep>("kelvin_voigt_step", defaults.kelvin_voigt_step,
                                                  {approximate_mobility, exact_mobility});
  if (dim == 3 && res.kelvin_voigt_step != approximate_mobility)
    q.fail("kelvin_voigt_step",
           "Kelvin-Voigt step \"" + choice_name(res.kelvin_voigt_step) +
               "\" is the 2D membrane's (the 3D membrane's viscosity is the standard linear solid)",
           "\"approximate_mobility\" in 3D");
  // The text's MRT, or TRT with the odd moments at Lambda = 3/16, which keeps a viscosity
  // contrast independent of tau. 3D only: the text's D2Q9 rates are a TRT already (q by (9) is
  // Lambda = 1/12 at every s_nu).
  using enum lbm::CollisionModel;
  res.collision = q.choice<lbm::CollisionModel>("collision", defaults.collision, {mrt, trt});
  if (dim == 2 && res.collision != mrt)
    q.fail("collision", "the 2D rates (9) are a two-relaxation-time collision already (Lambda = 1/12)", "\"mrt\" in 2D");
}

// resolution.refine (3D): the fluid at half the spacing and time step in a block about the
// capsule (solver/scene/refined_block_extent.hpp, docs/guide/refinement.md "In a scene"); a is
// the fine lattice's radius. What the refined fluid does not hold yet is refused by its key.
void read_refine(ObjectReader& q, const json& block, Scene& s) {
  if (!q.has("refine")) return;
  if (s.dim != 3) q.fail("refine", "the refined block is built for the 3D fluid only", "no refine key in 2D");
  ObjectReader f(block.at("refine"), q.source(), q.child_path("refine"), {"levels", "margin"});
  Scene::Resolution& res = s.resolution;
  SceneRefinement spec;
  spec.levels = f.integer("levels", spec.levels, 1, 1);
  const double max_margin = 4.0;
  spec.margin = f.number("margin", spec.margin, refined_block_min_margin(res), max_margin);
  f.refuse_unknown();
  res.refine = spec;
  if (s.V != 1.0)
    q.fail("refine", "the viscosity contrast (V = " + number_text(s.V) + ") is not built on the refined block yet", "no refine key unless V = 1");
  if (s.power_law.K > 0 && s.power_law.model == PowerLawModel::fluid_shell)
    q.fail("refine", "the power law's fluid shell (a viscosity field on the lattice) is not built on the refined block yet",
           "no refine key with power_law.model \"fluid_shell\" and K > 0");
  const RefinedBlockPlan plan = refined_block_extent(s);
  if (!plan.why.empty()) {
    if (plan.why.rfind("the domain", 0) == 0) q.fail("refine", plan.why, "a x domain even on every axis");
    f.fail("margin", plan.why, "[" + number_text(refined_block_min_margin(res)) + ", " + number_text(plan.max_margin) + "] in this channel");
  }
}

void read_resolution(ObjectReader& r, Scene& s, const SceneDefaults& defaults) {
  json block = r.object("resolution", false);
  ObjectReader q(block, r.source(), r.child_path("resolution"),
                 {"a", "domain", "segments", "mesh_level", "tau", "kernel", "precision", "membrane_update",
                  "marker_inset", "kelvin_voigt_step", "collision", "refine"});
  // A refined scene defaults to double precision (its first members ran so; single stores the
  // populations as floats, docs/guide/refinement.md).
  SceneDefaults d = defaults;
  if (block.is_object() && block.contains("refine")) d.precision = lbm::Precision::double_precision;
  read_lattice(q, block, s.dim, s.resolution, d);
  read_delta_and_update(q, s.dim, s.resolution, d);
  read_marker_inset(q, block, s.dim, s.resolution, d);
  read_viscous_steps(q, s.dim, s.resolution, d);
  read_refine(q, block, s);
  q.refuse_unknown();
}

// protocol: the shear phase (or the stretch, 3D: solver/scene/stretch_scene.hpp), then the
// recovery. `scene`'s dim, law and physical block are already read.
void read_protocol(ObjectReader& r, const Scene& scene, Scene::Protocol& protocol) {
  const std::string& source = r.source();
  json proto = r.object("protocol", true);
  ObjectReader p(proto, source, "protocol", {"shear", "stretch", "recover"});
  if (p.has("stretch")) {
    if (p.has("shear")) p.fail("stretch", "a protocol shears or stretches, not both", "\"shear\" or \"stretch\"");
    protocol.stretch = read_stretch(proto.at("stretch"), source, scene, protocol.shear);
  } else {
    protocol.shear = read_phase(p.object("shear", true), source, "protocol.shear", true);
  }
  protocol.recover = read_phase(p.object("recover", true), source, "protocol.recover", false);
  p.refuse_unknown();
}

// output: the rows' spacing, the stored shapes and the snapshots.
void read_output(ObjectReader& r, Scene::Output& output) {
  json out = r.object("output", false);
  ObjectReader o(out, r.source(), "output", {"interval_kt", "shapes_at_kt", "snapshots"});
  output.interval_kt = o.number("interval_kt", 0.05, 0.0, 10.0, true);
  output.shapes_at_kt = o.numbers("shapes_at_kt", {}, 0.0, 1e5, 0, 10000);
  output.snapshots = o.choice<Snapshots>("snapshots", Snapshots::none, {Snapshots::none, Snapshots::vtk});
  o.refuse_unknown();
}

}  // namespace

Scene Scene::from_json(const json& j, const std::string& source) {
  ObjectReader r(j, source, "",
                 {"dim", "physics_version", "numerics", "shape", "law", "C", "Re", "Ca", "E_b", "V", "eta", "G", "c0",
                  "reference_case", "volume_penalty", "power_law", "conventions", "resolution", "protocol", "output",
                  "physical"});
  Scene s;
  read_dim_and_version(r, j, s);
  read_capsule(r, s);
  const SceneDefaults defaults = defaults_for(s);  // the preset's depend on the shape
  read_conventions(r, s);
  read_physical(r, s);
  read_power_law(r, s, defaults);
  read_resolution(r, s, defaults);
  read_protocol(r, s, s.protocol);
  read_output(r, s.output);
  r.refuse_unknown();
  ignore_other_dimension(s);
  check_run_bounds(s, source);
  return s;
}

Scene Scene::load(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SceneError(path + ": is a folder, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file: " + unreadable_file_reason(path));
  std::ostringstream text;
  text << in.rdbuf();
  json j;
  try {
    j = parse_json_text(text.str(), path);
  } catch (const JsonTextError& e) {
    throw SceneError(e.what());
  }
  if (document_kind(j) == "campaign")
    throw SceneError(path + ": this is a campaign file, not a scene: run it with "
                     "`study run " + path + "`, or give capsule one member's scene.json");
  return from_json(j, path);
}

namespace {
// The writers, one per section. Version 5's canonical text is kept key for key: a key it did
// not know, or that held its default, is left out, so the ids of its members stay
// (Scene::omitted_defaults()). Later versions write every key: a key's default may change with
// the physics version, and the id must say what ran. Each value is written with its C++ type,
// so "a": 10 and "a": 10.0 give the same canonical text.

// The capsule's keys, at the top level.
void write_capsule(const Scene& s, json& j) {
  j["dim"] = s.dim;
  j["shape"] = choice_name(s.shape);
  j["law"] = choice_name(s.law);
  j["C"] = s.C;
  j["Re"] = s.Re;
  j["Ca"] = s.Ca;
  j["E_b"] = s.E_b;
  j["V"] = s.V;
  j["eta"] = s.eta;
  j["G"] = s.G;
  j["c0"] = s.c0;
  j["reference_case"] = choice_name(s.reference_case);
  j["volume_penalty"] = s.volume_penalty;
}

json power_law_json(const Scene::PowerLaw& p, PhysicsVersion version) {
  json j = {{"K", p.K}, {"n", p.n}};
  if (version != PhysicsVersion::v5 || p.model != PowerLawModel::fluid_shell) j["model"] = choice_name(p.model);
  return j;
}

json conventions_json(const Scene::Conventions& c, PhysicsVersion version) {
  json j = {{"sls_viscosity", choice_name(c.sls_viscosity)}, {"E_b_2d", choice_name(c.E_b_2d)}};
  if (version != PhysicsVersion::v5 || c.biconcave_2d != BiconcaveSize2d::equivalent)
    j["biconcave_2d"] = choice_name(c.biconcave_2d);
  return j;
}

// Version 5's resolution: the keys it knew, the later ones only where off their default.
json resolution_json_v5(const Scene::Resolution& r, int dim) {
  json j = {{"a", r.a}, {"domain", r.domain}, {"segments", r.segments},
            {"mesh_level", r.mesh_level}, {"tau", r.tau}, {"kernel", choice_name(r.delta)}};
  if (dim == 3 || r.precision != lbm::Precision::double_precision) j["precision"] = choice_name(r.precision);
  if (r.membrane_update != ib::MembraneUpdate::euler) j["membrane_update"] = choice_name(r.membrane_update);
  if (r.marker_inset_rule != MarkerInsetRule::given) j["marker_inset"] = choice_name(r.marker_inset_rule);
  else if (r.marker_inset != 0.0) j["marker_inset"] = r.marker_inset;
  if (r.kelvin_voigt_step != KelvinVoigtStep::approximate_mobility)
    j["kelvin_voigt_step"] = choice_name(r.kelvin_voigt_step);
  if (r.collision != lbm::CollisionModel::mrt) j["collision"] = choice_name(r.collision);
  return j;
}

json resolution_json(const Scene::Resolution& r, int dim, PhysicsVersion version) {
  if (version == PhysicsVersion::v5) return resolution_json_v5(r, dim);
  json j = {{"a", r.a}, {"domain", r.domain}, {"segments", r.segments},
            {"mesh_level", r.mesh_level}, {"tau", r.tau}, {"kernel", choice_name(r.delta)},
            {"precision", choice_name(r.precision)}, {"membrane_update", choice_name(r.membrane_update)},
            {"kelvin_voigt_step", choice_name(r.kelvin_voigt_step)}, {"collision", choice_name(r.collision)}};
  // The rule's name where a rule set it (its value follows from a and the delta), else the number.
  if (r.marker_inset_rule == MarkerInsetRule::given) j["marker_inset"] = r.marker_inset;
  else j["marker_inset"] = choice_name(r.marker_inset_rule);
  // Written only when given: it changes the numerics, so the ids of the members that set it,
  // and of no other.
  if (r.refine) j["refine"] = {{"levels", r.refine->levels}, {"margin", r.refine->margin}};
  return j;
}

// Written only when given, so the ids of scenes without it stay; one bending key, the one given.
json physical_json(const PhysicalCell& c) {
  json j = {{"radius_um", c.radius_um}, {"shear_modulus_uN_per_m", c.shear_modulus_uN_per_m},
            {"plasma_viscosity_mPa_s", c.plasma_viscosity_mPa_s}, {"cytoplasm_viscosity_mPa_s", c.cytoplasm_viscosity_mPa_s},
            {"membrane_viscosity_uN_s_per_m", c.membrane_viscosity_uN_s_per_m}, {"shear_rate_per_s", c.shear_rate_per_s},
            {"density_kg_per_m3", c.density_kg_per_m3}};
  if (c.bending_modulus_kT > 0) j["bending_modulus_kT"] = c.bending_modulus_kT;
  else j["bending_modulus_J"] = c.bending_modulus_J;
  if (c.temperature_K > 0) j["temperature_K"] = c.temperature_K;
  return j;
}

json phase_json(const PhaseSpec& p, bool shear) {
  json j = {{"until", choice_name(p.until)}, {"kt", p.kt}, {"value", p.value}, {"tolerance", p.tolerance},
            {"window_kt", p.window_kt}, {"max_kt", p.max_kt}};
  if (shear) j["oscillatory_period_kt"] = p.oscillatory_period_kt;
  else j["window_fraction"] = p.window_fraction;
  // Written only when set, so the ids of members run before the key stay.
  if (shear && p.after_kt > 0) j["after_kt"] = p.after_kt;
  return j;
}

// A stretch protocol in place of the shear; a scene without one is written as before.
json protocol_json(const Scene::Protocol& p) {
  if (p.stretch) return {{"stretch", stretch_json(*p.stretch, p.shear)}, {"recover", phase_json(p.recover, false)}};
  return {{"shear", phase_json(p.shear, true)}, {"recover", phase_json(p.recover, false)}};
}

json output_json(const Scene::Output& o) {
  return {{"interval_kt", o.interval_kt}, {"shapes_at_kt", o.shapes_at_kt}, {"snapshots", choice_name(o.snapshots)}};
}
}  // namespace

json Scene::to_json() const {
  json j;
  write_capsule(*this, j);
  j["power_law"] = power_law_json(power_law, physics_version);
  j["conventions"] = conventions_json(conventions, physics_version);
  j["resolution"] = resolution_json(resolution, dim, physics_version);
  if (physical) j["physical"] = physical_json(*physical);
  j["protocol"] = protocol_json(protocol);
  j["output"] = output_json(output);
  // The member id hashes the scene without this key and with the version after it
  // (study/campaign/member_id.cpp); it is here so that the solver runs what study planned.
  j["physics_version"] = choice_name(physics_version);
  // Written only under the preset, so the ids of the toolkit's scenes stay; the preset's values
  // are in the keys above as well, and the name says which defaults they came from.
  if (numerics != Numerics::toolkit) j["numerics"] = choice_name(numerics);
  return j;
}

const std::map<std::string, json>& Scene::omitted_defaults(int dim) {
  // Version 5's defaults of the keys its canonical text left out while they held them.
  const auto table = [](int d) {
    const SceneDefaults v5 = scene_defaults(PhysicsVersion::v5, d);
    std::map<std::string, json> m = {{"power_law.model", choice_name(v5.power_law_model)},
                                     {"conventions.biconcave_2d", choice_name(BiconcaveSize2d::equivalent)},
                                     {"resolution.membrane_update", choice_name(ib::MembraneUpdate::euler)},
                                     {"resolution.marker_inset", 0.0},
                                     {"resolution.kelvin_voigt_step", choice_name(v5.kelvin_voigt_step)},
                                     {"resolution.collision", choice_name(v5.collision)}};
    if (d == 2) m["resolution.precision"] = choice_name(v5.precision);  // always written in 3D
    return m;
  };
  static const std::map<std::string, json> d2 = table(2), d3 = table(3);
  return dim == 2 ? d2 : d3;
}

std::vector<int> Scene::grid() const {
  std::vector<int> n(3, 1);
  for (int d = 0; d < dim; ++d) n[d] = static_cast<int>(std::lround(resolution.domain[d] * resolution.a));
  return n;
}

}  // namespace capsule
