#include "study/plan/measured_speed.hpp"

#include <cmath>

#include "solver/io/member_file.hpp"

namespace capsule::study {

bool add_measurement(MeasuredSpeed& speed, const Member& member, const MemberPaths& paths) {
  std::error_code ec;
  if (!std::filesystem::exists(paths.h5, ec)) return false;
  io::MemberStatus s;
  try {
    s = io::read_member_status(paths.h5.string());
  } catch (const std::exception&) {
    return false;
  }
  if (s.member_id != member.id || !std::isfinite(s.wall_seconds) || !std::isfinite(s.steps) || s.steps <= 0) return false;
  const int dim = member.scene.at("dim").get<int>();
  speed.for_dim(dim).add(estimate_cost(member.scene, &speed.lengths), s.steps, static_cast<int>(std::max(1L, s.threads)), s.wall_seconds);
  return true;
}

MeasuredSpeed measure_speed(const CampaignSurvey& survey) {
  MeasuredSpeed speed;
  speed.lengths = PhaseLengths::known(survey.layout.root.parent_path());
  for (const auto& m : survey.members) add_measurement(speed, m, survey.layout.member(m));
  return speed;
}

}  // namespace capsule::study
