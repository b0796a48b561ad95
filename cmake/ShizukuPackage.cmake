# The Debian package: `cpack -G DEB` in the build folder writes
# shizuku_<version>_<arch>.deb with the install rules at prefix /usr
# (programs in /usr/bin, tutorials and etc/bashrc in /usr/share/shizuku,
# docs in /usr/share/doc/shizuku).
# Depends: the Debian 12 runtime packages of the libraries the programs link
# (each checked with dpkg -S against the library files) and of the python
# utilities (shizukuPlot: matplotlib, numpy, vtk9; shizukuCompare: numpy).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME shizuku)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Shizuku maintainers")
set(CPACK_PACKAGE_CONTACT "Shizuku maintainers <maintainers@users.noreply.h-seed-44fdf410.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "incompressible SPH (ISPH) solver for free-surface flow")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
"Shizuku solves free-surface flow with projection ISPH, second-order SPH(2)
 derivative operators and density-corrected particle shifting, run the way
 OpenFOAM users run a case: shizuku -case DIR on a case directory of
 dictionaries, results in time directories that ParaView opens.
 Includes shizukuParticles, shizukuPostProcess, the python utilities
 shizukuPlot and shizukuCompare, the tutorials and the documentation.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libc6, libgcc-s1, libstdc++6, libgomp1, libboost-program-options1.74.0, libmuparser2v5, libvtk9.1, \
libumfpack5, libklu1, libamd2, libcolamd2, libbtf1, libcholmod3, libsuitesparseconfig5, \
python3, python3-numpy, python3-matplotlib, python3-vtk9")
# A build with MPI (the default) or hypre also needs MPI's, Zoltan's, PETSc's and hypre's
# libraries: dpkg-shlibdeps adds them, read from the programs themselves.
if(SHIZUKU_HYPRE_LINKED OR SHIZUKU_MPI_LINKED)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
endif()
include(CPack)
