#include "analysis/dissertation/figure_axes.hpp"

#include <sstream>
#include <stdexcept>

#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/figure_index.hpp"
#include "figure_axes_md.hpp"

namespace capsule::analysis {

namespace {

std::string trimmed(const std::string& s) {
  const std::size_t first = s.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

// "label: a, b / label: c" -> groups.
std::vector<MemberGroup> parse_groups(const std::string& cell, const std::string& where) {
  std::vector<MemberGroup> groups;
  if (cell.empty()) return groups;
  std::size_t at = 0;
  while (at <= cell.size()) {
    const std::size_t end = std::min(cell.find(" / ", at), cell.size());
    const std::string group = cell.substr(at, end - at);
    const std::size_t colon = group.rfind(": ");
    if (colon == std::string::npos)
      throw std::runtime_error(where + "drawn together: a group \"" + group + "\" without \"label: members\"");
    MemberGroup g{trimmed(group.substr(0, colon)), {}};
    std::stringstream members(group.substr(colon + 2));
    std::string slug;
    while (std::getline(members, slug, ','))
      if (!trimmed(slug).empty()) g.members.push_back(trimmed(slug));
    if (g.label.empty() || g.members.empty())
      throw std::runtime_error(where + "drawn together: a group \"" + group + "\" without a label or members");
    groups.push_back(g);
    at = end + 3;
  }
  return groups;
}

// "x = kt; left y = a; b: why" -> the value after `name = ` up to the next "; <axis> = " or ": ".
std::string otherwise_value(const std::string& cell, const std::string& name) {
  const std::string colon_cut = cell.substr(0, cell.find(": "));
  const std::size_t at = colon_cut.find(name + " = ");
  if (at == std::string::npos) return "";
  const std::size_t begin = at + name.size() + 3;
  std::size_t end = colon_cut.size();
  for (const char* next : {"; x = ", "; left y = ", "; right y = "})
    if (const std::size_t n = colon_cut.find(next, begin); n != std::string::npos) end = std::min(end, n);
  return trimmed(colon_cut.substr(begin, end - begin));
}

}  // namespace

std::string TextFigureAxes::toolkit_x() const {
  const std::string v = otherwise_value(toolkit_otherwise, "x");
  return v.empty() ? x : v;
}
std::vector<std::string> TextFigureAxes::toolkit_left() const {
  const std::string v = otherwise_value(toolkit_otherwise, "left y");
  return v.empty() ? left : split_list(v);
}
std::vector<std::string> TextFigureAxes::toolkit_right() const {
  const std::string v = otherwise_value(toolkit_otherwise, "right y");
  return v.empty() ? right : split_list(v);
}

std::vector<TextFigureAxes> parse_figure_axes(const std::string& markdown) {
  std::vector<TextFigureAxes> out;
  for (const auto& [line_number, cells] : markdown_table_rows(markdown)) {
    const std::string where = "analysis/dissertation/figure_axes.md line " + std::to_string(line_number) + ": ";
    if (cells.size() != 6) throw std::runtime_error(where + "expected 6 cells, found " + std::to_string(cells.size()));
    if (cells[0].empty() || cells[1].empty() || cells[2].empty())
      throw std::runtime_error(where + "a row needs the figure number, x and left y");
    std::string right = cells[3];
    double right_scale = 0.0;
    if (const std::size_t open = right.rfind(" ("); open != std::string::npos && right.size() > open + 2 &&
                                                   right.compare(right.size() - 8, 8, " x left)") == 0) {
      try {
        right_scale = std::stod(right.substr(open + 2));
      } catch (const std::exception&) {
        throw std::runtime_error(where + "right y: \"(N x left)\" needs a number N");
      }
      right = right.substr(0, open);
    }
    TextFigureAxes a{cells[0], cells[1], split_list(cells[2]), split_list(right), right_scale,
                     parse_groups(cells[4], where), cells[5]};
    if (!a.toolkit_otherwise.empty() && a.toolkit_otherwise.find(": ") == std::string::npos)
      throw std::runtime_error(where + "the toolkit draws otherwise: give the axes, then \": \" and why");
    out.push_back(std::move(a));
  }
  return out;
}

const std::vector<TextFigureAxes>& figure_axes() {
  static const std::vector<TextFigureAxes> axes = parse_figure_axes(k_figure_axes_markdown);
  return axes;
}

nlohmann::json text_figures_of_campaign(const std::string& campaign) {
  nlohmann::json out = nlohmann::json::array();
  const std::string prefix = campaign + "/report/figures/";
  for (const auto& f : figure_index())
    for (const auto& file : f.files) {
      if (file.rfind(prefix, 0) != 0) continue;
      const std::string name = file.substr(prefix.size());
      nlohmann::json entry{{"file", name}, {"number", f.number}, {"shows", f.shows}};
      for (const auto& a : figure_axes())
        if (a.number == f.number && !a.together.empty() && name == "fig" + f.number + ".png") {
          entry["together"] = nlohmann::json::array();
          for (const auto& g : a.together) entry["together"].push_back({{"label", g.label}, {"members", g.members}});
          entry["left"] = a.toolkit_left();  // the members' series drawn: D_xy, theta
          if (!a.toolkit_otherwise.empty()) entry["otherwise"] = a.toolkit_otherwise;
        }
      out.push_back(entry);
    }
  return out;
}

}  // namespace capsule::analysis
