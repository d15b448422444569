# Installation (README.md "Install"): `cmake --install build --prefix <dir>` writes one
# self-contained tree laid out like the source tree, so that etc/bashrc, bin/tools/RunFunctions
# and the tutorials' scripts work there unchanged (MPMFOAM_DIR = the prefix):
#   bin/                 mpmFoam and every utility (each program the build puts in bin/), and
#                        the scripts tracked in bin/
#   bin/tools/           RunFunctions, CleanFunctions and the Python helpers of the validate
#                        scripts (not the developer tools checkFormat, installDependencies)
#   etc/bashrc           the shell environment
#   tutorials/, cases/, docs/, README.md
#                        the git-tracked files only: no run output (cmake/InstallTracked.cmake)
# The default prefix is /opt/mpmFoam (the Debian package's too, cmake/Packaging.cmake); /usr
# and /usr/local are refused, as the tree would spill etc/ and tutorials/ into them.

# Every executable the build puts in bin/ (the tests go to build/tests/): the directories
# below `dir`, recursively.
function(mpmfoam_bin_programs dir out)
  set(found)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(outDir ${target} RUNTIME_OUTPUT_DIRECTORY)
    if(type STREQUAL "EXECUTABLE" AND outDir STREQUAL "${CMAKE_SOURCE_DIR}/bin")
      list(APPEND found ${target})
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    mpmfoam_bin_programs(${subdir} subFound)
    list(APPEND found ${subFound})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()
mpmfoam_bin_programs(${CMAKE_SOURCE_DIR} MPMFOAM_PROGRAMS)

# `cmake --build build --target programs`: what gets installed, without the unit tests.
add_custom_target(programs)
add_dependencies(programs ${MPMFOAM_PROGRAMS})

install(CODE [[
  get_filename_component(_mpmfoamPrefix "${CMAKE_INSTALL_PREFIX}" ABSOLUTE)
  if(_mpmfoamPrefix MATCHES "^/(usr(/local)?)?/*$")
    message(FATAL_ERROR "mpmFoam installs as one tree (bin/, bin/tools/, etc/bashrc, "
            "tutorials/, docs/) and will not spread it over ${_mpmfoamPrefix}: give it a "
            "folder of its own, e.g. cmake --install build --prefix /opt/mpmFoam")
  endif()
]])
install(TARGETS ${MPMFOAM_PROGRAMS} RUNTIME DESTINATION bin)
install(FILES etc/bashrc DESTINATION etc)
install(FILES README.md DESTINATION .)
# The git-tracked files of bin/ (scripts such as bin/tools/RunFunctions), tutorials/, cases/ and
# docs/, less the developer tools.
set(MPMFOAM_PROGRAM_FILES)
foreach(program IN LISTS MPMFOAM_PROGRAMS)
  list(APPEND MPMFOAM_PROGRAM_FILES "$<TARGET_FILE_NAME:${program}>")
endforeach()
install(CODE "set(MPMFOAM_SOURCE_DIR \"${CMAKE_SOURCE_DIR}\")
set(MPMFOAM_TRACKED_DIRS bin tutorials cases docs)
set(MPMFOAM_TRACKED_EXCLUDE \"^bin/tools/(checkFormat|installDependencies)$\")
set(MPMFOAM_PROGRAM_FILES \"${MPMFOAM_PROGRAM_FILES}\")")
install(SCRIPT cmake/InstallTracked.cmake)
