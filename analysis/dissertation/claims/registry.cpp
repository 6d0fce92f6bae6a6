#include "analysis/dissertation/claims/registry.hpp"

#include <algorithm>
#include <set>

namespace capsule::analysis::claims {

RegisteredClaim once(const std::string& key, ClaimResult (*rule)(const DissertationResults&)) {
  return {key, {rule}};
}

RegisteredClaim per_case(const std::string& key, ClaimResult (*rule)(const DissertationResults&, const std::string&)) {
  RegisteredClaim c{key, {}};
  for (const char* case_name : {"2d", "3d"})
    c.rows.push_back([rule, case_name](const DissertationResults& res) { return rule(res, case_name); });
  return c;
}

const ClaimList& claim_registry() {
  static const ClaimList all = [] {
    ClaimList out;
    for (ClaimList (*file)() : {chapter2_claims, chapter3_claims, chapter3_normalized_claims, chapter3_trends_claims,
                                chapter4_claims, chapter4_conservation_claims, chapter4_fig38_claims,
                                chapter4_parameters_claims, chapter5_claims, chapter5_bilinear_claims, chapter5_shapes_claims}) {
      ClaimList part = file();
      out.insert(out.end(), part.begin(), part.end());
    }
    return out;
  }();
  return all;
}

std::vector<std::string> registry_mismatches(const std::vector<std::string>& registered, const std::vector<std::string>& worded) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  const auto has = [](const std::vector<std::string>& keys, const std::string& key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
  };
  for (const auto& key : registered) {
    if (!seen.insert(key).second) out.push_back("the claim '" + key + "' is registered twice");
    else if (!has(worded, key)) out.push_back("the claim '" + key + "' has a rule but no words in analysis/dissertation/claims.md");
  }
  for (const auto& key : worded)
    if (!has(registered, key))
      out.push_back("the claim '" + key + "' of analysis/dissertation/claims.md has no rule in claims/ (no file's list registers it)");
  return out;
}

}  // namespace capsule::analysis::claims
