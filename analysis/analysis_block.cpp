#include "analysis/analysis_block.hpp"

#include <algorithm>
#include <regex>
#include <set>
#include <stdexcept>

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

}  // namespace

const std::vector<std::string>& known_fits() {
  static const std::vector<std::string> fits{"response", "recovery", "two_phase", "double_exponential",
                                             "double_exponential_free"};
  return fits;
}

std::vector<std::string> times_of_fit(const std::string& fit) {
  if (fit == "response") return {"k_tau_s"};
  if (fit == "recovery") return {"k_tau_r"};
  if (fit == "two_phase" || fit == "double_exponential") return {"k_tau_R1", "k_tau_R2"};
  if (fit == "double_exponential_free") return {"k_tau_R1", "k_tau_R2", "w_R1"};
  return {};
}

AnalysisBlock parse_analysis_block(const nlohmann::json& block, const std::string& where) {
  AnalysisBlock out;
  if (block.is_null()) return out;
  if (!block.is_object()) fail(where, "", "expected an object");
  only_keys(block, {"fits", "parameters", "tables", "bilinear", "figures"}, where, "");

  if (block.contains("fits")) {
    out.fits = string_array(block["fits"], where, "/fits", false);
    std::set<std::string> seen;
    for (std::size_t i = 0; i < out.fits.size(); ++i) {
      const auto& f = out.fits[i];
      if (std::find(known_fits().begin(), known_fits().end(), f) == known_fits().end())
        fail(where, "/fits/" + std::to_string(i),
             "expected one of response, recovery, two_phase, double_exponential, double_exponential_free; got \"" +
                 f + "\"");
      if (!seen.insert(f).second) fail(where, "/fits/" + std::to_string(i), "\"" + f + "\" listed twice");
    }
  }

  if (block.contains("parameters")) {
    const auto& p = block["parameters"];
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
      out.parameters[name] = text;
    }
  }

  if (block.contains("tables")) {
    const auto& t = block["tables"];
    if (!t.is_array()) fail(where, "/tables", "expected an array of table objects");
    std::set<std::string> names;
    static const std::regex name_pattern("[A-Za-z0-9_-]+");
    for (std::size_t i = 0; i < t.size(); ++i) {
      const std::string path = "/tables/" + std::to_string(i);
      const auto& e = t[i];
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
        check_column(spec.columns[c], out.fits, where, path + "/columns/" + std::to_string(c));
      if (e.contains("normalise")) {
        spec.normalise = a_string(e["normalise"], where, path + "/normalise");
        if (spec.normalise != "none" && spec.normalise != "tau_e" && spec.normalise != "tau_v")
          fail(where, path + "/normalise", "expected \"none\", \"tau_e\" or \"tau_v\"");
      }
      out.tables.push_back(spec);
    }
  }

  if (block.contains("bilinear")) {
    const auto& b = block["bilinear"];
    if (!b.is_object()) fail(where, "/bilinear", "expected an object with targets[, V_base]");
    only_keys(b, {"targets", "V_base"}, where, "/bilinear");
    if (!b.contains("targets")) fail(where, "/bilinear/targets", "required key missing");
    BilinearSpec spec;
    spec.targets = string_array(b["targets"], where, "/bilinear/targets", true);
    for (std::size_t c = 0; c < spec.targets.size(); ++c)
      check_column(spec.targets[c], out.fits, where, "/bilinear/targets/" + std::to_string(c));
    if (b.contains("V_base")) {
      if (!b["V_base"].is_number()) fail(where, "/bilinear/V_base", "expected a number");
      spec.V_base = b["V_base"].get<double>();
    }
    out.bilinear = spec;
  }

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
