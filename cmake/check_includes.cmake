cmake_minimum_required(VERSION 3.22)
# Fails when a source of a layer reaches a header the layer may not use, directly or through
# another header. Run at build time by ydscope_forbid_includes() (cmake/forbid_includes.cmake) as
#   cmake -DARGUMENTS=file -P check_includes.cmake
# where the file sets CXX, FLAGS, SOURCES, FORBIDDEN (regular expressions), LAYER and STAMP.
# The compiler's own dependency list (-M) is the truth, so an include hidden behind three other
# headers is found as surely as a direct one. The headers seen go to STAMP.d, so the check runs
# again when any of them changes.
include(${ARGUMENTS})
separate_arguments(flags UNIX_COMMAND "${FLAGS}")
set(offences "")
set(all_deps "")
foreach(source IN LISTS SOURCES)
  execute_process(COMMAND ${CXX} ${flags} -x c++ -M ${source}
                  OUTPUT_VARIABLE deps ERROR_VARIABLE error RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "Could not list the includes of ${source}: ${error}")
  endif()
  string(REPLACE "\\\n" " " deps "${deps}")
  string(REGEX REPLACE "[ \t\r\n]+" ";" deps "${deps}")
  list(FILTER deps EXCLUDE REGEX ":$")
  list(APPEND all_deps ${deps})
  # The first forbidden header in the compiler's order is the one the source's chain led to.
  foreach(dep IN LISTS deps)
    set(hit FALSE)
    foreach(pattern IN LISTS FORBIDDEN)
      if(dep MATCHES "${pattern}")
        set(hit TRUE)
      endif()
    endforeach()
    if(hit)
      list(APPEND offences "${source} reaches ${dep}")
      break()
    endif()
  endforeach()
endforeach()
if(offences)
  list(REMOVE_DUPLICATES offences)
  list(JOIN offences "\n  " text)
  message(FATAL_ERROR "The ${LAYER} layer may not include these headers (the rule is where its "
                      "CMakeLists.txt calls ydscope_forbid_includes):\n  ${text}")
endif()
list(REMOVE_DUPLICATES all_deps)
list(JOIN all_deps " " dep_text)
file(WRITE "${STAMP}.d" "${STAMP}: ${dep_text}\n")
file(WRITE "${STAMP}" "ok\n")
