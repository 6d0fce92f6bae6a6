#pragma once
// Measurements a campaign's members are compared with (the report's "experiments" section):
// tables of a controlled variable (a force, a shear rate) and, per measured quantity, its mean and
// spread, shipped in analysis/reference/ (sources in its README) and embedded at build time.
#include <string>
#include <vector>

namespace capsule::analysis {

struct ExperimentData {
  std::string name;                      // the file stem, e.g. "mills2004_optical_tweezers"
  std::string source;                    // the paper, as analysis/reference/README.md names it
  std::vector<std::string> columns;      // the header's column names
  std::vector<std::vector<double>> rows; // one per data point, a number per column

  // The column of that name; throws std::invalid_argument naming the known ones.
  std::vector<double> column(const std::string& name) const;
};

// Every embedded data set's name, sorted.
std::vector<std::string> experiment_data_names();

// The data set of that name; throws std::invalid_argument naming the known ones.
ExperimentData experiment_data(const std::string& name);

// A CSV of a header line and rows of numbers (lines starting with '#' skipped). Throws
// std::runtime_error naming the line of a row that is not as many numbers as the header has names.
void parse_experiment_csv(const std::string& text, ExperimentData& data);

}  // namespace capsule::analysis
