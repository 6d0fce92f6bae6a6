#pragma once
// Members that another campaign under the same results root has already run. A member's id is
// the hash of its canonical scene and the physics version (member_id.hpp), so a complete member
// folder "<slug>-<id>" in <results>/<other campaign>/members/ holds exactly what running the
// member here would compute (same scene, same physics; on the same CPU bitwise, at any thread
// count, docs/guide/model.md "Fluid"). `study run` copies such a member instead of running it and `study plan`
// leaves it out of the cost: the campaigns that regenerate the dissertation share 26 members
// (a base member of ch3_ca is also one of ch3_eb and ch3_v; the probes reuse campaign members).
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "study/campaign/expansion.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

struct FinishedMember {
  std::filesystem::path dir;  // <results>/<campaign>/members/<slug>-<id>
  std::string campaign;       // the campaign folder's name
};

class ReusableMembers {
 public:
  // Indexes the member folders of every campaign folder under results_root except own_root.
  ReusableMembers(const std::filesystem::path& results_root, const std::filesystem::path& own_root);

  // A complete member with m's id whose scene.json is m's scene (first campaign by name) and
  // whose member file passes reuse_refusal, if any. A candidate refused for its file is named
  // on *notes with the reason, when notes is given.
  std::optional<FinishedMember> find(const Member& m, std::ostream* notes = nullptr) const;

 private:
  std::map<std::string, std::vector<FinishedMember>> by_id_;
};

// Why the member file h5 may not be copied into another campaign, "" when it may: it must read
// whole (every dataset's checksum, and the content hash where the file records one, see
// solver/io/member_file.hpp) and hold the series every member writes (io::missing_series).
std::string reuse_refusal(const std::filesystem::path& h5);

// Copies a finished member's files into target (member.h5 under a temporary name, then renamed;
// capsule.log with a line naming the source; exit_status), and removes what an interrupted
// attempt left there (.partial, .restart, .progress). The copy is read back before it is
// renamed into place; throws std::runtime_error (and leaves nothing) when it does not read whole.
void copy_finished_member(const FinishedMember& source, const MemberPaths& target);

// Copies every member of `candidates` that another campaign finished, prints one line each,
// and returns the indices copied. Used by `study run` before it hands the rest to GNU Parallel.
std::vector<std::size_t> copy_reusable_members(const std::vector<Member>& members,
                                                         const std::vector<std::size_t>& candidates,
                                                         const ResultsLayout& layout, std::ostream& out);

}  // namespace capsule::study
