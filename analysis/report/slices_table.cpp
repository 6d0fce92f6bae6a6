#include "analysis/report/slices_table.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "analysis/report/table.hpp"
#include "solver/membrane3d/surface_geometry.hpp"

namespace capsule::analysis {

namespace {
bool is_3d(const io::MemberData::Shape& s) { return s.dim == 3 && !s.xyz.empty(); }

// The loop's points with the first repeated at the end when closed.
std::vector<std::array<double, 2>> drawn(const membrane3d::Polyline& l) {
  auto p = l.points;
  if (l.closed && !p.empty()) p.push_back(p.front());
  return p;
}
}  // namespace

bool has_3d_shapes(const io::MemberData& data) {
  if (data.triangles.empty()) return false;
  for (const auto& s : data.shapes)
    if (is_3d(s)) return true;
  return false;
}

MemberSlices member_slices(const io::MemberData& data, double a) {
  MemberSlices out;
  if (!has_3d_shapes(data)) return out;
  bool scale_set = std::isfinite(a) && a > 0.0;
  if (scale_set) out.scale = a;
  else out.unit = "r_V";
  for (const auto& s : data.shapes) {
    if (!is_3d(s)) continue;
    membrane3d::Mesh mesh;
    try {
      mesh = membrane3d::mesh_from_arrays(s.xyz, data.triangles);
    } catch (const std::exception& e) {
      throw std::runtime_error("shape at kt = " + format_number(s.kt) + ": " + e.what());
    }
    if (!scale_set) {
      const double V = membrane3d::enclosed_volume(mesh);
      if (!(V > 0.0)) throw std::runtime_error("shape at kt = " + format_number(s.kt) + ": enclosed volume <= 0");
      out.scale = std::cbrt(3.0 * V / (4.0 * std::numbers::pi));
      scale_set = true;
    }
    out.kt.push_back(s.kt);
    out.slices.push_back(membrane3d::central_slices(mesh, out.scale));
  }
  return out;
}

std::string slices_csv(const MemberSlices& slices) {
  std::ostringstream csv;
  csv << "kt,plane,loop,u,v\n";
  for (std::size_t i = 0; i < slices.kt.size(); ++i) {
    const auto& s = slices.slices[i];
    for (const auto& [plane, loops] : {std::pair{"xy", &s.xy}, std::pair{"yz", &s.yz}})
      for (std::size_t k = 0; k < loops->size(); ++k)
        for (const auto& p : drawn((*loops)[k]))
          csv << format_number(slices.kt[i]) << ',' << plane << ',' << k << ',' << format_number(p[0]) << ','
              << format_number(p[1]) << '\n';
  }
  return csv.str();
}

nlohmann::json slices_figure_json(const MemberSlices& slices) {
  nlohmann::json j{{"unit", slices.unit}, {"shapes", nlohmann::json::array()}};
  for (std::size_t i = 0; i < slices.kt.size(); ++i) {
    const auto& s = slices.slices[i];
    nlohmann::json sj{{"kt", slices.kt[i]}, {"theta", s.theta}};
    for (const auto& [plane, loops] : {std::pair{"xy", &s.xy}, std::pair{"yz", &s.yz}}) {
      sj[plane] = nlohmann::json::array();
      for (const auto& l : *loops) {
        std::vector<double> u, v;
        for (const auto& p : drawn(l)) {
          u.push_back(p[0]);
          v.push_back(p[1]);
        }
        sj[plane].push_back({{"u", u}, {"v", v}, {"closed", l.closed}});
      }
    }
    j["shapes"].push_back(sj);
  }
  return j;
}

}  // namespace capsule::analysis
