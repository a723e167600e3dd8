#!/usr/bin/env bash
# Installs what FeaturePoints needs on Debian 12 (run as root).
#   scripts/install-dependencies.sh             the plain VTK build: libvtk9-dev (VTK 9.1)
#   scripts/install-dependencies.sh --paraview  the ParaView 5.11 plugin build: paraview-dev
# The two cannot be installed together (libvtk9-dev needs python3-vtk9, which conflicts with
# python3-paraview): each mode removes what conflicts with it. README.md, "ParaView plugin".
set -euo pipefail
# liblzf-dev: PCD's binary_compressed data (the IO module, built in both modes).
# mpi-default-dev: VTK's MPI modules need it to build FeaturePoints::Parallel; openmpi-bin:
# mpiexec, for distributed runs and their tests (both modes).
common=(cmake g++ make libeigen3-dev libnanoflann-dev liblzf-dev xvfb xauth mpi-default-dev openmpi-bin)
if [ "${1:-}" = "--paraview" ]; then
  # paraview-dev's CMake package finds Qt 5 and the system libraries its bundled VTK was built
  # with, but depends on none of their -dev packages: they are listed here.
  # paraview: pvbatch (paraview-dev depends on it; listed for the plugin's pvbatch tests).
  packages=("${common[@]}" paraview paraview-dev python3-paraview
    qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev qtxmlpatterns5-dev-tools
    libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libboost-dev
    libdouble-conversion-dev libexpat1-dev libfreetype6-dev libgdal-dev libgl-dev libgl2ps-dev
    libglew-dev libhdf5-dev libhdf5-mpi-dev libjpeg-dev libjsoncpp-dev liblz4-dev liblzma-dev
    libnetcdf-dev libnetcdf-cxx-legacy-dev libpng-dev libpython3-dev libtbb-dev libtheora-dev
    libtiff-dev libutfcpp-dev libx11-dev libxml2-dev libxt-dev mpi-default-dev python3-mpi4py
    zlib1g-dev)
  conflicting=(libvtk9-dev python3-vtk9)
else
  # python3-vtk9 (a dependency of libvtk9-dev) and these: the Python package and its tests.
  packages=("${common[@]}" libvtk9-dev python3-numpy python3-pytest)
  conflicting=(paraview-dev python3-paraview)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# apt does not remove the other mode's packages by itself: "name-" removes in the same transaction.
remove=()
for p in "${conflicting[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && remove+=("$p-")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" ${remove[@]+"${remove[@]}"}
fi
