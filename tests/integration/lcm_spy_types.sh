#!/bin/sh
# RIG-2, RIG-7: `hil spy` starts Debian 12's lcm-spy (Java 17) with every type
# of lcmtypes/ decodable, live on a URL or on a log file (in simulated time).
# Headless: lcm-spy prints how many types it found, then cannot open its
# window, said in one line (issue 37: no Java trace, no URL warning, exit 2).
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
grep -q "lcm-spy on $WORK/empty.lcmlog at 2 x simulated time" "$WORK/spy.out" || fail "not on the log file"
quiet() {
  grep -q "no display to open its window on" "$WORK/spy.out" || fail "no one-line message without a display"
  ! grep -q "Exception\|	at \|Invalid key-value pair\|Picked up JDK_JAVA_OPTIONS" "$WORK/spy.out" || fail "Java noise: $(cat "$WORK/spy.out")"
}
quiet
set +e
env -u DISPLAY timeout 60 "$hil" logplayer "$WORK/empty.lcmlog" >"$WORK/spy.out" 2>&1
status=$?
set -e
[ "$status" -eq 2 ] || fail "hil logplayer without a display exited with $status, not 2 (a hang is 124)"
quiet
