// Markdown, CSV and LaTeX writers: quoting and escaping.
#include <catch2/catch.hpp>

#include "analysis/report/table.hpp"

using namespace capsule::analysis;
using Catch::Matchers::Contains;

TEST_CASE("Tables quote and escape their cells", "[analysis]") {
  Table t;
  t.title = "k_tau with 95 %";
  t.header = {"case", "value"};
  t.rows = {{"a,b", "x \"q\""}, {"p|q", "0.1 ± 0.01"}};
  CHECK(t.to_csv() == "case,value\n\"a,b\",\"x \"\"q\"\"\"\np|q,0.1 ± 0.01\n");
  CHECK_THAT(t.to_markdown(), Contains("| p\\|q | 0.1 ± 0.01 |") && Contains("|---|---|"));
  const std::string tex = t.to_latex();
  CHECK_THAT(tex, Contains("\\caption{k\\_tau with 95 \\%}") && Contains("0.1 $\\pm$ 0.01 \\\\"));
  CHECK(format_number(0.123456789) == "0.123457");
  CHECK(format_number(std::nan("")).empty());
}
