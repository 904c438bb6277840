# Included by LAMMPS' CMakeLists.txt right after its project() line
# (CMAKE_PROJECT_lammps_INCLUDE, set by plugin/lammps/build.sh): builds
# c_core (DC_ROOT/c_core) in the LAMMPS build tree, with the flags of the
# project's own build, and links it into the LAMMPS library, so that the
# sub-models in src/GRANULAR (copied from plugin/lammps/GRANULAR) reach the
# laws and a change in c_core relinks lmp.
enable_language(C)
set(CMAKE_C_STANDARD 11)
set(CMAKE_C_STANDARD_REQUIRED ON)
set(CMAKE_C_FLAGS_RELEASE "-O2")
add_subdirectory(${DC_ROOT}/c_core ${CMAKE_BINARY_DIR}/c_core EXCLUDE_FROM_ALL)
cmake_language(DEFER CALL target_link_libraries lammps PUBLIC demcontact)
