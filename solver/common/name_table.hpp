#pragma once
// The one name table of each choice (a scene string <-> its enum), after Ceres's types.cc: a
// choice's names are written once, beside its enum, and parsed once (solver/scene/scene.cpp);
// past the parser the code switches on the enum. A choice's header declares its table as
//   inline constexpr NameTable<E, n> e_names{{{E::a, "a"}, ...}};
//   constexpr const auto& name_table(E) { return e_names; }   // found by argument lookup
// and choice_name / choice_from_name / choice_names_list work for it.
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace capsule {

template <class E>
struct Named {
  E value;
  std::string_view name;
};

template <class E, std::size_t N>
using NameTable = std::array<Named<E>, N>;

// The name of a value; a value missing from its table is a bug, not an input error.
template <class E>
std::string choice_name(E value) {
  for (const auto& entry : name_table(value))
    if (entry.value == value) return std::string(entry.name);
  throw std::logic_error("a choice value without a name in its table");
}

// The value of a name; none for a name not in the table.
template <class E>
std::optional<E> choice_from_name(std::string_view name) {
  for (const auto& entry : name_table(E{}))
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

// The value of a name; std::invalid_argument naming `what` and the allowed names otherwise.
template <class E>
E choice_from_name_or_throw(std::string_view name, std::string_view what);

// Every name of the table, in its order (for a command line's list of allowed values).
template <class E>
std::vector<std::string> choice_names() {
  std::vector<std::string> names;
  for (const auto& entry : name_table(E{})) names.emplace_back(entry.name);
  return names;
}

// "a | b | c": every name of the table, in its order.
template <class E>
std::string choice_names_list(std::string_view separator = " | ") {
  std::string list;
  for (const auto& entry : name_table(E{})) list += (list.empty() ? "" : std::string(separator)) + std::string(entry.name);
  return list;
}

template <class E>
E choice_from_name_or_throw(std::string_view name, std::string_view what) {
  if (const auto value = choice_from_name<E>(name)) return *value;
  throw std::invalid_argument("unknown " + std::string(what) + " \"" + std::string(name) +
                              "\" (allowed: " + choice_names_list<E>(", ") + ")");
}

}  // namespace capsule
