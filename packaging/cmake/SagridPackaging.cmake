# Installation and the Debian package (`make install`, `make package`): the sagrid binary in
# <prefix>/bin, the default models, samples and bundled datasets in <prefix>/share/sagrid (where
# core/common/resource_paths finds them from <prefix>/bin/..), a desktop entry and icon, and a
# man page made from --help at install time. CPack builds the .deb with the dependencies
# dpkg-shlibdeps reads off the binary.
include(GNUInstallDirs)

install(TARGETS sagrid RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(SAGRID_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/sagrid)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/models ${PROJECT_SOURCE_DIR}/resources/samples
                  ${PROJECT_SOURCE_DIR}/resources/datasets
        DESTINATION ${SAGRID_SHARE_DIR}
        PATTERN "*.loss.csv" EXCLUDE  # training curves: in the repository, not needed to run
        PATTERN "*.loss.png" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/sagrid.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/sagrid.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(CODE "
  set(man_page \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_MANDIR}/man1/sagrid.1.gz\")
  message(STATUS \"Installing: \${man_page} (from sagrid --help)\")
  execute_process(COMMAND \"${CMAKE_COMMAND}\" -DSAGRID=$<TARGET_FILE:sagrid>
                          -DOUTPUT=\${man_page}
                          -P \"${PROJECT_SOURCE_DIR}/packaging/cmake/SagridManPage.cmake\"
                  RESULT_VARIABLE man_rc)
  if(NOT man_rc EQUAL 0)
    message(FATAL_ERROR \"the man page could not be made\")
  endif()
  list(APPEND CMAKE_INSTALL_MANIFEST_FILES \"\${man_page}\")
")

# `make install` / `make package` build first; installing must not rebuild the whole tree
# (the package test runs cpack from a build where only some targets may be current).
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY TRUE)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sagrid)
set(CPACK_PACKAGE_VENDOR "SAGrid")
set(CPACK_PACKAGE_CONTACT "SAGrid maintainers <sagrid@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "simulation affordance points on 3D meshes")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "SAGrid predicts where a robot simulator needs an object to work -- heat sources, fluid "
    "sources, toggle buttons -- on 3D meshes (OBJ, glTF/GLB, FBX, PLY, STL) with a voxel CNN, "
    "lets a person review and correct the points in a GUI, and exports simulator-ready labels. "
    "Default models and sample meshes are in /usr/share/sagrid.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # sagrid_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)  # Depends from the libraries the binary links
# Not linked, but needed to run well: an optimised BLAS for libtorch, the Mesa EGL/GL drivers
# for the GUI and headless rendering (libEGL/libGL are only the GLVND dispatchers).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libopenblas0-openmp, libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
include(CPack)
