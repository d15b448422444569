# Install-time script (cmake/Install.cmake): copies the git-tracked files of
# MPMFOAM_TRACKED_DIRS (folders of MPMFOAM_SOURCE_DIR), less those matching
# MPMFOAM_TRACKED_EXCLUDE, into CMAKE_INSTALL_PREFIX, keeping their permissions, so that what
# runs leave in the source tree (time directories, runs/, logs, pictures, generated STL files
# and level sets: the .gitignore files) stays behind, even while CTest runs the tutorials there.
# Outside a git checkout (an unpacked source archive) every file is copied except the usual
# run output, matched by name below, and the programs of bin/ (MPMFOAM_PROGRAM_FILES, installed
# by install(TARGETS)).
cmake_policy(VERSION 3.20)
set(_src "${MPMFOAM_SOURCE_DIR}")
set(_files)
set(_fromGit FALSE)
execute_process(COMMAND git rev-parse --show-toplevel WORKING_DIRECTORY "${_src}"
                OUTPUT_VARIABLE _top RESULT_VARIABLE _rc OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(_rc EQUAL 0)
  file(REAL_PATH "${_top}" _top)
  file(REAL_PATH "${_src}" _srcReal)
  if(_top STREQUAL _srcReal)
    execute_process(COMMAND git -c core.quotePath=off ls-files -- ${MPMFOAM_TRACKED_DIRS}
                    WORKING_DIRECTORY "${_src}" OUTPUT_VARIABLE _list RESULT_VARIABLE _rc
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(_rc EQUAL 0)
      string(REPLACE "\n" ";" _files "${_list}")
      set(_fromGit TRUE)
    endif()
  endif()
endif()
if(NOT _fromGit)
  message(STATUS "Not a git checkout: installing ${MPMFOAM_TRACKED_DIRS} without run output")
  foreach(_dir IN LISTS MPMFOAM_TRACKED_DIRS)
    file(GLOB_RECURSE _all LIST_DIRECTORIES false RELATIVE "${_src}" "${_src}/${_dir}/*")
    list(APPEND _files ${_all})
  endforeach()
  # time directories (names that start with a digit), runs/, processor<N>/, postProcessing/,
  # writes in progress, generated STL files and level sets; logs, .pvd, Python caches, the
  # tutorials' pictures and results. (A few inputs that some tutorials write themselves may
  # remain: ./Allclean in the tutorials first for a tree as clean as git's.)
  list(FILTER _files EXCLUDE REGEX
       "(^(tutorials|cases)/.*/([0-9][^/]*|runs|processor[0-9]+|postProcessing|\\.[^/]*\\.writing)/)|^tutorials/.*/constant/(geometry|levelSets)/|/__pycache__/|/log\\.[^/]*$|\\.pvd$|\\.pyc$|^tutorials/.*(\\.png|/results\\.md|/accuracyCost\\.md)$")
  foreach(_program IN LISTS MPMFOAM_PROGRAM_FILES)
    list(REMOVE_ITEM _files "bin/${_program}")
  endforeach()
  list(FILTER _files EXCLUDE REGEX "^bin/.*\\.so$")
endif()
if(MPMFOAM_TRACKED_EXCLUDE)
  list(FILTER _files EXCLUDE REGEX "${MPMFOAM_TRACKED_EXCLUDE}")
endif()

# One file(INSTALL) per folder.
set(_dirs)
foreach(_file IN LISTS _files)
  if(_file STREQUAL "" OR NOT EXISTS "${_src}/${_file}" OR IS_DIRECTORY "${_src}/${_file}")
    continue() # deleted in the work tree, or a submodule
  endif()
  get_filename_component(_dir "${_file}" DIRECTORY)
  if(NOT DEFINED "_in_${_dir}")
    list(APPEND _dirs "${_dir}")
  endif()
  list(APPEND "_in_${_dir}" "${_src}/${_file}")
endforeach()
foreach(_dir IN LISTS _dirs)
  file(INSTALL ${_in_${_dir}} DESTINATION "${CMAKE_INSTALL_PREFIX}/${_dir}"
       USE_SOURCE_PERMISSIONS)
endforeach()
