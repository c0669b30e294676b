#!/bin/sh
# Sets up (packages, build) and runs the demo scenario through the whole rig
# in a private network namespace; prints the report, leaves the run folder.
set -eu
cd "$(dirname "$0")"
HIL_BUILD_TARGETS="hil" scripts/setup.sh  # hil and the nodes it starts: not the tests
exec scripts/in_netns.sh build/bin/hil run scenarios/demo.yaml "$@"
