// write_report on 3D members: central slices of stored shapes (Figs. 41-53) written as
// slices_<slug>.csv beside the member table and drawn as member_<slug>_slices.png; the surface
// shear rate range of power-law members (Fig. 64) drawn as member_<slug>_gamma.png.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "analysis/report/report.hpp"
#include "solver/io/member_file.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using capsule::analysis::testing::lines;
using capsule::analysis::testing::slurp;
using capsule::analysis::testing::TempDir;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;
namespace m3 = capsule::membrane3d;

namespace {


std::vector<double> flat(const m3::Mesh& m) {
  std::vector<double> xyz;
  for (const auto& p : m.x) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  return xyz;
}

// A complete member with a response/recovery D_xy series (as the synthetic campaign) and the
// given shapes. dim 3 shapes carry the icosphere's triangles. power_law: the gamma_min and
// gamma_max columns of a power-law member.
void write_member(const std::string& path, const nlohmann::json& scene, int dim,
                  const std::vector<std::pair<double, std::vector<double>>>& shapes, const std::vector<int>& triangles,
                  bool power_law = false) {
  fs::create_directories(fs::path(path).parent_path());
  capsule::io::MemberWriter w(path);
  w.set_scene(scene);
  w.set_attribute("dim", static_cast<long>(dim));
  for (int i = 0; i <= 240; ++i) {
    const double t = 0.05 * i;
    const bool shear = t <= 6.0 + 1e-12;
    const double D = shear ? 0.3 * (1 - std::exp(-t / 0.5)) : 0.3 * std::exp(-(t - 6.0) / 0.6);
    std::map<std::string, double> row{{"kt", t}, {"D_xy", D}, {"theta", 0.4}, {"shear_on", shear ? 1.0 : 0.0}};
    if (power_law) row["gamma_min"] = 0.01 + 0.001 * i, row["gamma_max"] = 0.3 + 0.001 * i;
    w.append(row);
  }
  const double nan = std::nan("");
  w.set_markers({{"t_max", 6.0}, {"D_max", 0.3}, {"t_stop", 6.0}, {"D_stop", 0.3},
                 {"t_min", nan}, {"D_min", nan}, {"t_end", 12.0}, {"D_inf", nan}});
  for (const auto& [kt, xyz] : shapes) w.add_shape(kt, xyz, dim, triangles);
  w.finish("complete");
}

struct Row {
  double kt;
  std::string plane;
  int loop;
  double u, v;
};
std::vector<Row> read_slices_csv(const fs::path& p) {
  const auto l = lines(slurp(p));
  REQUIRE(!l.empty());
  CHECK(l[0] == "kt,plane,loop,u,v");
  std::vector<Row> rows;
  for (std::size_t i = 1; i < l.size(); ++i) {
    std::istringstream in(l[i]);
    std::string kt, plane, loop, u, v;
    std::getline(in, kt, ',');
    std::getline(in, plane, ',');
    std::getline(in, loop, ',');
    std::getline(in, u, ',');
    std::getline(in, v, ',');
    rows.push_back({std::stod(kt), plane, std::stoi(loop), std::stod(u), std::stod(v)});
  }
  return rows;
}

}  // namespace

TEST_CASE("write_report writes central slices of 3D members' shapes in units of a", "[analysis][slices]") {
  TempDir tmp("slices");
  const double a = 5.0;
  const m3::Mesh unit = m3::unit_icosphere(3);
  std::vector<int> tri;
  for (const auto& t : unit.triangles) tri.insert(tri.end(), t.begin(), t.end());
  // kt = 0: the sphere of radius a; kt = 6: an ellipsoid with semi-axes (1.3, 0.8, 0.9) a
  // inclined by 0.5 rad. Both away from the origin, as in a lattice.
  m3::Mesh sphere = m3::sphere_mesh(unit, a);
  m3::rotate_about_z_and_translate(sphere, 0.0, m3::Vec3(20, 21, 22));
  m3::Mesh ell = unit;
  for (auto& p : ell.x) p = a * m3::Vec3(1.3 * p.x(), 0.8 * p.y(), 0.9 * p.z());
  m3::rotate_about_z_and_translate(ell, 0.5, m3::Vec3(20, 21, 22));

  ReportRequest req;
  req.campaign_name = "slices";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response", "recovery"}}, {"figures", true}};
  const nlohmann::json scene3{{"dim", 3}, {"Ca", 0.05}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
                              {"resolution", {{"a", a}, {"mesh_level", 3}}}};
  const std::string p3 = (tmp.path / "members" / "s3" / "member.h5").string();
  write_member(p3, scene3, 3, {{0.0, flat(sphere)}, {6.0, flat(ell)}}, tri);
  req.members.push_back({"id3", "sphere/3d", p3, "sphere", nlohmann::json()});
  // A 3D member whose scene has no "a": the volume-equivalent radius is the unit.
  nlohmann::json scene_no_a = scene3;
  scene_no_a.erase("resolution");
  const std::string pv = (tmp.path / "members" / "sv" / "member.h5").string();
  write_member(pv, scene_no_a, 3, {{0.0, flat(sphere)}}, tri);
  req.members.push_back({"idv", "no_a", pv, "sphere", nlohmann::json()});
  // A 2D member with a stored contour: no slices.
  std::vector<double> contour;
  for (int i = 0; i < 64; ++i) contour.insert(contour.end(), {a * std::cos(i * 0.1), a * std::sin(i * 0.1)});
  const std::string p2 = (tmp.path / "members" / "s2" / "member.h5").string();
  nlohmann::json scene2 = scene3;
  scene2["dim"] = 2;
  write_member(p2, scene2, 2, {{0.0, contour}}, {});
  req.members.push_back({"id2", "circle2d", p2, "circle", nlohmann::json()});

  const ReportSummary summary = write_report(req);
  const fs::path out(req.out_dir);
  REQUIRE(fs::exists(out / "slices_sphere_3d.csv"));
  CHECK(fs::exists(out / "slices_no_a.csv"));
  CHECK_FALSE(fs::exists(out / "slices_circle2d.csv"));  // 2D members unaffected

  const auto rows = read_slices_csv(out / "slices_sphere_3d.csv");
  std::set<std::pair<double, std::string>> seen;
  // Level-3 icosphere: edges subtend at most 0.165 rad (measured in test_slices.cpp), so slice
  // points lie within 1 - cos(0.0824) = 3.4e-3 of the sphere (chords); plus 6-digit CSV rounding.
  const double chord = 3.5e-3;
  std::map<std::string, double> max_u, max_v;
  for (const auto& r : rows) {
    seen.insert({r.kt, r.plane});
    CHECK(r.loop == 0);  // one closed loop per plane
    if (r.kt == 0.0) {
      const double rad = std::hypot(r.u, r.v);
      CHECK(rad <= 1.0 + 1e-5);
      CHECK(rad >= 1.0 - chord);
    } else {
      max_u[r.plane] = std::max(max_u[r.plane], std::abs(r.u));
      max_v[r.plane] = std::max(max_v[r.plane], std::abs(r.v));
    }
  }
  CHECK(seen == std::set<std::pair<double, std::string>>{{0.0, "xy"}, {0.0, "yz"}, {6.0, "xy"}, {6.0, "yz"}});
  // The ellipsoid mapped to theta = 0: xy shows semi-axes 1.3 and 0.8, yz (u = z, v = y) 0.9 and
  // 0.8; extremal points are within 1 - cos^2(0.0824) = 6.8e-3 relative of the axes.
  CHECK(max_u["xy"] == Approx(1.3).epsilon(7e-3));
  CHECK(max_v["xy"] == Approx(0.8).epsilon(7e-3));
  CHECK(max_u["yz"] == Approx(0.9).epsilon(7e-3));
  CHECK(max_v["yz"] == Approx(0.8).epsilon(7e-3));
  CHECK(max_u["xy"] <= 1.3 + 1e-5);

  // Without a: units of the volume-equivalent radius, which for the inscribed polyhedron is a
  // little below a, so the slice radii come out a little above 1 (at most the chord error).
  for (const auto& r : read_slices_csv(out / "slices_no_a.csv")) {
    const double rad = std::hypot(r.u, r.v);
    CHECK(rad == Approx(1.0).margin(chord));
  }

  const auto j = nlohmann::json::parse(slurp(out / "fits.json"));
  for (const auto& m : j["members"]) {
    INFO(m["slug"]);
    if (m["slug"] == "sphere/3d") {
      CHECK(m["slices"]["file"] == "slices_sphere_3d.csv");
      CHECK(m["slices"]["unit"] == "a");
    } else if (m["slug"] == "no_a") {
      CHECK(m["slices"]["unit"] == "r_V");
    } else {
      CHECK_FALSE(m.contains("slices"));
    }
  }

  const fs::path fig = out / "figures";
  const auto fd = nlohmann::json::parse(slurp(fig / "figure_data.json"));
  REQUIRE(fd["slices"].size() == 2);
  CHECK(fd["slices"][0]["slug"] == "sphere_3d");
  CHECK(fd["slices"][0]["shapes"].size() == 2);
  CHECK(fd["slices"][0]["shapes"][1]["theta"].get<double>() == Approx(0.5).margin(1e-9));
  if (summary.figures_skipped) {
    WARN("figures skipped: " << summary.figures_note);
    CHECK_THAT(summary.figures_note, Contains("skipped"));
  } else {
    CHECK(fs::exists(fig / "member_sphere_3d_slices.png"));
    CHECK(fs::exists(fig / "member_no_a_slices.png"));
    CHECK_FALSE(fs::exists(fig / "member_circle2d_slices.png"));
    CHECK(fs::exists(fig / "member_circle2d.png"));  // the 2D member's D_xy figure as before
  }
}

TEST_CASE("write_report draws the surface shear rate range of power-law members (Fig. 64)", "[analysis]") {
  TempDir tmp("gamma");
  ReportRequest req;
  req.campaign_name = "gamma";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response"}}, {"figures", true}};
  const nlohmann::json scene{{"dim", 3}, {"Ca", 0.1}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
                             {"power_law", {{"K", 10.0}, {"n", 0.64}}}};
  const std::string pl = (tmp.path / "members" / "pl" / "member.h5").string();
  const std::string el = (tmp.path / "members" / "el" / "member.h5").string();
  write_member(pl, scene, 3, {}, {}, true);
  write_member(el, scene, 3, {}, {}, false);
  req.members.push_back({"idp", "power", pl, "", nlohmann::json()});
  req.members.push_back({"ide", "elastic", el, "", nlohmann::json()});
  const ReportSummary summary = write_report(req);
  const fs::path fig = fs::path(req.out_dir) / "figures";
  const auto fd = nlohmann::json::parse(slurp(fig / "figure_data.json"));
  REQUIRE(fd["members"].size() == 2);
  for (const auto& m : fd["members"]) {
    INFO(m["slug"]);
    if (m["slug"] == "power") {
      REQUIRE(m.contains("gamma"));
      CHECK(m["gamma"]["min"].size() == m["kt"].size());
      CHECK(m["gamma"]["max"][0].get<double>() == Approx(0.3));
      CHECK(m["gamma"]["min"].back().get<double>() == Approx(0.25));
    } else {
      CHECK_FALSE(m.contains("gamma"));
    }
  }
  if (summary.figures_skipped) {
    WARN("figures skipped: " << summary.figures_note);
  } else {
    CHECK(fs::exists(fig / "member_power_gamma.png"));
    CHECK_FALSE(fs::exists(fig / "member_elastic_gamma.png"));
    CHECK(fs::exists(fig / "member_power.png"));
  }
}
