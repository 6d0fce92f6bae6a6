#pragma once
// Published curves D(kt) that a campaign's members are compared with (the report's
// "published" section): digitised from the figures of the papers the dissertation validates
// against, shipped in analysis/reference/ (sources in its README) and embedded at build time.
#include <string>
#include <vector>

namespace capsule::analysis {

struct PublishedCurve {
  std::string name;               // the file stem, e.g. "sphere_neohookean_V1_rp1998_ca0.05"
  std::string source;             // the paper, as its README names it
  std::string measure;            // how the paper measures D
  double digitising_error = 0;    // +- in D (README of the reference data)
  std::vector<double> kt, D;      // sorted by kt
};

// Every embedded curve's name, sorted.
std::vector<std::string> published_curve_names();

// The curve of that name; throws std::invalid_argument naming the known ones.
PublishedCurve published_curve(const std::string& name);

// A "kt,D" CSV (header line, then pairs; points in any order) as a curve sorted by kt.
// Throws std::runtime_error naming the line of a malformed row.
void parse_curve_csv(const std::string& text, PublishedCurve& curve);

}  // namespace capsule::analysis
