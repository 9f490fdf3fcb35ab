# cpack -G DEB (README.md, "Installing"): one Debian package, shadelab_VERSION_ARCH.deb, of
# everything cmake --install installs, under /usr (the library folder is the build's
# CMAKE_INSTALL_LIBDIR: lib, or lib/<multiarch> when the build was configured with
# CMAKE_INSTALL_PREFIX=/usr). Its Depends:
#  - the runtime libraries the ELF files need, found by dpkg-shlibdeps (dpkg-dev; CPack finds
#    the ELF files with `file`): libc6, libstdc++6, libpng16-16, libhwy1, cpp-httplib, libX11 ...
#  - the development packages that the headers, the CMake package and the pkg-config files
#    need: glm is in the public headers (a PUBLIC dependency of shadelab::shadelab), and the
#    static core library is linked with libpng, libjpeg, Highway, tinyobjloader and stb, which
#    shadelabConfig.cmake finds with find_dependency and shadelab.pc requires. The package
#    is runtime and development files at once, so it depends on both.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME shadelab)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "shadelab maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "OpenGL's fixed-function lighting and shading on the CPU: renderer, OpenGL 1.1 library")
set(CPACK_PACKAGE_DESCRIPTION "\
The lighting, shading and materials of classic OpenGL, rendered on the CPU, headless
and exactly: the shadelab command (render, sweep, gallery, serve, run), the core C++
library with its headers, libshadelab-gl (OpenGL 1.1 and OSMesa, its headers apart
from Mesa's), GLUT's shapes, shadelab's GLVND vendors (GLX, EGL), libOSMesa.so.8, a
CMake package, pkg-config files and the Python package (import shadelab).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # debug information stays in the build
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# fonts-dejavu-core: the contact sheets' labels; python3 and python3-numpy: the Python
# package; then the development packages (above).
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "fonts-dejavu-core, python3, python3-numpy, libglm-dev, libpng-dev, libjpeg62-turbo-dev, libhwy-dev, libtinyobjloader-dev, libstb-dev")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "xvfb, pkg-config")  # shadelab run --xvfb; the .pc files
include(CPack)
