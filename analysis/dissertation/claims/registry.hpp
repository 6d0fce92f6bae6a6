#pragma once
// The claim registry: every rule of the dissertation comparison under its key in claims.md.
// Each file of claims/ lists its own claims at its end (chapter2_claims(), ...); claim_registry()
// gathers the lists, and evaluate_claims (claims.cpp) walks claims.md, in the order of the text,
// asking each key's rule for its rows. A claim is its rule and its line in its file's list, its
// words in claims.md, and its test; registry_mismatches says where rules and words disagree.
#include <functional>
#include <string>
#include <vector>

#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/results.hpp"

namespace capsule::analysis::claims {

// One row of a claim: the rule judged once (a case, a figure, a campaign).
using RowRule = std::function<ClaimResult(const DissertationResults&)>;

// A claim: its key in claims.md and its rows, in the order THESIS.md lists them.
struct RegisteredClaim {
  std::string key;
  std::vector<RowRule> rows;
};
using ClaimList = std::vector<RegisteredClaim>;

// A rule judged once, and a rule judged for the circle and the sphere (cases 2d, 3d).
RegisteredClaim once(const std::string& key, ClaimResult (*rule)(const DissertationResults&));
RegisteredClaim per_case(const std::string& key, ClaimResult (*rule)(const DissertationResults&, const std::string&));

// Each file's claims, defined at the end of that file.
ClaimList chapter2_claims();              // chapter2.cpp
ClaimList chapter3_claims();              // chapter3.cpp
ClaimList chapter3_normalized_claims();   // chapter3_normalized.cpp
ClaimList chapter3_trends_claims();       // chapter3_trends.cpp
ClaimList chapter4_claims();              // chapter4.cpp
ClaimList chapter4_conservation_claims(); // chapter4_conservation.cpp
ClaimList chapter4_fig38_claims();        // chapter4_fig38.cpp
ClaimList chapter4_parameters_claims();   // chapter4_parameters.cpp
ClaimList chapter5_claims();              // chapter5.cpp
ClaimList chapter5_bilinear_claims();     // chapter5_bilinear.cpp
ClaimList chapter5_shapes_claims();       // chapter5_shapes.cpp

// Every registered claim, the files' lists one after the other.
const ClaimList& claim_registry();

// Where the registry and claims.md disagree, one sentence each: a key registered twice, a
// registered key without words in claims.md, a key of claims.md without a rule. Empty when they agree.
std::vector<std::string> registry_mismatches(const std::vector<std::string>& registered, const std::vector<std::string>& worded);

}  // namespace capsule::analysis::claims
