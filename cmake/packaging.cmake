# What `cmake --install` puts under the prefix besides the program, the library and
# its headers (src/, apps/stockbridge/) and the Python package (python/): the CMake
# package for find_package(stockbridge), the docs and the examples; and CPack's
# Debian package of all of it. What goes where: docs/install.md.
include(CMakePackageConfigHelpers)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/stockbridge)
install(EXPORT stockbridgeTargets NAMESPACE stockbridge:: DESTINATION ${config_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/stockbridgeConfig.cmake.in
  ${PROJECT_BINARY_DIR}/stockbridgeConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/stockbridgeConfigVersion.cmake
  COMPATIBILITY ${STOCKBRIDGE_COMPATIBILITY})   # set with the version, top-level CMakeLists.txt
install(FILES ${PROJECT_BINARY_DIR}/stockbridgeConfig.cmake ${PROJECT_BINARY_DIR}/stockbridgeConfigVersion.cmake
        DESTINATION ${config_dir})

# What a person reads goes to share/doc/stockbridge; what the program and its users
# run (damper, cable and span files, scripts, the C++ consumer) to share/stockbridge,
# which minimal systems do not strip as they may share/doc.
# README.md beside docs/, as in the sources, so that its links to docs/*.md hold.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR} FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples DESTINATION ${CMAKE_INSTALL_DATADIR}/stockbridge
        PATTERN __pycache__ EXCLUDE)
# The conductor catalogue, compiled into the library as well (src/CMakeLists.txt): the
# files to read, and to start one's own conductor files from.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/conductors DESTINATION ${CMAKE_INSTALL_DATADIR}/stockbridge)

# The Debian package: `cpack -G DEB` in the build tree makes stockbridge_<version>_<arch>.deb
# of everything above, installed to /usr.
# Its name, version and one-line summary are project()'s.
set(CPACK_PACKAGE_VENDOR stockbridge)
set(CPACK_PACKAGE_CONTACT "stockbridge maintainers")
set(CPACK_PACKAGE_DESCRIPTION
    "The stockbridge program, the C++ library with its headers and CMake package, and the Python module.")
# The install runs with CMAKE_INSTALL_PREFIX=/usr (CPACK_INSTALL_PREFIX) into a staging
# DESTDIR, so that the rules that depend on the prefix (the Python package's
# directory) see /usr, whatever prefix the build tree was configured with.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)   # stockbridge_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries the program, the Python module (and a shared libstockbridge)
# link, from dpkg-shlibdeps: libc6, libstdc++6, libfmt9, libnlopt0, libtomlplusplus3,
# libopenmpi3 when built with MPI ...; the Python module's interpreter and numpy by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(STOCKBRIDGE_BUILD_PYTHON)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${STOCKBRIDGE_PYTHON_DEB_DEPENDS}")   # python/CMakeLists.txt
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS python3-matplotlib)   # stockbridge.plot
endif()
set(suggests "libeigen3-dev, libfmt-dev, libtomlplusplus-dev, libnlopt-cxx-dev")   # to build against the library
if(STOCKBRIDGE_MPI)
  string(APPEND suggests ", openmpi-bin")   # mpirun, for `stockbridge design` on several ranks
endif()
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "${suggests}")
set(CPACK_GENERATOR DEB)
include(CPack)
