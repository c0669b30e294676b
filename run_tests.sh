#!/bin/sh
# Sets up (packages, build) and runs every test: unit and integration.
set -eu
cd "$(dirname "$0")"
scripts/setup.sh
exec ctest --test-dir build --output-on-failure -j "$(nproc)"
