# stride_library(<name> [DIRS <dir>...] [SOURCES <file>...] [EXCLUDE <regex>] DEPS <targets>...
#                EXPOSES <path>... [INTERNAL <path>...])
# One static library per architectural layer; sources are every .cpp below DIRS (plus SOURCES), so
# a new file needs no CMake edit.
#
# The dependency direction (docs/architecture.md) is enforced through include paths: a library does
# not see the source tree, only an include root of its own in the build tree holding links to what
# it EXPOSES (its folders, or single headers, as paths from the checkout). It sees other folders only
# through the libraries it links, so a wrong-way include (robot/ including simulator/, or
# simulator/scene/ including simulator/world/) does not compile. INTERNAL paths are seen by the
# library's own sources but not by its users.
function(stride_include_root target)
  set(root ${PROJECT_BINARY_DIR}/include_roots/${target})
  # Made anew: a link left from an earlier layout would widen what the library sees.
  file(REMOVE_RECURSE ${root})
  file(MAKE_DIRECTORY ${root})
  foreach(path ${ARGN})
    get_filename_component(parent ${root}/${path} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${path} ${root}/${path} SYMBOLIC)
  endforeach()
  set(STRIDE_INCLUDE_ROOT ${root} PARENT_SCOPE)
endfunction()

function(stride_library name)
  cmake_parse_arguments(ARG "" "EXCLUDE" "DIRS;SOURCES;DEPS;EXPOSES;INTERNAL" ${ARGN})
  set(srcs ${ARG_SOURCES})
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
  if(ARG_INTERNAL)
    stride_include_root(${name}_internal ${ARG_INTERNAL})
    target_include_directories(${name} PRIVATE ${STRIDE_INCLUDE_ROOT})
  endif()
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
endfunction()

# stride_headers(<name> EXPOSES <header>... DEPS <targets>...): header-only vocabulary a layer may
# use without seeing the rest of the folder the headers live in.
function(stride_headers name)
  cmake_parse_arguments(ARG "" "" "EXPOSES;DEPS" ${ARGN})
  add_library(${name} INTERFACE)
  stride_include_root(${name} ${ARG_EXPOSES})
  target_include_directories(${name} INTERFACE ${STRIDE_INCLUDE_ROOT})
  target_link_libraries(${name} INTERFACE ${ARG_DEPS})
endfunction()
