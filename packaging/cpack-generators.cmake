# Read by cpack once per generator (CPACK_PROJECT_CONFIG_FILE, packaging/CMakeLists.txt): the
# Debian package installs the component `candela` (its libraries are the system's, named in
# Depends); the tarball adds `bundled`, the shared libraries that make it run elsewhere.
if(CPACK_GENERATOR STREQUAL "DEB")
  set(CPACK_INSTALL_CMAKE_PROJECTS "${CPACK_CANDELA_BUILD_DIR};Candela;candela;/")
else()
  set(CPACK_PACKAGE_FILE_NAME ${CPACK_CANDELA_TARBALL_NAME})
  set(CPACK_INSTALL_CMAKE_PROJECTS "${CPACK_CANDELA_BUILD_DIR};Candela;candela;/;${CPACK_CANDELA_BUILD_DIR};Candela;bundled;/")
  # cpack -D CANDELA_GPU_CHECK=ON: the GPU check's tarball (packaging/CMakeLists.txt).
  if(CANDELA_GPU_CHECK)
    set(CPACK_PACKAGE_FILE_NAME ${CPACK_CANDELA_TARBALL_NAME}-gpu-check)
    list(APPEND CPACK_INSTALL_CMAKE_PROJECTS "${CPACK_CANDELA_BUILD_DIR};Candela;gpu-check;/")
  endif()
endif()
