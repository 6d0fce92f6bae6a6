#include "solver/app/shapes_command.hpp"

#include <memory>

#include "solver/app/choice_option.hpp"
#include "solver/run/shape_rerun.hpp"

namespace capsule::cli {

Command add_shapes_command(CLI::App& capsule) {
  auto o = std::make_shared<ShapeRerunOptions>();
  CLI::App& app = *capsule.add_subcommand(
      "shapes", "write the membrane's shapes of a finished member at chosen times, by rerunning it as far as needed");
  app.footer(
      "The member's scene is rerun from its restart point (MEMBER/member.h5.restart, when one precedes the first\n"
      "time) or from kt = 0, and stops at the output row of the last time asked for. The rerun's rows are compared\n"
      "with the member's series: unless they are the same bit for bit (as they are for the same physics and\n"
      "C library) nothing is written, unless --accept-difference. member.h5 is only read.\n"
      "docs/guide/member-files.md \"Shapes of a finished member\".\n"
      "Examples:\n"
      "  capsule shapes results/demo/members/<member> --at-kt 0.5,1,2\n"
      "  capsule shapes results/ch3_ca/members/<member> --at-kt 2 --snapshots vtk -o ca_shapes.h5\n"
      "Exit status: 0 written, 1 the rerun failed or does not reproduce the member (nothing written),\n"
      "2 bad member folder, time, output path or command line (nothing run).");
  app.add_option("member", o->member, "the member's folder (results/<campaign>/members/<member>) or a member file")
      ->required();
  app.add_option("--at-kt", o->at_kt, "times in units of 1/k, comma-separated, within the member's rows")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(finite_number_in(0, 1e5, /*low_included=*/true));
  add_choice_option(app, "--snapshots", o->snapshots, "vtk: also .vtp frames and a .pvd beside the output (3D)");
  app.add_option("-o,--output", o->output_path, "shape file to write (default MEMBER/shapes.h5)");
  app.add_option("--threads", o->threads, "OpenMP threads (0 = the member's own count)")
      ->check(whole_number_at_least(0));
  app.add_option("--restart", o->restart_path, "a restart point of this member's run to continue from "
                                               "(default MEMBER/member.h5.restart when there is one)");
  app.add_flag("--accept-difference", o->accept_difference,
               "write the shapes even when the rerun's series are not the member's bit for bit");
  app.add_flag("-q,--quiet", o->quiet, "no progress lines");
  return {&app, [o] { return write_member_shapes(*o); }};
}

}  // namespace capsule::cli
