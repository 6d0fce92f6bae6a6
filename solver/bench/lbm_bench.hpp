#pragma once
// `capsule bench lbm`: MLUPS, bytes per update, STREAM-like bandwidth and roofline fraction.
namespace capsule::lbm {
int bench_lbm(bool quick, int max_threads);
}
