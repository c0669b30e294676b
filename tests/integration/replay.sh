#!/bin/sh
# RIG-4, RIG-7: a recorded run is a standard LCM event log. `hil replay`
# (lcm-logplayer) plays it four times faster than recorded, a burst far
# denser than a lock-step run, and hil_logger records it with no loss.
# (Debian's lcm-logger loses a few messages even at speed 1; see README.)
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/run" --port 7710
url="udpm://239.255.76.67:7711?ttl=0&recv_buf_size=4194304"
# The replayed HIL_PARTICIPANT messages end the recorder, as in a live run.
"$HIL_BIN/hil_logger" --url "$url" --out "$WORK/replayed.lcmlog" &
recorder=$!
sleep 1
"$hil" replay "$WORK/run/run.lcmlog" --url "$url" --speed 4
wait "$recorder" || fail "hil_logger failed on the replay"
expect_status 0 "$hil" compare "$WORK/run/run.lcmlog" "$WORK/replayed.lcmlog"
expect_output "identical"
