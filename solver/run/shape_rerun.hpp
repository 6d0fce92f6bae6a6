#pragma once
// `capsule shapes`: the membrane's shape at chosen times of a member that has ended, which its
// member file did not store (docs/guide/member-files.md "Shapes of a finished member"). The
// member's own scene is rerun only as far as the last time asked for, from the member's restart
// point when one precedes the first time, else from kt = 0; the rerun's rows are compared with
// the member's series (a run is deterministic for one scene, build and thread count), and the
// shapes go to a separate file with the member file's /shapes layout. member.h5 is only read.
#include <cstddef>
#include <string>
#include <vector>

#include "solver/io/member_file.hpp"
#include "solver/scene/scene.hpp"

namespace capsule {

struct ShapeRerunOptions {
  std::string member;              // the member's folder (member.h5, scene.json) or a member file
  std::vector<double> at_kt;       // the times, in units of 1/k, within the member's rows
  Snapshots snapshots = Snapshots::none;  // vtk: .vtp frames and a .pvd beside the output (3D)
  std::string output_path;         // "": <folder>/shapes.h5, or <file less .h5>_shapes.h5 for a member file
  int threads = 0;                 // 0: the member's own thread count (its attribute `threads`)
  std::string restart_path;        // "": the member's own <member file>.restart, when there is one
  bool accept_difference = false;  // write the shapes even when the rerun does not reproduce the member
  bool quiet = false;              // no progress lines
};

// The rerun's rows against the member's: the largest absolute difference over every series both
// hold (beta included) and every row of the rerun; two NaNs count as equal.
struct SeriesDifference {
  std::size_t rows = 0;         // rows compared
  bool bitwise = true;          // every compared value has the same bits
  double largest = 0;           // the largest |rerun - member| (infinite for a NaN against a number)
  std::string column;           // where it is ("" when every value agrees)
  double at_kt = 0;
  std::vector<std::string> not_compared;  // series in only one of the two
  std::string row_count;        // "" or why the rows could not all be compared
};
SeriesDifference compare_series(const io::MemberWriter& rerun, const io::MemberData& member);

// The rerun counts as the member's run only when its rows are the member's bit for bit: a run is
// deterministic for one scene and physics, on 1 or 2 threads alike (tests/solver/run/member3d_threads_test.cpp),
// and the shipped members rerun by a later build of the same physics reproduce bitwise
// (docs/guide/member-files.md "Shapes of a finished member"). Any difference (another physics, a
// C library that rounds otherwise) is reported with its size and refused unless accepted.
// Exit status: 0 the shapes are written; 1 the rerun failed, or does not reproduce the member's
// series bitwise (nothing written unless accept_difference); 2 bad input (not a
// member, a member that has not ended, a time outside its rows, a bad output path): nothing run.
// Messages on stderr.
int write_member_shapes(const ShapeRerunOptions& options);

}  // namespace capsule
