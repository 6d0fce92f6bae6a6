// jobs x threads: many single-threaded 2D members at once; a 3D member takes every core.
#include <catch2/catch.hpp>

#include "study/plan/concurrency.hpp"

using namespace capsule::study;

TEST_CASE("jobs x threads follow the cores and the members' dimension", "[study]") {
  auto c = choose_concurrency(8, 20, false, 0, 0);
  CHECK((c.jobs == 8 && c.threads == 1));
  c = choose_concurrency(8, 3, false, 0, 0);  // never more slots than members
  CHECK((c.jobs == 3 && c.threads == 1));
  c = choose_concurrency(8, 5, true, 0, 0);
  CHECK((c.jobs == 1 && c.threads == 8));
  c = choose_concurrency(8, 5, true, 2, 0);  // jobs given: the cores are shared out
  CHECK((c.jobs == 2 && c.threads == 4));
  c = choose_concurrency(8, 20, false, 0, 2);  // threads given: jobs fill the cores
  CHECK((c.jobs == 4 && c.threads == 2));
  c = choose_concurrency(2, 20, false, 5, 3);  // both given: as given (oversubscribing is the user's call)
  CHECK((c.jobs == 5 && c.threads == 3));
  CHECK(usable_cores() >= 1);
}
