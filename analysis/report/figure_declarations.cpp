#include "analysis/report/figure_declarations.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace capsule::analysis {

namespace {

using json = nlohmann::json;

// The axis a time-table quantity goes on: the text draws k tau_R2 on a right axis and keeps
// fractions (w_R1) off the time axes.
std::string axis_of(const std::string& quantity) {
  if (quantity == "w_R1") return "panel";
  if (quantity.find("tau_R2") != std::string::npos) return "right";
  return "left";
}

void add_unique(json& list, const std::string& value) {
  for (const auto& v : list)
    if (v == value) return;
  list.push_back(value);
}

json times_declaration(const json& table) {
  const std::string normalise = table.value("normalise", std::string("none"));
  json d{{"file", table["name"].get<std::string>() + ".png"}, {"kind", "times"}, {"source", table["name"]},
         {"x", table["x"]}, {"left", json::array()}, {"right", json::array()}, {"panels", json::array()},
         {"series", json::array()}};
  // Series that vary x; a case whose members all share one x (another case's sweep) is a
  // point of the tables, not a line of this figure, unless no series varies x.
  auto varies = [](const json& cdata) {
    for (const auto& [col, s] : cdata["columns"].items()) {
      std::set<double> xs;
      for (const auto& x : s["x"]) xs.insert(x.get<double>());
      if (xs.size() > 1) return true;
    }
    return false;
  };
  bool any_varies = false;
  for (const auto& [c, cdata] : table["cases"].items()) any_varies = any_varies || varies(cdata);
  // The main axes hold the text's fits; a free-amplitude fit of the same times gets a panel of
  // its own below (the same two axes), and fractions a panel of their own.
  std::set<std::string> main_quantities;
  for (const auto& [c, cdata] : table["cases"].items())
    for (const auto& [col, s] : cdata["columns"].items())
      if (col.find("_free.") == std::string::npos) main_quantities.insert(column_quantity(col, normalise));
  json free_panel{{"label", "free-amplitude fit"}, {"left", json::array()}, {"right", json::array()}};
  json fraction_panel{{"label", "fraction"}, {"left", json::array()}, {"right", json::array()}};
  for (const auto& [c, cdata] : table["cases"].items()) {
    if (any_varies && !varies(cdata)) continue;
    json series{{"label", c}, {"columns", json::array()}};
    for (const auto& [col, s] : cdata["columns"].items()) {
      if (s["x"].empty()) continue;
      const std::string q = column_quantity(col, normalise);
      const std::string axis = axis_of(q) == "right" ? "right" : "left";
      json* target = &d;
      std::string panel = "main";
      if (axis_of(q) == "panel") {
        target = &fraction_panel;
        panel = "fraction";
      } else if (col.find("_free.") != std::string::npos && main_quantities.count(q)) {
        target = &free_panel;
        panel = "free-amplitude fit";
      }
      add_unique((*target)[axis], q);
      series["columns"].push_back({{"column", col}, {"quantity", q}, {"axis", axis}, {"panel", panel},
                                   {"fit", col.substr(0, col.find('.'))}});
    }
    if (!series["columns"].empty()) d["series"].push_back(series);
  }
  for (json* p : {&free_panel, &fraction_panel})
    if (!(*p)["left"].empty() || !(*p)["right"].empty()) d["panels"].push_back(*p);
  // The text scales the right axis by the times' usual ratio: 100 for the tank-treading phases
  // (87)-(89), O(10^-1) against O(10) (Figs. 25-28), 10 for the tumbling (90), O(10^-1) against O(1)
  // (Figs. 33-36).
  if (!d["right"].empty()) {
    bool tank_treading = false;
    for (const auto& s : d["series"])
      for (const auto& c : s["columns"]) tank_treading = tank_treading || c["fit"] == "two_phase";
    d["right_scale"] = tank_treading ? 100 : 10;
  }
  return d;
}

// Members drawn together, as one figure of the text draws them (e.g. Fig. 62: the power law
// and its Kelvin-Voigt partners; Fig. 63 their inclinations): the groups' members this report
// has whose block carries the series drawn.
json together_declaration(const json& text_figure, const json& figure_data) {
  const std::string file = text_figure["file"].get<std::string>();
  const json left = text_figure.value("left", json::array({"D_xy"}));
  const auto& allowed = together_quantities();
  if (left.size() != 1 || std::find(allowed.begin(), allowed.end(), left[0].get<std::string>()) == allowed.end())
    throw std::invalid_argument("figure " + file + ": members drawn together plot one series against kt, one of " +
                                "D_xy, theta; got " + left.dump());
  const std::string quantity = left[0].get<std::string>();
  std::set<std::string> slugs;  // members whose block has the series
  for (const auto& m : figure_data.value("members", json::array()))
    if (m.contains(quantity) && m[quantity].size() == m["kt"].size()) slugs.insert(m["slug"].get<std::string>());
  json groups = json::array(), series = json::array();
  for (const auto& g : text_figure["together"]) {
    json present = json::array();
    for (const auto& slug : g["members"])
      if (slugs.count(slug.get<std::string>())) {
        present.push_back(slug);
        series.push_back(slug);
      }
    groups.push_back({{"label", g["label"]}, {"members", present}});
  }
  return {{"file", file}, {"kind", "together"}, {"source", groups}, {"x", "kt"}, {"left", left},
          {"right", json::array()}, {"panels", json::array()}, {"series", series}};
}

}  // namespace

const std::vector<std::string>& together_quantities() {
  static const std::vector<std::string> q = {"D_xy", "theta"};
  return q;
}

std::map<std::string, std::set<std::string>> together_series(const json& text_figures) {
  std::map<std::string, std::set<std::string>> out;
  for (const auto& t : text_figures) {
    if (!t.contains("together")) continue;
    for (const auto& q : t.value("left", json::array()))
      if (q != "D_xy")
        for (const auto& g : t["together"])
          for (const auto& slug : g["members"]) out[slug.get<std::string>()].insert(q.get<std::string>());
  }
  return out;
}

std::string column_quantity(const std::string& column, const std::string& normalise) {
  std::string q = column.substr(column.find('.') == std::string::npos ? 0 : column.find('.') + 1);
  if (q.rfind("k_tau_", 0) == 0) {
    const std::string which = q.substr(6);
    if (normalise == "tau_e" || normalise == "tau_v") return "tau_" + which + "/" + normalise;
    if (normalise == "seconds") return "tau_" + which + " (s)";
    return "k tau_" + which;
  }
  if (q == "k_t_c") {  // the extensional recovery's t_c (Hochmuth et al. 1979)
    if (normalise == "tau_e" || normalise == "tau_v") return "t_c/" + normalise;
    if (normalise == "seconds") return "t_c (s)";
    return "k t_c";
  }
  return q;
}

void declare_figures(json& figure_data, const json& text_figures) {
  json figures = json::array();
  std::set<std::string> files;
  auto add = [&](json d) {
    if (!files.insert(d["file"].get<std::string>()).second) return;  // a member shared by two cases: one PNG
    figures.push_back(std::move(d));
  };
  for (const auto& m : figure_data.value("members", json::array())) {
    json series = json::array({"simulation"});
    for (const auto& c : m["curves"]) series.push_back(c["label"]);
    add({{"file", "member_" + m["slug"].get<std::string>() + ".png"}, {"kind", "member"}, {"source", m["slug"]},
         {"x", "kt"}, {"left", {"D_xy"}}, {"right", json::array()}, {"panels", json::array()}, {"series", series}});
  }
  for (const auto& m : figure_data.value("members", json::array()))
    if (m.contains("gamma"))
      add({{"file", "member_" + m["slug"].get<std::string>() + "_gamma.png"}, {"kind", "gamma"}, {"source", m["slug"]},
           {"x", "kt"}, {"left", {"gamma_max", "gamma_min"}}, {"right", json::array()}, {"panels", json::array()},
           {"series", {"maximum", "minimum"}}});
  for (const auto& t : figure_data.value("tables", json::array())) add(times_declaration(t));
  for (const auto& s : figure_data.value("slices", json::array()))
    add({{"file", "member_" + s["slug"].get<std::string>() + "_slices.png"}, {"kind", "slices"}, {"source", s["slug"]},
         {"x", "x/a"}, {"left", {"y/a"}}, {"right", json::array()}, {"panels", json::array({{{"left", {"y/a"}}}})},
         {"series", json::array()}});
  for (const auto& a : figure_data.value("accuracy", json::array()))
    add({{"file", a["name"].get<std::string>() + ".png"}, {"kind", "accuracy"}, {"source", a["name"]},
         {"x", "cost"}, {"left", {"relative error"}}, {"right", json::array()}, {"panels", json::array()},
         {"series", {"settings", "non-dominated"}}});
  for (const auto& s : figure_data.value("stability", json::array()))
    add({{"file", s["name"].get<std::string>() + ".png"}, {"kind", "stability"}, {"source", s["name"]},
         {"x", s["x"]}, {"left", {s["y"]}}, {"right", json::array()}, {"panels", json::array()},
         {"series", {"complete", "unstable", "stopped / no result"}}});
  if (figure_data.contains("published") && !figure_data["published"].empty()) {
    json series = json::array();
    for (const auto& p : figure_data["published"]) series.push_back(p["curve"]);
    add({{"file", "published.png"}, {"kind", "published"}, {"x", "kt"}, {"left", {"D"}}, {"right", json::array()},
         {"panels", json::array()}, {"series", series}});
  }
  for (const auto& e : figure_data.value("experiments", json::array())) {
    json left = json::array(), series = json::array();
    for (const auto& q : e["quantities"]) {
      left.push_back(q["series"]);
      series.push_back(q["measured"]);
    }
    add({{"file", "experiment_" + e["name"].get<std::string>() + ".png"}, {"kind", "experiment"},
         {"source", e["name"]}, {"x", e["x"]}, {"left", left}, {"right", json::array()}, {"panels", json::array()},
         {"series", series}});
  }
  for (const auto& t : text_figures)
    if (t.contains("together"))
      if (json d = together_declaration(t, figure_data); !d["series"].empty()) add(std::move(d));
  // The text's figure each one stands for.
  std::map<std::string, const json*> text_of;
  for (const auto& t : text_figures) text_of[t["file"].get<std::string>()] = &t;
  for (auto& d : figures)
    if (const auto it = text_of.find(d["file"].get<std::string>()); it != text_of.end()) {
      d["number"] = (*it->second)["number"];
      d["shows"] = (*it->second)["shows"];
      if (d["kind"] == "together" && it->second->contains("otherwise")) d["otherwise"] = (*it->second)["otherwise"];
    }
  figure_data["figures"] = figures;
}

}  // namespace capsule::analysis
