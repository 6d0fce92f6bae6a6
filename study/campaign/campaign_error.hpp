#pragma once
// A refused campaign file. what() reads "<file>: <json path>: <problem> (expected: <what>)".
#include <stdexcept>
#include <string>

namespace capsule::study {

struct CampaignError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Builds the message above; json_path may be empty (the whole document).
CampaignError campaign_error(const std::string& source, const std::string& json_path, const std::string& problem,
                             const std::string& expected = "");

}  // namespace capsule::study
