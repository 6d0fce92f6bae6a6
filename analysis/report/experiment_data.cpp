#include "analysis/report/experiment_data.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "experiment_data_csv.hpp"

namespace capsule::analysis {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}

// What analysis/reference/README.md says of each data set.
std::string source_of(const std::string& name) {
  if (name.rfind("mills2004", 0) == 0)
    return "Mills, Qie, Dao, Lim and Suresh, Mech. Chem. Biosyst. 1 (2004) 169-180, Fig. 5";
  return "analysis/reference/README.md";
}

std::string known_names() {
  std::string known;
  for (const auto& n : experiment_data_names()) known += (known.empty() ? "" : ", ") + n;
  return known;
}

}  // namespace

std::vector<double> ExperimentData::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) {
    std::string known;
    for (const auto& c : columns) known += (known.empty() ? "" : ", ") + c;
    throw std::invalid_argument("experiment data " + this->name + " has no column \"" + name + "\" (columns: " +
                                known + ")");
  }
  const auto k = static_cast<std::size_t>(it - columns.begin());
  std::vector<double> out;
  for (const auto& r : rows) out.push_back(r[k]);
  return out;
}

std::vector<std::string> experiment_data_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : generated::experiment_data_files) names.emplace_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

void parse_experiment_csv(const std::string& text, ExperimentData& data) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  data.columns.clear();
  data.rows.clear();
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    if (data.columns.empty()) {
      data.columns = split(line);
      continue;
    }
    const auto cells = split(line);
    std::vector<double> row;
    try {
      if (cells.size() != data.columns.size()) throw std::invalid_argument("count");
      for (const auto& c : cells) {
        std::size_t used = 0;
        row.push_back(std::stod(c, &used));
        if (used != c.size()) throw std::invalid_argument("trailing text");
      }
    } catch (const std::exception&) {
      throw std::runtime_error("experiment data " + data.name + " line " + std::to_string(line_no) + ": expected " +
                               std::to_string(data.columns.size()) + " numbers; got \"" + line + "\"");
    }
    data.rows.push_back(std::move(row));
  }
  if (data.columns.empty()) throw std::runtime_error("experiment data " + data.name + ": no header line");
}

ExperimentData experiment_data(const std::string& name) {
  for (const auto& [stem, text] : generated::experiment_data_files)
    if (stem == name) {
      ExperimentData d;
      d.name = name;
      d.source = source_of(name);
      parse_experiment_csv(std::string(text), d);
      return d;
    }
  throw std::invalid_argument("unknown experiment data \"" + name + "\" (known: " + known_names() + ")");
}

}  // namespace capsule::analysis
