#pragma once
// results/<name>/ belongs to one campaign file. Two files that share a "name" but differ
// in content would share the folder and overwrite each other's campaign.json, so the
// second is refused, naming both paths. The same file edited (same path, new content) or
// the same content moved (new path) is still the same campaign.
#include "study/campaign/campaign.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

// Throws CampaignError when layout.campaign_json() holds another text recorded as coming
// from another file (layout.campaign_source()).
void require_same_campaign(const Campaign& campaign, const ResultsLayout& layout);

// Records campaign.json and campaign_source for the check above (both written atomically).
void record_campaign(const Campaign& campaign, const ResultsLayout& layout);

}  // namespace capsule::study
