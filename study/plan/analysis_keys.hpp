#pragma once
// The scene keys a campaign's analysis block names (tables' x, the stability parameters, the
// ladders' and the bilinear model's resolution key, the accuracy settings, the published
// curves' filters), looked up in a member's canonical scene as the report will look them up:
// a key the scene lacks is refused at plan, not found missing after the campaign ran.
#include <nlohmann/json.hpp>

#include "study/campaign/campaign.hpp"

namespace capsule::study {

// Throws CampaignError naming the campaign file, the analysis entry and the key, when
// member_scene (a canonical member scene of the campaign) has no numeric value for it.
void check_analysis_keys(const Campaign& campaign, const nlohmann::json& member_scene);

}  // namespace capsule::study
