#include "analysis/report/published_curves.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "published_curves_data.hpp"

namespace capsule::analysis {

namespace {

// What analysis/reference/README.md says of each family of curves.
void describe(PublishedCurve& c) {
  if (c.name.find("rp1998") != std::string::npos) {
    c.source = "Ramanujan and Pozrikidis, J. Fluid Mech. 361 (1998) 117-143";
    c.measure = "capsule extent in the shear plane (boundary integral)";
    c.digitising_error = 0.005;
  } else {
    c.source = "analysis/reference/README.md";
    c.measure = "as the source";
    c.digitising_error = 0.005;
  }
}

}  // namespace

std::vector<std::string> published_curve_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : generated::published_curve_files) names.emplace_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

void parse_curve_csv(const std::string& text, PublishedCurve& curve) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::pair<double, double>> points;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 || line.empty() || line[0] == '#') continue;  // header "kt,D"
    const auto comma = line.find(',');
    try {
      if (comma == std::string::npos) throw std::invalid_argument("no comma");
      const double t = std::stod(line.substr(0, comma));
      const double d = std::stod(line.substr(comma + 1));
      points.emplace_back(t, d);
    } catch (const std::exception&) {
      throw std::runtime_error("published curve " + curve.name + " line " + std::to_string(line_no) +
                               ": expected \"kt,D\"; got \"" + line + "\"");
    }
  }
  // The digitised points are not always in increasing kt (README): sort before use.
  std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  curve.kt.clear();
  curve.D.clear();
  for (const auto& [t, d] : points) curve.kt.push_back(t), curve.D.push_back(d);
}

PublishedCurve published_curve(const std::string& name) {
  for (const auto& [stem, text] : generated::published_curve_files)
    if (stem == name) {
      PublishedCurve c;
      c.name = name;
      describe(c);
      parse_curve_csv(std::string(text), c);
      return c;
    }
  std::string known;
  for (const auto& n : published_curve_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown published curve \"" + name + "\" (known: " + known + ")");
}

}  // namespace capsule::analysis
