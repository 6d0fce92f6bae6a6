// The D2Q9 stream-collide passes in float, both streaming patterns (stream_collide.hpp).
#include "solver/lbm/stream_collide.hpp"

namespace capsule::lbm {

template void stream_collide_pass<D2Q9, float>(const InPlaceFields<float>&, bool, bool, bool);
template void stream_collide_pass<D2Q9, float>(const ShiftedFields<float>&, bool, bool);

}  // namespace capsule::lbm
