#!/bin/sh
# RIG-9: a logger that is not scheduled for a while (a loaded machine) must
# not lose the run's messages at its socket. hil_inject stops the logger
# (SIGSTOP) at cycle 1000 of the demo for 1.5 s: the cnc waits while the
# logger is more than 128 cycles behind, the run goes on when it catches up,
# the log is whole and the run PASSES. Without that flow control the rig ran
# on and the kernel dropped thousands of datagrams at the logger's socket.
. "$(dirname "$0")/lib.sh"

bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil cnc plc_sim axis_sim; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
printf '#!/bin/sh\necho $$ >"%s/logger.pid"\nexec "%s/hil_logger" "$@"\n' "$WORK" "$HIL_BIN" >"$bin/hil_logger"
chmod +x "$bin/hil_logger"

"$HIL_BIN/hil_inject" --url "udpm://239.255.76.67:7791?ttl=0" --at-cycle 1000 --kill-pid-file "$WORK/logger.pid" \
  --pause-s 1.5 >"$WORK/inject.out" 2>&1 &
injector=$!
expect_status 0 "$bin/hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/run" --port 7791 --bin-dir "$bin"
wait "$injector" || { cat "$WORK/inject.out"; fail "hil_inject did not act"; }
expect_output "PASSED"
grep -q "the kernel dropped 0 datagram(s) at its socket" "$WORK/run/logger.out" || fail "the logger lost datagrams"
expect_status 0 "$hil" check "$WORK/run/run.lcmlog"
