# Computes the code version recorded in member files and run records, at every build (not
# once at configure time): `git describe` of HEAD, and when the sources that go into the
# binaries differ from it (tracked changes or untracked files under common/ solver/ study/ analysis/
# cmake/ and CMakeLists.txt; results/, docs/ and tests/ never count), "-dirty-" and the first
# 12 hex digits of a SHA-256 over those differences, so two different dirty builds never share
# a version. Writes OUT only when the text changes, so an unchanged tree rebuilds nothing.
# Usage: cmake -DSOURCE_DIR=... -DOUT=... -DTEMPLATE=... -P code_version.cmake
set(paths common solver study analysis cmake CMakeLists.txt)
execute_process(COMMAND git describe --always --abbrev=12
                WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE describe
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE git_failed)
if(git_failed OR NOT describe)
  set(CAPSULE_GIT_VERSION "unknown")
else()
  execute_process(COMMAND git diff HEAD --binary -- ${paths}
                  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE diff ERROR_QUIET)
  execute_process(COMMAND git ls-files --others --exclude-standard -- ${paths}
                  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE untracked
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  set(difference "${diff}")
  if(untracked)
    string(REPLACE "\n" ";" untracked_files "${untracked}")
    foreach(f IN LISTS untracked_files)
      file(SHA256 ${SOURCE_DIR}/${f} h)
      string(APPEND difference "untracked ${f} ${h}\n")
    endforeach()
  endif()
  if(difference STREQUAL "")
    set(CAPSULE_GIT_VERSION "${describe}")
  else()
    string(SHA256 h "${difference}")
    string(SUBSTRING "${h}" 0 12 h)
    set(CAPSULE_GIT_VERSION "${describe}-dirty-${h}")
  endif()
endif()
set(CMAKE_SOURCE_DIR ${SOURCE_DIR})
configure_file(${TEMPLATE} ${OUT}.new @ONLY)
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.new ${OUT})
file(REMOVE ${OUT}.new)
