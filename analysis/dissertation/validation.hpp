#pragma once
// THESIS.md's Chapter 2 validation: the members of the validation campaigns against the
// published curves they name (the report's "published" kind, fits.json "published"), beside
// what the text says of its own Figs. 7 and 9.
#include <string>
#include <vector>

#include "analysis/report/table.hpp"
#include "analysis/dissertation/results.hpp"

namespace capsule::analysis {

// The validation campaigns, in the order of the text.
const std::vector<std::string>& validation_campaigns();

// One row per published-curve entry of each validation campaign's fits.json; a campaign not
// run, or run without a published block, gives one row that says so.
Table validation_table(const DissertationResults& results);

}  // namespace capsule::analysis
