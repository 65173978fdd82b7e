#!/usr/bin/env bash
# Installs everything Prism needs to build and test, from Debian 12 packages only.
# Idempotent: apt-get skips what is already installed. Run as root.
set -euo pipefail

packages=(
  g++ cmake make ninja-build pkg-config  # toolchain
  lld                               # links several times faster than GNU ld (PRISM_LLD)
  libglm-dev                        # vector math
  libtiff-dev libpng-dev            # 8-bit TIFF and PNG, written directly (core/io/image_io.cpp)
  libopenimageio-dev openimageio-tools  # other image files, in the module libprism_oiio.so (and oiiotool for comparisons)
  fonts-dejavu-core                 # the text of `prism sweep`'s plots (OpenImageIO draws it)
  libcli11-dev                      # command-line parsing
  nlohmann-json3-dev                # statistics as JSON
  libtinyobjloader-dev              # OBJ/MTL import
  libgtest-dev                      # tests
  # the Python module (python/, docs/python.md): pybind11, the headers of
  # Debian's python3, numpy for its pictures; pytest for running its tests
  # by hand (ctest runs them with unittest)
  pybind11-dev python3-dev python3-numpy python3-pytest
  help2man                          # the manual page, written at build time from --help (packaging/)
  dpkg-dev                          # cpack's .deb: dpkg-shlibdeps finds its Depends (tests/package_test.cpp)
  openmpi-bin libopenmpi-dev        # distributed rendering (libprism_mpi.so; mpirun for its tests)
  # the previewer: windows, OpenGL (GLVND) and Mesa's software rasteriser, Dear ImGui
  libglfw3-dev libopengl-dev libgl-dev libgl1-mesa-dri libimgui-dev
  libosmesa6-dev                    # the display test draws offscreen through OSMesa
  xvfb xauth                        # the window tests start their own X server (xvfb-run)
  xdotool                           # ... and drive the window with real mouse and key events
  libx11-dev                        # ... and drop files on it (tests/xdnd_source.cpp)
  x11-xserver-utils                 # xrdb: a HiDPI screen (Xft.dpi) for the scaling test
  # fuzzing the readers (.ci/fuzz.sh): clang with libFuzzer's runtime (only a
  # Recommends of clang-14) and llvm-symbolizer for readable stack traces
  clang-14 libclang-rt-14-dev llvm-14
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
