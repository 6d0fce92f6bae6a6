# Rooms: each folder of the house (or a few together) is one library with declared dependencies,
# and CMake refuses a back-edge at configure time.
#
#   capsule_floor_plan(room...)
#     Every room of the house, from the bottom floor up. A room may depend only on rooms below it.
#   capsule_room(room [TARGET target] [FOLDERS dir...] [DEPENDS room...] [LIBS lib...]
#                [PRECOMPILE header...])
#     The library `target` (default capsule_<room> with / as _) made of every .cpp in the
#     folders (default: the folder named like the room), linking the targets of the rooms it
#     DEPENDS on and the outside libraries LIBS. PRECOMPILE: outside headers most of the room's
#     sources include (<nlohmann/json.hpp>, <Eigen/Dense>, <CLI/CLI.hpp>), parsed once into a
#     precompiled header instead of once per source (capsule_precompile).
#     Refused when a dependency is not in the floor
#     plan, is above the room ("room X may not depend on Y: Y is above X"), or is not defined
#     yet. At the end of the configure step every room's .cpp and .hpp files are read: an
#     `#include "dir/file.hpp"` of a header of another room that is not among the room's
#     dependencies (direct or through others) is refused, naming the file, the line and both rooms.
include_guard(GLOBAL)

# capsule_precompile(target header...): the headers as the target's precompiled header, unless
# CAPSULE_PRECOMPILED_HEADERS is off. Only outside libraries' headers, which the target's sources
# include anyway (a header of the house would hide a missing include). The build of the tools
# on two cores: docs/findings/performance.md "Building the tools".
function(capsule_precompile target)
  set(headers ${ARGN})
  if(CAPSULE_PRECOMPILED_HEADERS AND headers)
    list(TRANSFORM headers REPLACE "^([^<].*)$" "<\\1>")
    target_precompile_headers(${target} PRIVATE ${headers})
  endif()
endfunction()

function(capsule_floor_plan)
  set_property(GLOBAL PROPERTY CAPSULE_FLOOR_PLAN ${ARGN})
endfunction()

function(_capsule_room_key room out)
  string(MAKE_C_IDENTIFIER "${room}" key)
  set(${out} "CAPSULE_ROOM_${key}" PARENT_SCOPE)
endfunction()

function(capsule_room room)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TARGET" "FOLDERS;DEPENDS;LIBS;PRECOMPILE")
  get_property(plan GLOBAL PROPERTY CAPSULE_FLOOR_PLAN)
  get_property(defined GLOBAL PROPERTY CAPSULE_ROOMS_DEFINED)
  list(FIND plan "${room}" floor)
  if(floor EQUAL -1)
    message(FATAL_ERROR "room ${room} is not in the floor plan (capsule_floor_plan)")
  endif()
  if("${room}" IN_LIST defined)
    message(FATAL_ERROR "room ${room} is defined twice")
  endif()

  # The dependencies: each one below this room and already defined; the closure is what the
  # room's sources may include.
  set(closure "")
  set(dependency_targets "")
  foreach(dependency IN LISTS arg_DEPENDS)
    list(FIND plan "${dependency}" dependency_floor)
    if(dependency_floor EQUAL -1)
      message(FATAL_ERROR "room ${room} may not depend on ${dependency}: ${dependency} is not in the floor plan")
    elseif(dependency_floor GREATER_EQUAL floor)
      message(FATAL_ERROR "room ${room} may not depend on ${dependency}: ${dependency} is above ${room}")
    elseif(NOT "${dependency}" IN_LIST defined)
      message(FATAL_ERROR "room ${room} depends on ${dependency}, which is not defined yet "
                          "(define the rooms in the order of the floor plan)")
    endif()
    _capsule_room_key("${dependency}" dependency_key)
    get_property(dependency_closure GLOBAL PROPERTY ${dependency_key}_CLOSURE)
    get_property(dependency_target GLOBAL PROPERTY ${dependency_key}_TARGET)
    list(APPEND closure "${dependency}" ${dependency_closure})
    list(APPEND dependency_targets ${dependency_target})
  endforeach()
  list(REMOVE_DUPLICATES closure)

  if(NOT arg_TARGET)
    string(REPLACE "/" "_" arg_TARGET "capsule_${room}")
  endif()
  if(NOT arg_FOLDERS)
    set(arg_FOLDERS "${room}")
  endif()
  set(folders "")
  set(sources "")
  foreach(folder IN LISTS arg_FOLDERS)
    get_filename_component(folder "${folder}" ABSOLUTE BASE_DIR "${CMAKE_SOURCE_DIR}")
    file(RELATIVE_PATH folder "${CMAKE_SOURCE_DIR}" "${folder}")
    list(APPEND folders "${folder}")
    set_property(GLOBAL APPEND PROPERTY CAPSULE_ROOM_FOLDERS "${folder}")
    _capsule_room_key("${folder}" folder_key)
    set_property(GLOBAL PROPERTY ${folder_key}_FOLDER_ROOM "${room}")
    file(GLOB folder_sources CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/${folder}/*.cpp")
    list(APPEND sources ${folder_sources})
  endforeach()

  if(sources)
    add_library(${arg_TARGET} STATIC ${sources})
    if(TARGET capsule_code_version)
      add_dependencies(${arg_TARGET} capsule_code_version)
    endif()
    target_include_directories(${arg_TARGET} PUBLIC ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/generated)
    target_link_libraries(${arg_TARGET} PUBLIC ${dependency_targets} ${arg_LIBS})
    capsule_precompile(${arg_TARGET} ${arg_PRECOMPILE})
  else()  # header-only while it has no .cpp
    add_library(${arg_TARGET} INTERFACE)
    target_include_directories(${arg_TARGET} INTERFACE ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/generated)
    target_link_libraries(${arg_TARGET} INTERFACE ${dependency_targets} ${arg_LIBS})
  endif()

  _capsule_room_key("${room}" key)
  set_property(GLOBAL PROPERTY ${key}_CLOSURE ${closure})
  set_property(GLOBAL PROPERTY ${key}_TARGET ${arg_TARGET})
  set_property(GLOBAL PROPERTY ${key}_FOLDERS ${folders})
  set_property(GLOBAL APPEND PROPERTY CAPSULE_ROOMS_DEFINED "${room}")
  # The includes are read once every room is known (a header of a room above this one too).
  get_property(scheduled GLOBAL PROPERTY CAPSULE_ROOM_INCLUDES_SCHEDULED)
  if(NOT scheduled)
    set_property(GLOBAL PROPERTY CAPSULE_ROOM_INCLUDES_SCHEDULED TRUE)
    cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL capsule_check_room_includes)
  endif()
endfunction()

# Reads the includes of every room's .cpp and .hpp files; one FATAL_ERROR lists every include of
# a header of a room outside the including room's dependencies, or of a folder that is no room
# under a floor (solver/app/ holds a binary, not a room).
function(capsule_check_room_includes)
  get_property(plan GLOBAL PROPERTY CAPSULE_FLOOR_PLAN)
  get_property(rooms GLOBAL PROPERTY CAPSULE_ROOMS_DEFINED)
  get_property(room_folders GLOBAL PROPERTY CAPSULE_ROOM_FOLDERS)
  set(floors "")  # the first folder of every room's folder: common, solver, analysis, study
  foreach(folder IN LISTS room_folders)
    string(REGEX REPLACE "/.*" "" top "${folder}")
    list(APPEND floors "${top}")
  endforeach()
  list(REMOVE_DUPLICATES floors)

  set(refusals "")
  foreach(room IN LISTS rooms)
    _capsule_room_key("${room}" key)
    get_property(closure GLOBAL PROPERTY ${key}_CLOSURE)
    get_property(folders GLOBAL PROPERTY ${key}_FOLDERS)
    list(FIND plan "${room}" floor)
    foreach(folder IN LISTS folders)
      file(GLOB files "${CMAKE_SOURCE_DIR}/${folder}/*.cpp" "${CMAKE_SOURCE_DIR}/${folder}/*.hpp")
      foreach(file IN LISTS files)
        file(STRINGS "${file}" include_lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]+/[^\"]+\"")
        foreach(line IN LISTS include_lines)
          if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\"")
            continue()  # the rest of a line that held a ';'
          endif()
          set(header "${CMAKE_MATCH_1}")
          get_filename_component(header_folder "${header}" DIRECTORY)
          string(REGEX REPLACE "/.*" "" header_top "${header}")
          if(NOT header_top IN_LIST floors)
            continue()  # not the house's (a generated header, another library's)
          endif()
          _capsule_room_key("${header_folder}" folder_key)
          get_property(other GLOBAL PROPERTY ${folder_key}_FOLDER_ROOM)
          if("${other}" STREQUAL "${room}" OR "${other}" IN_LIST closure)
            continue()
          endif()
          # Where: the line number of the first line holding this include.
          file(READ "${file}" text)
          string(FIND "${text}" "${line}" at)
          string(SUBSTRING "${text}" 0 ${at} before)
          string(REGEX MATCHALL "\n" newlines "${before}")
          list(LENGTH newlines number)
          math(EXPR number "${number} + 1")
          file(RELATIVE_PATH where "${CMAKE_SOURCE_DIR}" "${file}")
          if("${other}" STREQUAL "")
            set(why "${header_folder} is no room (only a binary may include it)")
          else()
            list(FIND plan "${other}" other_floor)
            if(other_floor GREATER floor)
              set(why "room ${room} may not include room ${other}: ${other} is above ${room}")
            else()
              set(why "room ${room} includes room ${other}, which it does not depend on (add it to its DEPENDS)")
            endif()
          endif()
          string(APPEND refusals "  ${where}:${number}: #include \"${header}\": ${why}\n")
        endforeach()
      endforeach()
    endforeach()
  endforeach()
  if(refusals)
    message(FATAL_ERROR "includes across rooms that the rooms' dependencies do not allow:\n${refusals}")
  endif()
endfunction()
