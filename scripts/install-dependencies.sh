#!/usr/bin/env bash
# Installs what FeaturePoints needs to build, test and render on Debian 12 (run as root).
# The plain-VTK build only: libvtk9-dev conflicts with ParaView's packages (see README, "ParaView").
set -euo pipefail
packages=(cmake g++ make libvtk9-dev libeigen3-dev xvfb xauth)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
