#!/usr/bin/env bash
# Installs the Debian 12 packages SAGrid builds, tests and runs with.
# Idempotent: does nothing when every package is already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache
  # libopenblas0-openmp: Debian's libtorch otherwise runs its matrix products on the reference BLAS
  # (about 4x slower for the SAGrid network; measured with tests/benchmarks/model_bench).
  libtorch-dev libopenblas0-openmp libembree-dev libassimp-dev libeigen3-dev
  libglfw3-dev libimgui-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libgmock-dev libbenchmark-dev
  libspdlog-dev libfmt-dev libcli11-dev nlohmann-json3-dev libstb-dev zlib1g-dev
  # libqhull-dev: convex hulls of the collision parts (core/physics)
  libqhull-dev
  # In-the-wild glTF: Draco-compressed meshes, EXT_meshopt_compression, WebP textures
  libdraco-dev libmeshoptimizer-dev libwebp-dev
  xvfb xauth
  # Simulator checks of the exports: MuJoCo 2.2.2 loads and simulates the MJCF export in tests,
  # check_urdf (urdfdom) validates the OmniGibson URDFs.
  libmujoco-dev liburdfdom-tools
  # help2man: the man page of the Debian package (make package, tests/packaging)
  help2man
  # slurm-wlm, munge: the one-node Slurm cluster of the array-job test (tests/e2e/slurm_cluster_test.cpp,
  # packaging/slurm/local_cluster.sh)
  slurm-wlm munge
)
# `install_deps.sh fuzz` adds the opt-in fuzzing toolchain of `make fuzz`: clang and libFuzzer.
if [ "${1:-}" = fuzz ]; then packages+=(clang libclang-rt-14-dev); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
