#include "analysis/report/analysis_block.hpp"

#include <algorithm>
#include <regex>
#include <set>
#include <stdexcept>

#include "analysis/report/experiment_data.hpp"
#include "analysis/report/published_curves.hpp"

namespace capsule::analysis {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& path, const std::string& what) {
  throw std::invalid_argument(where + ": /analysis" + path + ": " + what);
}

void only_keys(const nlohmann::json& j, const std::set<std::string>& allowed, const std::string& where,
               const std::string& path) {
  for (const auto& [key, value] : j.items()) {
    (void)value;
    if (!allowed.count(key)) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(where, path + "/" + key, "unknown key (allowed: " + list + ")");
    }
  }
}

std::vector<std::string> string_array(const nlohmann::json& j, const std::string& where, const std::string& path,
                                      bool non_empty) {
  if (!j.is_array()) fail(where, path, "expected an array of strings");
  if (non_empty && j.empty()) fail(where, path, "expected a non-empty array of strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_string()) fail(where, path + "/" + std::to_string(i), "expected a string");
    out.push_back(j[i].get<std::string>());
  }
  return out;
}

std::string a_string(const nlohmann::json& j, const std::string& where, const std::string& path) {
  if (!j.is_string() || j.get<std::string>().empty()) fail(where, path, "expected a non-empty string");
  return j.get<std::string>();
}

// "<fit>.<time>" naming a fit listed in `fits`.
void check_column(const std::string& column, const std::vector<std::string>& fits, const std::string& where,
                  const std::string& path) {
  const auto dot = column.find('.');
  const std::string fit = dot == std::string::npos ? "" : column.substr(0, dot);
  const std::string time = dot == std::string::npos ? "" : column.substr(dot + 1);
  std::string allowed;
  for (const auto& f : known_fits())
    for (const auto& t : times_of_fit(f)) allowed += (allowed.empty() ? "" : ", ") + f + "." + t;
  const auto times = times_of_fit(fit);
  if (std::find(times.begin(), times.end(), time) == times.end())
    fail(where, path, "expected \"<fit>.<time>\", one of " + allowed + "; got \"" + column + "\"");
  if (std::find(fits.begin(), fits.end(), fit) == fits.end())
    fail(where, path, "the fit \"" + fit + "\" is not listed in /analysis/fits");
}

// A quantity for the ladder and accuracy analyses: a fitted time of a listed fit or a marker.
void check_quantity(const std::string& q, const std::vector<std::string>& fits, const std::string& where,
                    const std::string& path) {
  const auto& markers = marker_quantities();
  if (std::find(markers.begin(), markers.end(), q) != markers.end()) return;
  if (q.find('.') == std::string::npos)
    fail(where, path, "expected a marker (D_stop, D_max, D_inf) or \"<fit>.<time>\"; got \"" + q + "\"");
  check_column(q, fits, where, path);
}

double a_number(const nlohmann::json& j, const std::string& where, const std::string& path) {
  if (!j.is_number()) fail(where, path, "expected a number");
  return j.get<double>();
}

// A dotted scene key such as "resolution.a": letters, digits and _ between dots.
std::string a_dotted_key(const nlohmann::json& j, const std::string& where, const std::string& path) {
  static const std::regex key_pattern("[A-Za-z_][A-Za-z0-9_]*(\\.[A-Za-z_][A-Za-z0-9_]*)*");
  const std::string key = a_string(j, where, path);
  if (!std::regex_match(key, key_pattern))
    fail(where, path, "expected a dotted scene key such as \"resolution.a\"; got \"" + key + "\"");
  return key;
}

std::vector<std::string> quantities_of(const nlohmann::json& e, const std::vector<std::string>& fits,
                                       const std::string& where, const std::string& path) {
  if (!e.contains("quantities")) return default_quantities(fits);
  auto q = string_array(e["quantities"], where, path + "/quantities", true);
  for (std::size_t i = 0; i < q.size(); ++i) check_quantity(q[i], fits, where, path + "/quantities/" + std::to_string(i));
  return q;
}

// h from a ladder key's value: "1/x" for a and segments, "2^-x" for mesh_level, else required.
std::string ladder_spacing_of(const nlohmann::json& e, const std::string& key, const std::string& where,
                              const std::string& path) {
  const std::string last = key.substr(key.rfind('.') + 1);
  if (e.contains("spacing")) {
    const std::string spacing = a_string(e["spacing"], where, path + "/spacing");
    if (spacing != "1/x" && spacing != "2^-x" && spacing != "x")
      fail(where, path + "/spacing", "expected \"1/x\", \"2^-x\" or \"x\" (h from the key's value x)");
    return spacing;
  }
  if (last == "a" || last == "segments") return "1/x";
  if (last == "mesh_level") return "2^-x";
  fail(where, path + "/spacing",
       "required for key \"" + key + "\": \"1/x\", \"2^-x\" or \"x\" (h from the key's value x)");
  return "";
}

double an_assumed_order(const nlohmann::json& e, const std::string& where, const std::string& path) {
  if (!e.contains("assumed_order")) return 1.0;
  const double p = a_number(e["assumed_order"], where, path + "/assumed_order");
  if (!(p > 0.0 && p <= 8.0)) fail(where, path + "/assumed_order", "expected an order in (0, 8]");
  return p;
}

LadderSpec parse_ladder(const nlohmann::json& e, const std::vector<std::string>& fits, const std::string& where,
                        const std::string& path) {
  if (!e.is_object()) fail(where, path, "expected an object with key[, spacing, quantities, cases, name, assumed_order]");
  only_keys(e, {"name", "key", "spacing", "quantities", "cases", "assumed_order"}, where, path);
  if (!e.contains("key")) fail(where, path + "/key", "required key missing (e.g. \"resolution.a\")");
  LadderSpec spec;
  spec.key = a_dotted_key(e["key"], where, path + "/key");
  const std::string last = spec.key.substr(spec.key.rfind('.') + 1);
  spec.spacing = ladder_spacing_of(e, spec.key, where, path);
  spec.name = e.contains("name") ? a_string(e["name"], where, path + "/name") : "ladder_" + last;
  static const std::regex name_pattern("[A-Za-z0-9_-]+");
  if (!std::regex_match(spec.name, name_pattern))
    fail(where, path + "/name", "expected letters, digits, _ or - (it names files)");
  spec.quantities = quantities_of(e, fits, where, path);
  if (e.contains("cases")) spec.cases = string_array(e["cases"], where, path + "/cases", true);
  spec.assumed_order = an_assumed_order(e, where, path);
  return spec;
}

AccuracySpec parse_accuracy(const nlohmann::json& a, const std::vector<std::string>& fits,
                            const std::vector<LadderSpec>& ladders, const std::string& where) {
  const std::string path = "/accuracy";
  if (!a.is_object()) fail(where, path, "expected an object with reference[, quantities, settings, bounds]");
  only_keys(a, {"quantities", "settings", "reference", "bounds"}, where, path);
  AccuracySpec spec;
  spec.quantities = quantities_of(a, fits, where, path);
  spec.settings = default_setting_keys();
  if (a.contains("settings")) {
    if (!a["settings"].is_array() || a["settings"].empty())
      fail(where, path + "/settings", "expected a non-empty array of dotted scene keys");
    spec.settings.clear();
    for (std::size_t i = 0; i < a["settings"].size(); ++i)
      spec.settings.push_back(a_dotted_key(a["settings"][i], where, path + "/settings/" + std::to_string(i)));
  }
  if (!a.contains("reference")) fail(where, path + "/reference", "required key missing (an array of reference objects)");
  const auto& r = a["reference"];
  if (!r.is_array() || r.empty()) fail(where, path + "/reference", "expected a non-empty array of reference objects");
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::string rp = path + "/reference/" + std::to_string(i);
    const auto& e = r[i];
    if (!e.is_object()) fail(where, rp, "expected an object: {\"case\": ..., \"<quantity>\": number, ...} or {\"ladder\": name}");
    ReferenceSpec ref;
    for (const auto& [key, value] : e.items()) {
      if (key == "case") ref.case_name = a_string(value, where, rp + "/case");
      else if (key == "ladder") {
        ref.ladder = a_string(value, where, rp + "/ladder");
        if (std::none_of(ladders.begin(), ladders.end(), [&](const LadderSpec& l) { return l.name == ref.ladder; }))
          fail(where, rp + "/ladder", "no ladder named \"" + ref.ladder + "\" in /analysis/ladder");
      } else {
        if (std::find(spec.quantities.begin(), spec.quantities.end(), key) == spec.quantities.end())
          fail(where, rp + "/" + key, "not one of the accuracy quantities (/analysis/accuracy/quantities), nor case or ladder");
        ref.values[key] = a_number(value, where, rp + "/" + key);
      }
    }
    if (ref.values.empty() && ref.ladder.empty())
      fail(where, rp, "expected reference values (\"<quantity>\": number) or \"ladder\": <ladder name>");
    spec.reference.push_back(ref);
  }
  if (a.contains("bounds")) {
    if (!a["bounds"].is_array() || a["bounds"].empty()) fail(where, path + "/bounds", "expected a non-empty array of relative errors");
    spec.bounds.clear();
    for (std::size_t i = 0; i < a["bounds"].size(); ++i) {
      const double b = a_number(a["bounds"][i], where, path + "/bounds/" + std::to_string(i));
      if (!(b > 0.0 && b < 1.0))
        fail(where, path + "/bounds/" + std::to_string(i), "expected a relative error in (0, 1), e.g. 0.01 for 1 %");
      spec.bounds.push_back(b);
    }
  }
  return spec;
}

StabilitySpec parse_stability(const nlohmann::json& s, const std::string& where) {
  const std::string path = "/stability";
  if (!s.is_object()) fail(where, path, "expected an object with parameters");
  only_keys(s, {"parameters"}, where, path);
  if (!s.contains("parameters")) fail(where, path + "/parameters", "required key missing (the swept scene parameters)");
  StabilitySpec spec;
  spec.parameters = string_array(s["parameters"], where, path + "/parameters", true);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < spec.parameters.size(); ++i)
    if (!seen.insert(spec.parameters[i]).second)
      fail(where, path + "/parameters/" + std::to_string(i), "\"" + spec.parameters[i] + "\" listed twice");
  return spec;
}

std::vector<PublishedSpec> parse_published(const nlohmann::json& p, const std::string& where) {
  const std::string path = "/published";
  if (!p.is_array() || p.empty())
    fail(where, path, "expected a non-empty array of {\"curve\": <name>, \"where\": {<parameter>: <value>}[, \"case\": <name>]}");
  std::vector<PublishedSpec> out;
  const auto names = published_curve_names();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::string at = path + "/" + std::to_string(i);
    const auto& e = p[i];
    if (!e.is_object()) fail(where, at, "expected an object with curve[, where, case]");
    only_keys(e, {"curve", "where", "case"}, where, at);
    if (!e.contains("curve")) fail(where, at + "/curve", "required key missing");
    PublishedSpec spec;
    spec.curve = a_string(e["curve"], where, at + "/curve");
    if (std::find(names.begin(), names.end(), spec.curve) == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      fail(where, at + "/curve", "unknown curve \"" + spec.curve + "\" (known: " + known + ")");
    }
    if (e.contains("case")) spec.case_name = a_string(e["case"], where, at + "/case");
    if (e.contains("where")) {
      const auto& w = e["where"];
      if (!w.is_object()) fail(where, at + "/where", "expected an object of scene parameter -> number");
      for (const auto& [key, value] : w.items()) spec.where[key] = a_number(value, where, at + "/where/" + key);
    }
    out.push_back(spec);
  }
  return out;
}

std::vector<ExperimentSpec> parse_experiments(const nlohmann::json& p, const std::string& where) {
  const std::string path = "/experiments";
  if (!p.is_array() || p.empty())
    fail(where, path, "expected a non-empty array of {\"data\", \"x\", \"parameter\", \"compare\"[, \"group\"]}");
  std::vector<ExperimentSpec> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::string at = path + "/" + std::to_string(i);
    const auto& e = p[i];
    if (!e.is_object()) fail(where, at, "expected an object with data, x, parameter, compare[, group]");
    only_keys(e, {"data", "x", "parameter", "group", "compare"}, where, at);
    for (const char* key : {"data", "x", "parameter", "compare"})
      if (!e.contains(key)) fail(where, at + "/" + key, "required key missing");
    ExperimentSpec spec;
    spec.data = a_string(e["data"], where, at + "/data");
    ExperimentData data;
    try {
      data = experiment_data(spec.data);
    } catch (const std::invalid_argument& error) {
      fail(where, at + "/data", error.what());
    }
    const auto column = [&](const nlohmann::json& v, const std::string& key_path) {
      const std::string name = a_string(v, where, key_path);
      try {
        (void)data.column(name);
      } catch (const std::invalid_argument& error) {
        fail(where, key_path, error.what());
      }
      return name;
    };
    spec.x = column(e["x"], at + "/x");
    spec.parameter = a_string(e["parameter"], where, at + "/parameter");
    if (e.contains("group")) spec.group = a_string(e["group"], where, at + "/group");
    const auto& c = e["compare"];
    if (!c.is_array() || c.empty())
      fail(where, at + "/compare", "expected a non-empty array of {\"measured\", \"spread\", \"series\"}");
    for (std::size_t k = 0; k < c.size(); ++k) {
      const std::string ck = at + "/compare/" + std::to_string(k);
      if (!c[k].is_object()) fail(where, ck, "expected an object with measured, spread, series");
      only_keys(c[k], {"measured", "spread", "series"}, where, ck);
      for (const char* key : {"measured", "spread", "series"})
        if (!c[k].contains(key)) fail(where, ck + "/" + key, "required key missing");
      spec.compare.push_back({column(c[k]["measured"], ck + "/measured"), column(c[k]["spread"], ck + "/spread"),
                              a_string(c[k]["series"], where, ck + "/series")});
    }
    out.push_back(spec);
  }
  return out;
}

// The fits of /fits: known, each once.
std::vector<std::string> parse_fits(const nlohmann::json& j, const std::string& where) {
  std::vector<std::string> out = string_array(j, where, "/fits", false);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& f = out[i];
    if (std::find(known_fits().begin(), known_fits().end(), f) == known_fits().end()) {
      std::string allowed;
      for (const auto& k : known_fits()) allowed += (allowed.empty() ? "" : ", ") + k;
      fail(where, "/fits/" + std::to_string(i), "expected one of " + allowed + "; got \"" + f + "\"");
    }
    if (!seen.insert(f).second) fail(where, "/fits/" + std::to_string(i), "\"" + f + "\" listed twice");
  }
  return out;
}

// Name -> JSON pointer into the canonical scene.
std::map<std::string, std::string> parse_parameters(const nlohmann::json& p, const std::string& where) {
  std::map<std::string, std::string> out;
  if (!p.is_object()) fail(where, "/parameters", "expected an object of name -> JSON pointer");
  for (const auto& [name, pointer] : p.items()) {
    const std::string path = "/parameters/" + name;
    const std::string text = a_string(pointer, where, path);
    try {
      nlohmann::json::json_pointer check(text);
      (void)check;
    } catch (const nlohmann::json::exception&) {
      fail(where, path, "expected a JSON pointer such as \"/Ca\"; got \"" + text + "\"");
    }
    if (text.empty() || text[0] != '/') fail(where, path, "expected a JSON pointer starting with /");
    out[name] = text;
  }
  return out;
}

// One entry of /tables: its name names files, its columns are fitted times of the block's fits.
TableSpec parse_table(const nlohmann::json& e, const std::vector<std::string>& fits, std::set<std::string>& names,
                      const std::string& where, const std::string& path) {
  static const std::regex name_pattern("[A-Za-z0-9_-]+");
  if (!e.is_object()) fail(where, path, "expected an object with name, x, columns[, normalise]");
  only_keys(e, {"name", "x", "columns", "normalise"}, where, path);
  for (const char* key : {"name", "x", "columns"})
    if (!e.contains(key)) fail(where, path + "/" + key, "required key missing");
  TableSpec spec;
  spec.name = a_string(e["name"], where, path + "/name");
  if (!std::regex_match(spec.name, name_pattern))
    fail(where, path + "/name", "expected letters, digits, _ or - (it names files)");
  if (spec.name == "member_fits" || spec.name == "bilinear" || spec.name == "artificial_viscosity")
    fail(where, path + "/name", "\"" + spec.name + "\" is reserved for a report file");
  if (!names.insert(spec.name).second) fail(where, path + "/name", "table name used twice");
  spec.x = a_string(e["x"], where, path + "/x");
  spec.columns = string_array(e["columns"], where, path + "/columns", true);
  for (std::size_t c = 0; c < spec.columns.size(); ++c)
    check_column(spec.columns[c], fits, where, path + "/columns/" + std::to_string(c));
  if (e.contains("normalise")) {
    spec.normalise = a_string(e["normalise"], where, path + "/normalise");
    if (spec.normalise != "none" && spec.normalise != "tau_e" && spec.normalise != "tau_v" &&
        spec.normalise != "seconds")
      fail(where, path + "/normalise", "expected \"none\", \"tau_e\", \"tau_v\" or \"seconds\"");
  }
  return spec;
}

std::vector<TableSpec> parse_tables(const nlohmann::json& t, const std::vector<std::string>& fits, const std::string& where) {
  if (!t.is_array()) fail(where, "/tables", "expected an array of table objects");
  std::vector<TableSpec> out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < t.size(); ++i) out.push_back(parse_table(t[i], fits, names, where, "/tables/" + std::to_string(i)));
  return out;
}

BilinearSpec parse_bilinear(const nlohmann::json& b, const std::vector<std::string>& fits, const std::string& where) {
  if (!b.is_object()) fail(where, "/bilinear", "expected an object with targets[, V_base, ladder, spacing, assumed_order]");
  only_keys(b, {"targets", "V_base", "ladder", "spacing", "assumed_order"}, where, "/bilinear");
  if (!b.contains("targets")) fail(where, "/bilinear/targets", "required key missing");
  BilinearSpec spec;
  spec.targets = string_array(b["targets"], where, "/bilinear/targets", true);
  for (std::size_t c = 0; c < spec.targets.size(); ++c)
    check_column(spec.targets[c], fits, where, "/bilinear/targets/" + std::to_string(c));
  if (b.contains("V_base")) {
    if (!b["V_base"].is_number()) fail(where, "/bilinear/V_base", "expected a number");
    spec.V_base = b["V_base"].get<double>();
  }
  if (b.contains("ladder")) {
    spec.ladder = a_dotted_key(b["ladder"], where, "/bilinear/ladder");
    spec.spacing = ladder_spacing_of(b, spec.ladder, where, "/bilinear");
    spec.assumed_order = an_assumed_order(b, where, "/bilinear");
  } else if (b.contains("spacing") || b.contains("assumed_order")) {
    fail(where, b.contains("spacing") ? "/bilinear/spacing" : "/bilinear/assumed_order",
         "only with /bilinear/ladder (the resolution key the grid is run at)");
  }
  return spec;
}

// One ladder object, or an array of them (e.g. one in resolution.a, one in resolution.mesh_level).
std::vector<LadderSpec> parse_ladders(const nlohmann::json& l, const std::vector<std::string>& fits, const std::string& where) {
  std::vector<LadderSpec> out;
  std::set<std::string> names;
  auto add = [&](const nlohmann::json& e, const std::string& path) {
    out.push_back(parse_ladder(e, fits, where, path));
    if (!names.insert(out.back().name).second)
      fail(where, path + "/name", "ladder name \"" + out.back().name + "\" used twice");
  };
  if (l.is_array()) {
    if (l.empty()) fail(where, "/ladder", "expected a ladder object or a non-empty array of them");
    for (std::size_t i = 0; i < l.size(); ++i) add(l[i], "/ladder/" + std::to_string(i));
  } else {
    add(l, "/ladder");
  }
  return out;
}

}  // namespace

const std::vector<std::string>& marker_quantities() {
  static const std::vector<std::string> q{"D_stop", "D_max", "D_inf"};
  return q;
}

std::vector<std::string> default_quantities(const std::vector<std::string>& fits) {
  std::vector<std::string> q{"D_stop"};
  for (const auto& f : fits)
    for (const auto& t : times_of_fit(f)) q.push_back(f + "." + t);
  return q;
}

const std::vector<std::string>& default_setting_keys() {
  static const std::vector<std::string> keys{"resolution.a",      "resolution.mesh_level", "resolution.segments",
                                             "resolution.tau",    "resolution.kernel",     "resolution.precision",
                                             "resolution.domain", "resolution.membrane_update", "Re"};
  return keys;
}

const std::vector<std::string>& known_fits() {
  static const std::vector<std::string> fits{"response", "recovery", "two_phase", "double_exponential",
                                             "double_exponential_free", "extensional_recovery"};
  return fits;
}

std::vector<std::string> times_of_fit(const std::string& fit) {
  if (fit == "response") return {"k_tau_s"};
  if (fit == "recovery") return {"k_tau_r"};
  if (fit == "two_phase" || fit == "double_exponential") return {"k_tau_R1", "k_tau_R2"};
  if (fit == "double_exponential_free") return {"k_tau_R1", "k_tau_R2", "w_R1"};
  if (fit == "extensional_recovery") return {"k_t_c"};
  return {};
}

AnalysisBlock parse_analysis_block(const nlohmann::json& block, const std::string& where) {
  AnalysisBlock out;
  if (block.is_null()) return out;
  if (!block.is_object()) fail(where, "", "expected an object");
  only_keys(block,
            {"fits", "parameters", "tables", "bilinear", "ladder", "accuracy", "stability", "published", "experiments",
             "figures"},
            where, "");
  if (block.contains("fits")) out.fits = parse_fits(block["fits"], where);
  if (block.contains("parameters")) out.parameters = parse_parameters(block["parameters"], where);
  if (block.contains("tables")) out.tables = parse_tables(block["tables"], out.fits, where);
  if (block.contains("bilinear")) out.bilinear = parse_bilinear(block["bilinear"], out.fits, where);
  if (block.contains("ladder")) out.ladders = parse_ladders(block["ladder"], out.fits, where);
  if (block.contains("accuracy")) out.accuracy = parse_accuracy(block["accuracy"], out.fits, out.ladders, where);
  if (block.contains("stability")) out.stability = parse_stability(block["stability"], where);
  if (block.contains("published")) out.published = parse_published(block["published"], where);
  if (block.contains("experiments")) out.experiments = parse_experiments(block["experiments"], where);

  if (block.contains("figures")) {
    if (!block["figures"].is_boolean()) fail(where, "/figures", "expected true or false");
    out.figures = block["figures"].get<bool>();
  }
  return out;
}

void validate_analysis_block(const nlohmann::json& block, const std::string& where) {
  (void)parse_analysis_block(block, where);
}

}  // namespace capsule::analysis
