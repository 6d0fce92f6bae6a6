#pragma once
// The number of members a campaign makes, bounded: a product of sweep lengths that overflows
// or is absurdly large is refused before anything is expanded.
#include <cstddef>

#include "study/campaign/campaign.hpp"

namespace capsule::study {

// At most this many members in one campaign (the planner is tested at 10^6).
inline constexpr std::size_t max_campaign_members = 10'000'000;

// Throws CampaignError naming the sweep, its keys with their lengths, and the limit, when the
// campaign (every case's sweep together) makes more than max_campaign_members members.
void check_member_count(const Campaign& campaign);

}  // namespace capsule::study
