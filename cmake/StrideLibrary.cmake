# stride_library(<name> DIRS <dir>... [EXCLUDE <regex>] DEPS <targets>... EXPOSES <folder>...)
# One static library per architectural folder; sources are every .cpp below the folders, so a
# new file needs no CMake edit.
#
# The dependency direction (docs/architecture.md) is enforced through include paths: a library does
# not see the source tree, only an include root of its own in the build tree holding links to the
# folders it EXPOSES (its own). It sees other folders only through the libraries it links, so a
# wrong-way include (robot/ including simulator/) does not compile.
function(stride_include_root target)
  set(root ${PROJECT_BINARY_DIR}/include_roots/${target})
  file(MAKE_DIRECTORY ${root})
  foreach(folder ${ARGN})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${root}/${folder} SYMBOLIC)
  endforeach()
  set(STRIDE_INCLUDE_ROOT ${root} PARENT_SCOPE)
endfunction()

function(stride_library name)
  cmake_parse_arguments(ARG "" "EXCLUDE" "DIRS;DEPS;EXPOSES" ${ARGN})
  set(srcs)
  foreach(dir ${ARG_DIRS})
    file(GLOB_RECURSE found CONFIGURE_DEPENDS ${dir}/*.cpp)
    list(APPEND srcs ${found})
  endforeach()
  if(ARG_EXCLUDE)
    list(FILTER srcs EXCLUDE REGEX "${ARG_EXCLUDE}")
  endif()
  if(NOT srcs)
    set(srcs ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
  endif()
  add_library(${name} STATIC ${srcs})
  stride_include_root(${name} ${ARG_EXPOSES})
  target_include_directories(${name} PUBLIC ${STRIDE_INCLUDE_ROOT})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
endfunction()
