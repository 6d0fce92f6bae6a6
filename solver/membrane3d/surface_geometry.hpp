#pragma once
// Discrete surface geometry of a closed outward-oriented triangle mesh: areas, enclosed
// volume, Voronoi areas (83) and the cotangent Laplace-Beltrami operator (81)-(82).
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// (x_j - x_i) x (x_k - x_i): twice the area times the outward unit normal.
Vec3 triangle_area_vector(const Mesh& mesh, int t);
double surface_area(const Mesh& mesh);
// Enclosed volume by the divergence theorem, (1/6) sum x_i . (x_j x x_k); positive for outward orientation.
double enclosed_volume(const Mesh& mesh);
// Unweighted average of the outward unit normals of the incident triangles (Sec. 2.5.4).
std::vector<Vec3> averaged_vertex_normals(const Mesh& mesh);
void averaged_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out);  // reusing out's storage
// The same, keeping each triangle's outward unit normal in triangle_normal (storage reused).
void averaged_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out, std::vector<Vec3>& triangle_normal);

// Voronoi area (83) of every vertex, a_vor = (1/8) sum (cot alpha_j + cot beta_j) |x_p - x_j|^2.
// For an obtuse triangle the circumcentre leaves the triangle and (83) over-counts; there the
// "mixed" area of Meyer et al. (2003), the paper the text's (83) comes from, is used:
// half the triangle's area to the obtuse corner and a quarter to each other one. The mixed
// areas of all vertices sum exactly to the surface area.
std::vector<double> voronoi_areas(const Mesh& mesh);
void voronoi_areas(const Mesh& mesh, std::vector<double>& out);  // reusing out's storage

// Cotangent Laplace-Beltrami operator (81)-(82):
//   (Delta f)(p) = (1 / a_vor(p)) sum_j (cot alpha_j + cot beta_j)/2 (f_j - f_p).
// NOTE the sign: (81) prints (f_p - f_j), which is MINUS the Laplace-Beltrami operator
// (it would give +l(l+1)/R^2 on a spherical harmonic); the standard sign is used here.
class LaplaceBeltrami {
 public:
  LaplaceBeltrami() = default;
  // Computes the cotangent weights and Voronoi areas for the current positions.
  explicit LaplaceBeltrami(const Mesh& mesh);
  // The same for new positions of a mesh of the same topology, reusing the storage.
  void update(const Mesh& mesh);
  std::vector<double> apply(const std::vector<double>& f) const;
  void apply(const std::vector<double>& f, std::vector<double>& out) const;
  const std::vector<double>& areas() const { return area_; }

 private:
  // Per vertex, per ring neighbour: (cot a + cot b)/2, flat; vertex v's run starts at
  // offset_[v] and follows mesh.ring[v] (neighbour_ holds the same indices, flat).
  std::vector<double> weight_;
  std::vector<int> neighbour_;
  std::vector<std::size_t> offset_;
  std::vector<double> area_;
  // Per triangle t and corner c, at 3 t + c: the cotangent of the angle and the share of the
  // corner's Voronoi area; per weight, where the cotangents at r[j-1] and r[j+1] sit in cot_.
  std::vector<double> cot_, share_;
  std::vector<int> angle_before_, angle_after_;
};

}  // namespace capsule::membrane3d
