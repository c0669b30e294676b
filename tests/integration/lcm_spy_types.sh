#!/bin/sh
# RIG-2, RIG-7: lcm-spy (Debian 12, Java 17) finds every type of lcmtypes/
# in the jar the build makes. Headless: it prints the count, then fails to
# open its window, which is expected here.
. "$(dirname "$0")/lib.sh"

jar="$HIL_BIN/../share/java/hil_types.jar"
[ -s "$jar" ] || fail "no types jar at $jar"
want=$(ls "$HIL_SOURCE"/lcmtypes/*.lcm | wc -l)
set +e
env -u DISPLAY JDK_JAVA_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions CLASSPATH="$jar" \
  timeout 60 lcm-spy >"$WORK/spy.out" 2>&1
set -e
grep "Found" "$WORK/spy.out" || true
grep -q "Found $want LCM types" "$WORK/spy.out" || fail "lcm-spy did not find $want types"
