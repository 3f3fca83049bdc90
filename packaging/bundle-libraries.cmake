# Installs the shared libraries CANDELA_BUNDLED_BINARIES and CANDELA_BUNDLED_LIBRARIES need, but glibc's (every Linux has its own,
# matched to its ld.so), into CANDELA_BUNDLED_LIBDIR, each under the names its link chain has
# (libglfw.so.3 -> libglfw.so.3.3); and, on Debian, the copyright file of each package they come
# from into CANDELA_BUNDLED_DOCDIR/third-party/PACKAGE/. The install script of the component
# `bundled` (packaging/CMakeLists.txt); the Vulkan loader is bundled, a driver is the machine's.
set(prefix "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}")
file(GET_RUNTIME_DEPENDENCIES
  EXECUTABLES ${CANDELA_BUNDLED_BINARIES}
  LIBRARIES ${CANDELA_BUNDLED_LIBRARIES}
  RESOLVED_DEPENDENCIES_VAR libraries
  UNRESOLVED_DEPENDENCIES_VAR unresolved
  PRE_EXCLUDE_REGEXES "^(libc|libm|libdl|libpthread|librt|libutil|libresolv|libmvec|ld-linux-x86-64)\\.so")
if(unresolved)
  message(FATAL_ERROR "the binaries need libraries this machine does not have: ${unresolved}")
endif()
list(REMOVE_DUPLICATES libraries)
foreach(library IN LISTS libraries)
  file(INSTALL ${library} DESTINATION "${prefix}/${CANDELA_BUNDLED_LIBDIR}" FOLLOW_SYMLINK_CHAIN)
  get_filename_component(name ${library} NAME)
  execute_process(COMMAND dpkg -S "*/${name}" OUTPUT_VARIABLE owners ERROR_QUIET RESULT_VARIABLE status)
  if(status EQUAL 0)
    string(REGEX MATCH "^[^:,]+" package "${owners}")
    if(EXISTS /usr/share/doc/${package}/copyright)
      file(INSTALL /usr/share/doc/${package}/copyright DESTINATION "${prefix}/${CANDELA_BUNDLED_DOCDIR}/third-party/${package}")
    endif()
  endif()
endforeach()
