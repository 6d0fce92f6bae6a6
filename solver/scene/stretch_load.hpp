#pragma once
// The optical-tweezers load of a stretch protocol (scene key protocol.stretch,
// docs/guide/scenes.md "Stretching"): a total force F pulling each of two opposite membrane
// patches apart along x, in a fluid at rest.

namespace capsule {

// Lengths are in units of the membrane's radius (a, or r_m = a - resolution.marker_inset where the
// markers sit inside a: the stretch is the membrane's statics, so its size is the markers').
struct StretchLoad {
  double force = 0;     // F / (E_s a), E_s the modulus of Ca (34)
  double force_pN = 0;  // F in pN, when the scene gave it so (with a physical block); else 0
  bool force_in_pN = false;  // the scene gave force_pN (0 pN included), which its canonical form keeps
  // The patch: a fraction of the vertices at each end (Fedosov et al. 2010: 0.02), or the
  // bead's contact diameter (in units of a, or in um with a physical block); one is 0.
  double patch_fraction = 0;
  double contact_diameter = 0;
  double contact_diameter_um = 0;  // as given, when given in um; contact_diameter then holds it in a
};

}  // namespace capsule
