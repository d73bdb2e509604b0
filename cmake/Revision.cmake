# cmake -DSOURCE=<repo> -DOUT=<file.cpp> -P Revision.cmake: writes build_revision() with the
# checkout's `git describe --always --dirty`, touching OUT only when the text changes.
execute_process(COMMAND git -C ${SOURCE} describe --always --dirty
                OUTPUT_VARIABLE rev OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR rev STREQUAL "")
  set(rev "unknown")
endif()
set(text "#include \"console/build_revision.hpp\"\nstd::string_view stride::console::build_revision() { return \"${rev}\"; }\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUT} "${text}")
endif()
