# Every dependency is a Debian 12 package (packaging/install_deps.sh installs them).
find_package(Threads REQUIRED)
find_package(Eigen3 3.3 CONFIG REQUIRED)
find_package(assimp CONFIG REQUIRED)
find_package(embree 3 CONFIG REQUIRED)
find_package(Torch CONFIG REQUIRED)
find_package(spdlog CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(ZLIB REQUIRED)
# Qhull (libqhull-dev): convex hulls of the collision parts (core/physics).
find_package(Qhull CONFIG REQUIRED)
# In-the-wild glTF (core/mesh/gltf_plain): Draco-compressed primitives (libdraco-dev),
# EXT_meshopt_compression (libmeshoptimizer-dev), WebP textures (libwebp-dev, pkg-config only).
find_package(draco CONFIG REQUIRED)
find_package(meshoptimizer CONFIG REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(SAGRID_WEBP REQUIRED IMPORTED_TARGET libwebp)

# stb ships headers only; its implementations are compiled once in core/common/stb_impl.cpp.
find_path(SAGRID_STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)
add_library(sagrid_stb INTERFACE)
target_include_directories(sagrid_stb SYSTEM INTERFACE ${SAGRID_STB_INCLUDE_DIR})

# Torch's imported targets carry its compile flags; keep them on the torch targets only.
add_library(sagrid_torch INTERFACE)
target_link_libraries(sagrid_torch INTERFACE ${TORCH_LIBRARIES})

if(SAGRID_BUILD_GUI)
  find_package(glfw3 CONFIG REQUIRED)
  find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
  find_library(SAGRID_IMGUI_LIBRARY imgui REQUIRED)
  find_path(SAGRID_IMGUI_INCLUDE_DIR imgui.h PATH_SUFFIXES imgui REQUIRED)
  set(SAGRID_IMGUI_BACKENDS_DIR /usr/share/doc/libimgui-dev/examples/backends
      CACHE PATH "Dear ImGui backend sources (GLFW, OpenGL3) shipped by libimgui-dev")
endif()

if(SAGRID_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
endif()
if(SAGRID_BUILD_BENCHMARKS)
  find_package(benchmark CONFIG REQUIRED)
endif()
