#pragma once
// A command-line option whose value is a choice (solver/common/name_table.hpp): the names of
// its table are the allowed values, and the option sets the enum.
#include <CLI/CLI.hpp>
#include <string>

#include "solver/common/name_table.hpp"

namespace capsule::cli {

template <class E>
CLI::Option* add_choice_option(CLI::App& app, const std::string& name, E& value, const std::string& description) {
  return app
      .add_option_function<std::string>(
          name, [&value](const std::string& text) { value = *choice_from_name<E>(text); }, description)
      ->check(CLI::IsMember(choice_names<E>()))
      ->default_str(choice_name(value));
}

}  // namespace capsule::cli
