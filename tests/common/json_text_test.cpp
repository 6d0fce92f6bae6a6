// Scene and campaign text: comments accepted, duplicate keys and overflowing numbers
// refused with the file name (and, for a duplicate, the key's path).
#include <catch2/catch.hpp>

#include "common/json_text.hpp"

using capsule::JsonTextError;
using capsule::parse_json_text;

TEST_CASE("JSON text with // and /* */ comments parses", "[scene]") {
  const auto j = parse_json_text("{\n  \"a\": 1, // one\n  /* two */ \"b\": [2, /* in a list */ 3]\n}\n", "c.json");
  CHECK(j.at("a") == 1);
  CHECK(j.at("b").size() == 2);
}

TEST_CASE("a key given twice is refused, naming the file and the key's path", "[scene]") {
  CHECK_THROWS_WITH(parse_json_text(R"({"Ca": 0.1, "Ca": 0.2})", "s.json"),
                    "s.json: Ca: key given twice (allowed: each key once per object)");
  CHECK_THROWS_WITH(parse_json_text(R"({"protocol": {"shear": {"kt": 1, "until": "time", "kt": 2}}})", "s.json"),
                    Catch::StartsWith("s.json: protocol.shear.kt: key given twice"));
  CHECK_THROWS_WITH(parse_json_text(R"({"cases": [{"name": "a"}, {"name": "b", "set": {}, "set": {}}]})", "c.json"),
                    Catch::StartsWith("c.json: cases[1].set: key given twice"));
  // The same key in different objects is fine.
  CHECK_NOTHROW(parse_json_text(R"({"a": {"k": 1}, "b": {"k": 2}, "l": [{"k": 1}, {"k": 2}]})", "ok.json"));
}

TEST_CASE("syntax errors and number overflow name the file and where the parser was", "[scene]") {
  CHECK_THROWS_WITH(parse_json_text(R"({"Ca": 1e400})", "big.json"),
                    Catch::StartsWith("big.json: Ca: not valid JSON: ") && Catch::Contains("1e400") &&
                        Catch::Contains("(allowed: numbers of magnitude below 1.8e308)"));
  CHECK_THROWS_WITH(parse_json_text(R"({"sweep": {"grid": {"Ca": [0.1, 1e999]}}})", "c.json"),
                    Catch::StartsWith("c.json: sweep.grid.Ca[1]: not valid JSON: "));
  CHECK_THROWS_WITH(parse_json_text(R"({"Ca": NaN})", "nan.json"),
                    Catch::StartsWith("nan.json: Ca: not valid JSON") && Catch::Contains("NaN and Infinity are not JSON"));
  CHECK_THROWS_WITH(parse_json_text(R"({"V": -Infinity})", "inf.json"), Catch::StartsWith("inf.json: V: not valid JSON"));
  CHECK_THROWS_WITH(parse_json_text(R"({"Ca": )", "cut.json"), Catch::StartsWith("cut.json: Ca: not valid JSON"));
  CHECK_THROWS_WITH(parse_json_text(R"([1, 2)", "a.json"), Catch::StartsWith("a.json: [2]: not valid JSON"));
  CHECK_THROWS_WITH(parse_json_text("", "empty.json"), Catch::StartsWith("empty.json: (top level): not valid JSON"));
  CHECK_THROWS_AS(parse_json_text("[1,]", "x.json"), JsonTextError);
}
