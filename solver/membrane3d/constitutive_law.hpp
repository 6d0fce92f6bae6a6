#pragma once
// The 3D membrane's elastic law by name (the scene's `law`, `capsule reference-bim --law`) and
// the one switch from that name to the law's formulas (laws/neo_hookean.hpp, laws/skalak.hpp,
// each a HyperelasticLaw). A new law: its file in laws/, a name here, a case in visit_law.
#include <stdexcept>
#include <utility>

#include "solver/common/name_table.hpp"
#include "solver/membrane3d/laws/neo_hookean.hpp"
#include "solver/membrane3d/laws/skalak.hpp"

namespace capsule::membrane3d {

enum class ElasticLaw { neo_hookean, skalak };
inline constexpr NameTable<ElasticLaw, 2> elastic_law_names{{{ElasticLaw::neo_hookean, "neo-hookean"},
                                                             {ElasticLaw::skalak, "skalak"}}};
constexpr const auto& name_table(ElasticLaw) { return elastic_law_names; }

// A law and its parameters.
struct Constitutive {
  ElasticLaw law = ElasticLaw::neo_hookean;
  double E_s = 1;  // the modulus the law's formulas take (law_modulus)
  double C = 15;   // Skalak area-dilation constant

  // Energy per reference area, the second Piola-Kirchhoff tension S = 2 dW/dC and the principal
  // Cauchy tensions of the law (one call each; a loop over elements calls visit_law once).
  double energy_density(const Mat2& C) const;
  Mat2 second_piola_kirchhoff(const Mat2& C) const;
  std::pair<double, double> principal_cauchy(double lambda1, double lambda2) const;
};

// Calls f with the law's formulas (a NeoHookean or a Skalak): the one switch over the laws.
template <class F>
decltype(auto) visit_law(const Constitutive& k, F&& f) {
  switch (k.law) {
    case ElasticLaw::neo_hookean: return std::forward<F>(f)(NeoHookean{k.E_s});
    case ElasticLaw::skalak: return std::forward<F>(f)(Skalak{k.E_s, k.C});
  }
  throw std::logic_error("membrane3d: an elastic law without formulas");
}

// The modulus the law's formulas take (Constitutive::E_s) for the E_s of Ca = mu k a / E_s (34)
// (docs/conventions.md "Neo-Hookean modulus"): neo-Hookean E_s/3, Skalak E_s as printed.
double law_modulus(ElasticLaw law, double E_s);

}  // namespace capsule::membrane3d
