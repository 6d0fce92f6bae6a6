#pragma once
// results/<name>/ belongs to one campaign file. Two files that share a "name" but differ
// in content would share the folder and overwrite each other's campaign.json, so the
// second is refused, naming both paths. The same file edited (same path, new content) or
// the same content moved (new path) is still the same campaign.
//
// Which file made the folder is known from its content, not only from the git-ignored
// campaign_source (a fresh clone has none, and campaign files move): when campaign.json (the
// campaign as last run, shipped with the results) differs from the campaign given, another
// campaign file that still holds exactly campaign.json's campaign (in the given file's folder, or
// anywhere under the campaigns/ folder beside the results folder) is the owner, and the given file is a
// different one. Found nowhere, the given file is taken for the owner, edited.
#include "study/campaign/campaign.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

// Throws CampaignError, before anything is written, when the folder belongs to another file:
// campaign_source names another file that still exists, or another campaign file holds the
// campaign recorded in campaign.json.
void require_same_campaign(const Campaign& campaign, const ResultsLayout& layout);

// Records campaign.json and campaign_source for the check above (both written atomically).
void record_campaign(const Campaign& campaign, const ResultsLayout& layout);

}  // namespace capsule::study
