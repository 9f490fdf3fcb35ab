# cmake --install (README.md, "Installing"): the `shadelab` command, the core library
# (libshadelab.a) and its headers, the CMake package shadelab (find_package(shadelab CONFIG):
# shadelab::shadelab, shadelab::gl, shadelab::gl_static, shadelab::glut) and the pkg-config
# files shadelab, shadelab-gl and shadelab-glut. gl/CMakeLists.txt installs libshadelab-gl, its
# headers and libshadelab-glut (exported in the same set), the GLVND vendors and libOSMesa.so.8
# (docs/platform.md, "Installed"). Every folder comes from GNUInstallDirs. Nothing here changes
# what the build makes in the build folder.
#
# The core library is installed static, as it is built. Its C++ API (std::vector, std::string and
# glm types in its structs, version 0.x) keeps no binary compatibility from one version to the
# next, which a shared library would promise; static, a program carries the version it was built
# with. Its link dependencies (libpng, libjpeg, Highway, tinyobjloader, stb, threads; glm for the headers)
# are in the package: shadelabConfig.cmake finds them with find_dependency, shadelab.pc lists
# them. libshadelab-gl.so has the core linked in, so C programs need none of them.
include(CMakePackageConfigHelpers)

set(SHADELAB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shadelab)
set(SHADELAB_PKGCONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
set(SHADELAB_INSTALL_STAGING ${CMAKE_BINARY_DIR}/install)

install(TARGETS shadelab_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set_target_properties(shadelab PROPERTIES EXPORT_NAME shadelab)
install(TARGETS shadelab EXPORT shadelab-targets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/shadelab DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Example scenes, for `shadelab render` (their meshes and textures are relative to them).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/shadelab/scenes)

# cmake --install --strip (and cpack, CPACK_STRIP_FILES) strips executables and shared libraries
# only; the static libraries lose their debug information too (as Debian's dh_strip does): over
# 200 MB of it, which stays in the build.
if(CMAKE_STRIP)
  foreach(lib shadelab shadelab-gl-static shadelab-glut)
    install(CODE "if(CMAKE_INSTALL_DO_STRIP)
  execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug
    \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:${lib}>\"
    COMMAND_ERROR_IS_FATAL ANY)
endif()")
  endforeach()
endif()

# The CMake package: relocatable (every path relative to the file's own folder).
install(EXPORT shadelab-targets NAMESPACE shadelab:: FILE shadelabTargets.cmake
        DESTINATION ${SHADELAB_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/install/shadelabConfig.cmake.in
  ${SHADELAB_INSTALL_STAGING}/shadelabConfig.cmake INSTALL_DESTINATION ${SHADELAB_CMAKE_DIR})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${SHADELAB_INSTALL_STAGING}/shadelabConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${SHADELAB_INSTALL_STAGING}/shadelabConfig.cmake
              ${SHADELAB_INSTALL_STAGING}/shadelabConfigVersion.cmake
        DESTINATION ${SHADELAB_CMAKE_DIR})

# pkg-config files, relocatable too: the prefix is found from the file's folder (${pcfiledir}).
file(RELATIVE_PATH SHADELAB_PC_TO_PREFIX /prefix/${SHADELAB_PKGCONFIG_DIR} /prefix)
string(REGEX REPLACE "/$" "" SHADELAB_PC_TO_PREFIX "${SHADELAB_PC_TO_PREFIX}")
set(SHADELAB_PC_PREFIX "\${pcfiledir}/${SHADELAB_PC_TO_PREFIX}")
foreach(pc shadelab shadelab-gl shadelab-glut)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/install/${pc}.pc.in ${SHADELAB_INSTALL_STAGING}/${pc}.pc @ONLY)
  install(FILES ${SHADELAB_INSTALL_STAGING}/${pc}.pc DESTINATION ${SHADELAB_PKGCONFIG_DIR})
endforeach()
