# ydscope_forbid_includes(TARGET FOLDER REASON [INCLUDES dir...] [DEPENDS file...] PATTERNS regex...):
# the build of TARGET fails when any .cpp or .h in FOLDER reaches a header whose path matches one
# of the regular expressions, with a message naming the file, the header and the reason. A layer's
# rules are then facts the build checks, not conventions a reviewer has to remember. INCLUDES are the
# folders of foreign or generated headers the layer uses (ImGui's, say), so the compiler can follow
# them; DEPENDS names generated headers that must exist first.
function(ydscope_forbid_includes target folder reason)
  cmake_parse_arguments(PARSE_ARGV 3 arg "" "" "INCLUDES;DEPENDS;PATTERNS")
  file(GLOB files CONFIGURE_DEPENDS ${folder}/*.cpp ${folder}/*.h)
  get_filename_component(name ${folder} NAME)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}_${name}_includes.stamp)
  set(flags "-std=c++${CMAKE_CXX_STANDARD} -I${PROJECT_SOURCE_DIR} -I${PROJECT_BINARY_DIR}/generated")
  foreach(dir IN LISTS arg_INCLUDES)
    string(APPEND flags " -I${dir}")
  endforeach()
  # The lists go in a file: a list on a custom command's line would be split into arguments.
  set(arguments ${CMAKE_CURRENT_BINARY_DIR}/${target}_${name}_includes_arguments.cmake)
  set(patterns ${arg_PATTERNS})
  file(CONFIGURE OUTPUT ${arguments} CONTENT [[
set(CXX "@CMAKE_CXX_COMPILER@")
set(FLAGS "@flags@")
set(SOURCES "@files@")
set(FORBIDDEN "@patterns@")
set(LAYER "@name@ (@reason@)")
set(STAMP "@stamp@")
]] @ONLY)
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DARGUMENTS=${arguments} -P ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
    DEPENDS ${files} ${arguments} ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake ${arg_DEPENDS}
    DEPFILE ${stamp}.d
    COMMENT "Checking that ${folder} stays ${reason}" VERBATIM)
  add_custom_target(${target}_${name}_includes DEPENDS ${stamp})
  add_dependencies(${target} ${target}_${name}_includes)
endfunction()
