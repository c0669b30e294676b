#!/bin/sh
# Sets up (packages, build) and runs every test: unit and integration.
set -eu
cd "$(dirname "$0")"
scripts/setup.sh
status=0
ctest --test-dir build --output-on-failure -j "$(nproc)" || status=$?
# A failed test's output is printed where it ended, among the others'; its
# last lines again at the very end, where a truncated CI log still shows them.
[ "$status" -eq 0 ] || scripts/failed_test_tails.sh build/Testing/Temporary/LastTest.log
exit "$status"
