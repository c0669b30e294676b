#!/bin/sh
# RIG-2, RIG-7: `hil spy` starts Debian 12's lcm-spy (Java 17) with every type
# of lcmtypes/ decodable, live on a URL or on a log file. Headless: lcm-spy
# prints how many types it found, then fails to open its window, as
# expected here.
. "$(dirname "$0")/lib.sh"

want=$(ls "$HIL_SOURCE"/lcmtypes/*.lcm | wc -l)
spy() {
  set +e
  env -u DISPLAY timeout 60 "$hil" spy "$@" >"$WORK/spy.out" 2>&1
  set -e
  grep "lcm-spy on\|Found" "$WORK/spy.out" || true
  grep -q "Found $want LCM types" "$WORK/spy.out" || fail "lcm-spy did not find $want types"
}
spy "udpm://239.255.76.67:7740?ttl=0"
grep -q "lcm-spy on udpm://239.255.76.67:7740?ttl=0" "$WORK/spy.out" || fail "not on the URL given"
: > "$WORK/empty.lcmlog"
spy "$WORK/empty.lcmlog" --speed 2
grep -q "lcm-spy on file://$WORK/empty.lcmlog?speed=2" "$WORK/spy.out" || fail "not on the log file"
