// The D2Q9 stream-collide passes in double, both streaming patterns (stream_collide.hpp).
#include "solver/lbm/stream_collide.hpp"

namespace capsule::lbm {

template void stream_collide_pass<D2Q9, double>(const InPlaceFields<double>&, bool, bool, bool);
template void stream_collide_pass<D2Q9, double>(const ShiftedFields<double>&, bool, bool);

}  // namespace capsule::lbm
