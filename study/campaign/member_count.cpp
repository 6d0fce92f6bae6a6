#include "study/campaign/member_count.hpp"

#include <string>

#include "study/campaign/campaign_error.hpp"

namespace capsule::study {

namespace {

// "Ca (3 values) x V (4 values)": the factors of a sweep's count.
std::string factors(const Sweep& sweep) {
  std::string text;
  for (const auto& axis : sweep.grid)
    text.append(text.empty() ? "" : " x ").append(axis.key + " (" + std::to_string(axis.values.size()) + " values)");
  if (!sweep.zip.empty())
    text.append(text.empty() ? "" : " x ")
        .append("zip (" + std::to_string(sweep.zip.front().values.size()) + " rows)");
  return text;
}

// The sweep's count, or 0 when it exceeds limit (every partial product is compared before it
// is formed, so nothing overflows).
std::size_t bounded_count(const Sweep& sweep, std::size_t limit) {
  std::size_t n = 1;
  const auto times = [&n, limit](std::size_t k) {
    if (k != 0 && n > limit / k) return false;
    n *= k;
    return true;
  };
  for (const auto& axis : sweep.grid)
    if (!times(axis.values.size())) return 0;
  if (!sweep.zip.empty() && !times(sweep.zip.front().values.size())) return 0;
  return n;
}

}  // namespace

void check_member_count(const Campaign& campaign) {
  const std::string limit = std::to_string(max_campaign_members);
  std::size_t total = 0;
  const auto add = [&](const Sweep& sweep, const std::string& path) {
    const std::size_t n = bounded_count(sweep, max_campaign_members);
    if (n == 0 || total + n > max_campaign_members)
      throw campaign_error(campaign.source, path,
                           factors(sweep) + (n == 0 ? " makes more than " + limit + " members"
                                                    : " makes " + std::to_string(n) + " members, " +
                                                          std::to_string(total + n) + " with the cases before it"),
                           "at most " + limit + " members in a campaign: split it");
    total += n;
  };
  if (campaign.cases.empty()) {
    add(campaign.sweep, "sweep");
    return;
  }
  for (std::size_t i = 0; i < campaign.cases.size(); ++i) {
    const CampaignCase& c = campaign.cases[i];
    add(c.sweep ? *c.sweep : campaign.sweep, c.sweep ? "cases[" + std::to_string(i) + "].sweep" : "sweep");
  }
}

}  // namespace capsule::study
