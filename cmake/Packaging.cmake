# Debian package (README.md "Install"): `cpack -G DEB` in the build tree, or
# `cmake --build build --target package`, after a full build. It holds the installed tree of
# cmake/Install.cmake under /opt/mpmFoam; users source /opt/mpmFoam/etc/bashrc (as for
# OpenFOAM's packages, nothing goes on the system PATH: decomposePar and reconstructPar share
# OpenFOAM's names). The shared-library dependencies come from dpkg-shlibdeps (dpkg-dev); the
# Python modules of the validate scripts and mpirun are added by hand.
# A package for other machines must be built with -DMPMFOAM_NATIVE=OFF: the default
# -march=native binaries need the build machine's instruction set.
set(MPMFOAM_PACKAGE_MAINTAINER
    "mpmFoam maintainers <maintainers@users.noreply.h-seed-488f95cc.example>"
    CACHE STRING "Maintainer field of the Debian package")

set(CPACK_GENERATOR DEB)
set(CPACK_VERBATIM_VARIABLES ON)
set(CPACK_PACKAGE_NAME mpmfoam)
set(CPACK_PACKAGE_VENDOR "mpmFoam")
set(CPACK_PACKAGE_CONTACT "${MPMFOAM_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /opt/mpmFoam)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # mpmfoam_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${MPMFOAM_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "openmpi-bin, python3, python3-numpy, python3-matplotlib, python3-vtk9")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "paraview")
# CPack indents the lines after the synopsis and writes empty ones as " .".
set(_mpmfoamArch "")
if(MPMFOAM_NATIVE)
  set(_mpmfoamArch "\n\nBuilt with -march=native: it runs only on processors with the instruction\nset of the build machine.")
endif()
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "material point method solver for granular media and rigid bodies
mpmFoam simulates soils and granular media that interact with stiff objects
(a boulder or a steel ball hitting sand, debris flows, a wheel on loose soil,
silos) with the material point method and rigid bodies. Cases use OpenFOAM's
layout; output opens in ParaView.

Installs under /opt/mpmFoam: source /opt/mpmFoam/etc/bashrc, then run
mpmFoam -case <dir>; copy a tutorial from /opt/mpmFoam/tutorials to run it.${_mpmfoamArch}")
# Source archives: use `git archive` (the work tree holds gigabytes of run output).
set(CPACK_SOURCE_GENERATOR TGZ)
set(CPACK_SOURCE_IGNORE_FILES "/\\.git/" "/build[^/]*/" "/tutorials/.*/runs/")
include(CPack)
