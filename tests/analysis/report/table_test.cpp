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

TEST_CASE("A column of numbers stays numeric in CSV, the reason for a missing value beside it", "[analysis]") {
  Table t;
  t.header = {"member", "k_tau_s", "±95%", "note"};
  t.rows = {{"a", "0.14", "0.004", "n/a: text column"},
            {"b", "n/a: the model does not describe the data: R^2 = 0.3 < 0.5", "", "ok"},
            {"c", "1e-05", "", "n/a"},
            {"d", "n/a", "", ""}};
  CHECK(t.to_csv() ==
        "member,k_tau_s,k_tau_s reason,±95%,note\n"
        "a,0.14,,0.004,n/a: text column\n"
        "b,,the model does not describe the data: R^2 = 0.3 < 0.5,,ok\n"
        "c,1e-05,,,n/a\n"
        "d,,not available,,\n");
  // Markdown and LaTeX, read by people, keep the reason in the cell.
  CHECK_THAT(t.to_markdown(), Contains("| b | n/a: the model does not describe the data"));
  // A table without a missing value is written as before: no reason column.
  t.rows = {{"a", "0.14", "0.004", "x"}};
  CHECK(t.to_csv() == "member,k_tau_s,±95%,note\na,0.14,0.004,x\n");
}
