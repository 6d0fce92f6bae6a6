#pragma once
// The solver's physics version: part of every member id. Bump it whenever a change
// alters the numbers a scene produces, so studies rerun members made by older physics.
namespace capsule {
// 2: MRT energy and energy-square rates follow s_nu (stability at large tau).
// 3: 2D Kelvin-Voigt membrane viscosity implicit in the node velocities.
// 4: "settled" recovery window grows with the time since the stop (window_fraction); scene
//    conventions (sls_viscosity, E_b_2d).
// 5: 3D relaxation-time rule tau = 1.5 (was 1), bounded by the measured stable S and B.
// 6: 3D: roma3 delta with the stresslet's marker inset (the smeared shell's hydrodynamic radius
//    removed), TRT collision (Lambda = 3/16), the power law in the membrane; 2D: the exact
//    Kelvin-Voigt step. Canonical scenes write every key.
inline constexpr const char* physics_version = "6";
}  // namespace capsule
