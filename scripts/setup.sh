#!/bin/sh
# Installs the Debian packages the rig needs (only when one is missing) and
# builds it into build/. Extra arguments go to cmake's configure step.
set -eu
cd "$(dirname "$0")/.."

packages="build-essential cmake pkg-config iproute2 util-linux git python3
  liblcm-dev liblcm-bin liblcm-java libjchart2d-java default-jdk-headless
  libeigen3-dev libspdlog-dev catch2 libcli11-dev libyaml-cpp-dev gnuplot-nox libsodium-dev liblzma-dev
  python3-yaml python3-jsonschema"

missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "setup: installing$missing"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends $missing
fi

cmake -S . -B build "$@"
# HIL_BUILD_TARGETS: only these (and what they need), e.g. "hil" for the
# demo: hil and the nodes it starts, without the tests and benchmarks.
if [ -n "${HIL_BUILD_TARGETS:-}" ]; then
  cmake --build build -j "$(nproc)" --target $HIL_BUILD_TARGETS
else
  cmake --build build -j "$(nproc)"
fi
