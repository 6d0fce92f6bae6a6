#pragma once
// Central slices of a 3D member's stored shapes for the report (Figs. 41-53, Sec. 4.2):
// each shape mapped to theta = 0 and cut by z = z_c (xy) and x = x_c (yz), in units of a.
// Written as slices_<slug>.csv and drawn as figures/member_<slug>_slices.png.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/io/member_file.hpp"
#include "solver/membrane3d/slices.hpp"

namespace capsule::analysis {

struct MemberSlices {
  double scale = 1.0;         // the length unit the slices are divided by
  std::string unit = "a";     // "a" (the scene's radius) or "r_V" (volume-equivalent radius)
  std::vector<double> kt;     // one per sliced shape, in the member file's order
  std::vector<membrane3d::CentralSlices> slices;
  bool empty() const { return kt.empty(); }
};

// True when the member stores at least one 3D shape together with its triangles.
bool has_3d_shapes(const io::MemberData& data);

// Slices of every stored 3D shape. `a` is the capsule radius in the shapes' units (the
// scene's resolution.a); when it is not finite and positive, the first shape's
// volume-equivalent radius (3 V / 4 pi)^(1/3) is used instead and `unit` says so.
// Throws std::runtime_error when a shape does not fit the triangles (bad file).
MemberSlices member_slices(const io::MemberData& data, double a);

// CSV with header kt,plane,loop,u,v: plane xy has (u, v) = (x, y), plane yz has (u, v) = (z, y),
// relative to the centroid after rotating by -theta about z, divided by the scale; loops are
// numbered from 0 per shape and plane, and a closed loop ends by repeating its first point.
std::string slices_csv(const MemberSlices& slices);

// {"unit", "shapes": [{"kt", "theta", "xy": [{"u": [...], "v": [...], "closed"}], "yz": [...]}]}
// for figure_data.json (closed loops repeat their first point, as in the CSV).
nlohmann::json slices_figure_json(const MemberSlices& slices);

}  // namespace capsule::analysis
