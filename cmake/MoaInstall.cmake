# Installation: the header, the shared library with its SONAME links, moa.pc, a CMake package
# giving moa::moa, and the moa tool when it is built. Included at the end of the top-level
# CMakeLists.txt, once every target exists.
include(CMakePackageConfigHelpers)

set(MOA_CMAKE_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/moa)

install(TARGETS moa EXPORT moaTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

install(FILES
    ${PROJECT_SOURCE_DIR}/include/moa/moa.h
    ${PROJECT_BINARY_DIR}/include/moa/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/moa)

if(TARGET moa_cli)
  # Let an installed tool find libmoa in its own prefix unless its author decided otherwise.
  get_target_property(_moa_cli_rpath moa_cli INSTALL_RPATH)
  if(NOT _moa_cli_rpath AND NOT APPLE AND NOT WIN32)
    file(RELATIVE_PATH _moa_bin_to_lib ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_LIBDIR})
    set_target_properties(moa_cli PROPERTIES INSTALL_RPATH "$ORIGIN/${_moa_bin_to_lib}")
  endif()
  install(TARGETS moa_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

# --- CMake package: find_package(moa) gives moa::moa -------------------------------------
install(EXPORT moaTargets
  NAMESPACE moa::
  FILE moaTargets.cmake
  DESTINATION ${MOA_CMAKE_PACKAGE_DIR})

# libmoa.so carries its dependencies and moa.h includes only the C library, so the package
# needs no find_dependency().
file(WRITE ${PROJECT_BINARY_DIR}/moaConfig.cmake.in [[
@PACKAGE_INIT@

include("${CMAKE_CURRENT_LIST_DIR}/moaTargets.cmake")
check_required_components(moa)
]])
configure_package_config_file(${PROJECT_BINARY_DIR}/moaConfig.cmake.in
  ${PROJECT_BINARY_DIR}/moaConfig.cmake
  INSTALL_DESTINATION ${MOA_CMAKE_PACKAGE_DIR})

# Before 1.0 a minor release may change the interface.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(_moa_compatibility SameMinorVersion)
else()
  set(_moa_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/moaConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY ${_moa_compatibility})

install(FILES
    ${PROJECT_BINARY_DIR}/moaConfig.cmake
    ${PROJECT_BINARY_DIR}/moaConfigVersion.cmake
  DESTINATION ${MOA_CMAKE_PACKAGE_DIR})

# --- pkg-config -------------------------------------------------------------------------
# moa.pc holds absolute paths, so it is written when installing: `cmake --install --prefix`
# then gets paths to where the files really went. First substitute everything known now and
# leave the prefix as a placeholder for the install step.
set(MOA_PC_PREFIX "@MOA_INSTALL_PREFIX@")
foreach(_moa_dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${_moa_dir}}")
    set(MOA_PC_${_moa_dir} "${CMAKE_INSTALL_${_moa_dir}}")
  else()
    set(MOA_PC_${_moa_dir} "\${prefix}/${CMAKE_INSTALL_${_moa_dir}}")
  endif()
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/pkgconfig/moa.pc.in ${PROJECT_BINARY_DIR}/moa.pc.in @ONLY)
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(_moa_pc_destination "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
else()
  set(_moa_pc_destination "\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig")
endif()

install(CODE "
  set(MOA_INSTALL_PREFIX \"\${CMAKE_INSTALL_PREFIX}\")
  configure_file(\"${PROJECT_BINARY_DIR}/moa.pc.in\" \"${PROJECT_BINARY_DIR}/moa.pc\" @ONLY)
  file(INSTALL DESTINATION \"${_moa_pc_destination}\"
       TYPE FILE FILES \"${PROJECT_BINARY_DIR}/moa.pc\")
")
