#include "study/plan/analysis_keys.hpp"

#include <utility>
#include <vector>

#include "analysis/report/analysis_block.hpp"
#include "analysis/report/scene_parameter.hpp"
#include "common/json_text.hpp"
#include "study/campaign/campaign_error.hpp"

namespace capsule::study {

void check_analysis_keys(const Campaign& campaign, const nlohmann::json& member_scene) {
  if (campaign.analysis.is_null()) return;
  const analysis::AnalysisBlock block = analysis::parse_analysis_block(campaign.analysis, campaign.source);
  std::vector<std::pair<std::string, std::string>> named;  // (where in the block, key)
  for (std::size_t i = 0; i < block.tables.size(); ++i)
    named.emplace_back("analysis.tables[" + std::to_string(i) + "] (\"" + block.tables[i].name + "\").x", block.tables[i].x);
  if (block.stability)
    for (const auto& p : block.stability->parameters) named.emplace_back("analysis.stability.parameters", p);
  for (std::size_t i = 0; i < block.ladders.size(); ++i)
    named.emplace_back("analysis.ladder[" + std::to_string(i) + "].key", block.ladders[i].key);
  if (block.bilinear && !block.bilinear->ladder.empty()) named.emplace_back("analysis.bilinear.ladder", block.bilinear->ladder);
  if (block.accuracy)
    for (const auto& s : block.accuracy->settings) named.emplace_back("analysis.accuracy.settings", s);
  for (std::size_t i = 0; i < block.published.size(); ++i)
    for (const auto& [key, value] : block.published[i].where)
      named.emplace_back("analysis.published[" + std::to_string(i) + "].where", key);
  for (const auto& [where, key] : named) {
    if (analysis::scene_value_at(member_scene, key)) continue;  // a dotted key at its path
    const analysis::SceneValue v = analysis::scene_parameter(member_scene, key, block.parameters);
    if (v.found || !v.pointer.empty()) continue;  // found (a string setting is compared as text)
    throw campaign_error(campaign.source, where,
                         message_value(key) + " is not a key of the member scenes (" + v.reason + ")",
                         "a scene key such as Ca, E_b, V, eta or resolution.a, or a name in analysis.parameters");
  }
}

}  // namespace capsule::study
