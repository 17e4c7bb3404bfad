# ctest script: every C++ source of the project is formatted as .clang-format says (STYLE.md §13).
# Usage: cmake -DCLANG_FORMAT=... -DSOURCE_DIR=... -P format_check.cmake
file(GLOB_RECURSE _files RELATIVE "${SOURCE_DIR}"
     "${SOURCE_DIR}/core/*.cpp" "${SOURCE_DIR}/core/*.h" "${SOURCE_DIR}/widgets/*.cpp" "${SOURCE_DIR}/widgets/*.h"
     "${SOURCE_DIR}/app/*.cpp" "${SOURCE_DIR}/app/*.h" "${SOURCE_DIR}/tests/*.cpp" "${SOURCE_DIR}/tests/*.h")
set(_bad "")
foreach(_f IN LISTS _files)
  execute_process(COMMAND "${CLANG_FORMAT}" --dry-run -Werror "${_f}" WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT _rc EQUAL 0)
    list(APPEND _bad "${_f}")
  endif()
endforeach()
list(LENGTH _files _n)
if(_bad)
  list(JOIN _bad " " _list)
  message(FATAL_ERROR "clang-format would change: ${_list} (run clang-format -i on them)")
endif()
message(STATUS "${_n} files formatted as .clang-format says")
