#!/bin/sh
# RIG-9 (issue 33): LCM fragment headers from a process on the rig's network.
# Ten LC03 headers, each announcing a 256 MiB message on a rig channel, took
# the logger from 161 MB to 2.5 GB RSS in 3 s (its bus allocated and zeroed
# every announced size), the CNC lost it and the run died. While the demo
# runs, scripts/inject/fragment_flood.py sends 800 such headers (10 bursts of
# 80, each from a socket of its own) and 240 that announce 30 MiB, within
# the bus's cap on one message, each with 60 kB of data that never goes on.
# The bursts go 40 ms apart, so that all of them fall within the demo's
# 0.6 .. 0.8 s of wall time on a fast host (0.1 s apart, the last two came
# after the run had ended). The run PASSES, the logger counts the refused headers per channel as
# oversized, and its peak RSS stays far below where it went.
. "$(dirname "$0")/lib.sh"
port=7760
flood="$HIL_SOURCE/scripts/inject/fragment_flood.py"

# The logger's pid, for its peak RSS (VmHWM) while the run goes on.
bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil cnc plc_sim axis_sim; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
printf '#!/bin/sh\necho $$ >"%s/logger.pid"\nexec "%s/hil_logger" "$@"\n' "$WORK" "$HIL_BIN" >"$bin/hil_logger"
chmod +x "$bin/hil_logger"

python3 "$flood" --port $port --wait-for HLI_STATE --count 80 --bursts 10 --interval-s 0.04 >"$WORK/huge.out" 2>&1 &
huge=$!
python3 "$flood" --port $port --wait-for HLI_STATE --count 80 --bursts 3 --interval-s 0.1 --announce-mib 30 \
  --payload 60000 >"$WORK/within.out" 2>&1 &
within=$!
for out in huge within; do  # both listening before the run starts
  i=0
  until grep -q "waiting for" "$WORK/$out.out"; do
    i=$((i + 1)); [ $i -lt 100 ] || fail "fragment_flood.py did not start: $(cat "$WORK/$out.out")"; sleep 0.1
  done
done

"$bin/hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/run" --port $port --bin-dir "$bin" \
  >"$WORK/last.out" 2>&1 &
run=$!
peak=0
while kill -0 $run 2>/dev/null; do
  pid=$(cat "$WORK/logger.pid" 2>/dev/null || true)
  kib=$( [ -n "$pid" ] && awk '/^VmHWM/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  [ -n "$kib" ] && [ "$kib" -gt "$peak" ] && peak=$kib
  sleep 0.05
done
set +e; wait $run; status=$?; set -e
cat "$WORK/last.out"
wait $huge || fail "fragment_flood.py (256 MiB) did not send: $(cat "$WORK/huge.out")"
wait $within || fail "fragment_flood.py (30 MiB) did not send: $(cat "$WORK/within.out")"
echo "logger peak RSS: $((peak / 1024)) MiB"
[ "$status" -eq 0 ] || fail "the run under the fragment flood exited with $status"
expect_output "PASSED"
expect_output "log complete: yes"
# 800 headers over the injector's 8 channels: 100 refused on each.
for channel in HLI_CONTROL HLI_STATE AXIS_X_STATE AXIS_Y_STATE AXIS_Z_STATE AXIS_X_CMD HIL_PARTICIPANT HIL_EVENT; do
  grep -q "^  logger: .*$channel: 100 oversized" "$WORK/last.out" || fail "the logger's refused $channel headers"
done
[ "$peak" -gt 0 ] || fail "no RSS read from the logger"
# The caps: 32 MiB a message, 64 MiB in all (lcm_support/fragment_reassembly.hpp),
# on top of the logger's own (161 MB measured on a developer's machine).
[ "$peak" -lt $((300 * 1024)) ] || fail "the logger's peak RSS was $((peak / 1024)) MiB"
expect_status 0 "$hil" check "$WORK/run/run.lcmlog"
expect_output "CHECK PASSED"
