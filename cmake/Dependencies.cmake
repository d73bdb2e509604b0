# Every package here is a Debian package installed by .ci/setup; see third_party_notes.md.
# What the robot side (robot/, behaviours/, stride-robot) needs:
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(tinyxml2 REQUIRED)
find_package(Threads REQUIRED)
pkg_check_modules(URDFDOM REQUIRED IMPORTED_TARGET urdfdom)
find_package(msgpack REQUIRED CONFIG)  # Debian's msgpack-cxx: target msgpackc-cxx
find_package(ZLIB REQUIRED)  # log frame checksums
find_package(OpenSSL REQUIRED)  # libcrypto: HMAC-SHA256 and SHA-256 for the debug server
if(STRIDE_ROBOT_ONLY)
  return()
endif()
# The simulator, console, tests and benchmarks:
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
# Optional (STRIDE_MP4): MP4 movies (Debian libavcodec-dev, libavformat-dev, libswscale-dev,
# libavutil-dev); without them movies are written as animated PNG only.
if(STRIDE_MP4)
  pkg_check_modules(FFMPEG IMPORTED_TARGET libavcodec libavformat libswscale libavutil)
  if(NOT FFMPEG_FOUND)
    message(STATUS "FFmpeg's libraries not found: building without .mp4 movies (.apng only)")
  endif()
else()
  set(FFMPEG_FOUND FALSE)
endif()
find_package(PNG REQUIRED)
find_library(READLINE_LIBRARY readline REQUIRED)
# pagmo (Debian libpagmo-dev 2.18): the optimiser of `stride tune` (console/tune/optimiser.cpp).
find_package(Pagmo REQUIRED CONFIG)
if(STRIDE_TESTS)
  find_package(GTest REQUIRED)
endif()
if(STRIDE_BENCH)
  find_package(benchmark REQUIRED)
endif()
# Optional: OpenMPI for sweeps across machines (Debian libopenmpi-dev, openmpi-bin).
if(STRIDE_MPI)
  find_package(MPI COMPONENTS C)
endif()
# Header and library found directly: Debian's mujocoConfig.cmake (2.2.2) names a qhull include
# directory that the C API does not need.
if(STRIDE_MUJOCO)
  find_path(MUJOCO_INCLUDE_DIR mujoco/mujoco.h)
  find_library(MUJOCO_LIBRARY mujoco)
  if(MUJOCO_INCLUDE_DIR AND MUJOCO_LIBRARY)
    add_library(stride_mujoco INTERFACE)
    target_include_directories(stride_mujoco SYSTEM INTERFACE ${MUJOCO_INCLUDE_DIR})
    target_link_libraries(stride_mujoco INTERFACE ${MUJOCO_LIBRARY})
  else()
    message(STATUS "MuJoCo not found (libmujoco-dev): building without engine=\"mujoco\"")
    set(STRIDE_MUJOCO OFF)
  endif()
endif()
