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
set(patterns "")
foreach(library IN LISTS libraries)
  file(INSTALL ${library} DESTINATION "${prefix}/${CANDELA_BUNDLED_LIBDIR}" FOLLOW_SYMLINK_CHAIN)
  # The folder's last part too: the same name lies elsewhere in other packages (/usr/lib32,
  # chromium's own libvulkan), and usrmerge makes /lib and /usr/lib one.
  get_filename_component(name ${library} NAME)
  get_filename_component(folder ${library} DIRECTORY)
  get_filename_component(folder ${folder} NAME)
  list(APPEND patterns "*/${folder}/${name}")
endforeach()
# Their packages, in one query (each dpkg -S reads the whole database: 0.4 s a call).
execute_process(COMMAND dpkg -S ${patterns} OUTPUT_VARIABLE owners ERROR_QUIET)
string(REGEX MATCHALL "[^\n]+" lines "${owners}")
set(packages "")
foreach(line IN LISTS lines)
  string(REGEX MATCH "^[^:,]+" package "${line}")
  list(APPEND packages ${package})
endforeach()
list(REMOVE_DUPLICATES packages)
foreach(package IN LISTS packages)
  if(EXISTS /usr/share/doc/${package}/copyright)
    file(INSTALL /usr/share/doc/${package}/copyright DESTINATION "${prefix}/${CANDELA_BUNDLED_DOCDIR}/third-party/${package}")
  endif()
endforeach()
