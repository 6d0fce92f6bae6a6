#pragma once
// Campaign -> members: every case x every sweep point becomes one complete scene,
// validated by the solver's Scene rules and named by its id (member_id.hpp).
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "study/campaign/campaign.hpp"

namespace capsule::study {

struct Member {
  std::size_t index = 0;   // position in the campaign's member list (plan order, Slurm task id)
  std::string case_name;   // empty when the campaign has no cases
  std::vector<std::string> other_cases;  // further cases that give this same scene (one-at-a-time
                                         // sweeps share their base point); it runs once
  std::vector<std::pair<std::string, nlohmann::json>> parameters;  // the swept keys and their values
  nlohmann::json scene;    // complete canonical scene (Scene::to_json)
  std::string id;          // member_id(scene, physics_version)
  std::string slug;        // readable: case and swept values, safe as a path component
  std::string dir_name() const { return slug + "-" + id; }
};

// Every member in plan order, one at a time, none kept: visit(member) for each new scene
// (other_cases empty), also_case(index, case) when a later case reaches the scene of member
// `index` again. Memory is the campaign plus about 40 bytes per member (the duplicate
// check), so `study plan` of a 10^6-member grid stays small.
// Throws CampaignError naming the file, the case and sweep point, and the scene problem.
// One scene reached twice within a case is refused (a mistake such as [0.1, 1e-1]); reached
// from several cases it is one member listing every case.
void for_each_member(const Campaign& campaign, const std::function<void(Member&&)>& visit,
                     const std::function<void(std::size_t, const std::string&)>& also_case);

// All members, with other_cases filled in (for_each_member, collected).
std::vector<Member> expand_campaign(const Campaign& campaign);

// "case-Ca0.04-E_b0.05": characters outside [A-Za-z0-9_.-] become '_', at most 80 long.
std::string member_slug(const std::string& case_name,
                        const std::vector<std::pair<std::string, nlohmann::json>>& parameters);

}  // namespace capsule::study
