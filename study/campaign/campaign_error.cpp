#include "study/campaign/campaign_error.hpp"

#include "common/json_text.hpp"

namespace capsule::study {

CampaignError campaign_error(const std::string& source, const std::string& json_path, const std::string& problem,
                             const std::string& expected) {
  // Built with append: GCC 12 -O3 reports a false -Wrestrict on chained operator+ here.
  std::string message = source;
  message.append(": ").append(json_path.empty() ? std::string("(top level)") : message_text(json_path));
  message.append(": ").append(problem);
  if (!expected.empty()) message.append(" (expected: ").append(expected).append(")");
  return CampaignError(message);
}

}  // namespace capsule::study
