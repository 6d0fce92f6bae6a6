#pragma once
// One fused stream-collide pass of lattice L on populations stored as T, its variant (per-node
// or uniform rates, MRT or TRT) chosen at run time. T computes in T: single precision collides
// in float (docs/findings/performance.md "Single against double").
// The passes are compiled once per lattice and precision, each in its own source
// (stream_collide_<lattice>_<precision>.cpp), so the unrolled, CPU-cloned kernels build in
// parallel and an edit of Fluid (fluid.cpp) does not rebuild them.
#include "solver/lbm/in_place_stream_collide.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/shifted_stream_collide.hpp"

namespace capsule::lbm {

// The AA pattern in one array (in_place_stream_collide.hpp); odd: the swapped step.
template <class L, class T>
void stream_collide_pass(const InPlaceFields<T>& a, bool odd, bool per_node, bool trt) {
  if (per_node && trt) in_place_stream_collide<L, T, T, true, true>(a, odd);
  else if (per_node) in_place_stream_collide<L, T, T, true>(a, odd);
  else if (trt) in_place_stream_collide<L, T, T, false, true>(a, odd);
  else in_place_stream_collide<L, T, T, false>(a, odd);
}

// Two lattices, shifted populations (shifted_stream_collide.hpp).
template <class L, class T>
void stream_collide_pass(const ShiftedFields<T>& a, bool per_node, bool trt) {
  if (per_node && trt) shifted_stream_collide<L, T, T, true, true>(a);
  else if (per_node) shifted_stream_collide<L, T, T, true>(a);
  else if (trt) shifted_stream_collide<L, T, T, false, true>(a);
  else shifted_stream_collide<L, T, T, false>(a);
}

// Compiled in stream_collide_<lattice>_<precision>.cpp, nowhere else.
extern template void stream_collide_pass<D2Q9, float>(const InPlaceFields<float>&, bool, bool, bool);
extern template void stream_collide_pass<D2Q9, float>(const ShiftedFields<float>&, bool, bool);
extern template void stream_collide_pass<D2Q9, double>(const InPlaceFields<double>&, bool, bool, bool);
extern template void stream_collide_pass<D2Q9, double>(const ShiftedFields<double>&, bool, bool);
extern template void stream_collide_pass<D3Q19, float>(const InPlaceFields<float>&, bool, bool, bool);
extern template void stream_collide_pass<D3Q19, float>(const ShiftedFields<float>&, bool, bool);
extern template void stream_collide_pass<D3Q19, double>(const InPlaceFields<double>&, bool, bool, bool);
extern template void stream_collide_pass<D3Q19, double>(const ShiftedFields<double>&, bool, bool);

}  // namespace capsule::lbm
