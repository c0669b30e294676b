#!/bin/sh
# RIG-7 (issue 37, 1): `hil run --pace F` runs lock-step no faster than F x
# real time and logs what an unpaced run logs; `hil run --spy` starts the spy
# (here a stand-in, $HIL_LCM_SPY, that listens on the port as lcm-spy does),
# waits until it listens, then runs paced: the spy sees the run from its
# manifest on. A log plays in simulated time.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
sed -e "s|^machine: .*|machine: $HIL_SOURCE/config/xyz_machine.yaml|" \
  "$HIL_SOURCE/tests/integration/scenarios/short_move.yaml" >short_move.yaml

wall() { sed -n "s/^$2: //p" "$1"; }
expect_status 0 "$hil" run short_move.yaml --in-process --out fast
expect_status 0 "$hil" run short_move.yaml --in-process --out paced --pace 1
simulated=$(wall paced/summary.yaml simulated_s)
paced=$(wall paced/summary.yaml wall_s)
python3 -c "import sys; s, w = map(float, sys.argv[1:]); assert w >= s, (w, s)" "$simulated" "$paced" \
  || fail "a run at --pace 1 took $paced s for $simulated s simulated"
expect_status 0 "$hil" compare fast/run.lcmlog paced/run.lcmlog
expect_output "identical"
# Processes, half the machine's pace.
expect_status 0 "$hil" run short_move.yaml --out paced_processes --pace 0.5 --port 7761
python3 -c "import sys; s, w = map(float, sys.argv[1:]); assert w >= 2 * s, (w, s)" \
  "$(wall paced_processes/summary.yaml simulated_s)" "$(wall paced_processes/summary.yaml wall_s)" \
  || fail "--pace 0.5 ran faster than half real time"
expect_status 0 "$hil" compare fast/run.lcmlog paced_processes/run.lcmlog
expect_output "identical"

# --spy with a stand-in for lcm-spy that counts what it hears until 3 s of silence.
cat >spy.py <<'PY'
#!/usr/bin/env python3
import re, socket, struct, sys
url = sys.argv[1].split("=", 1)[1]
group, port = re.match(r"udpm://([\d.]+):(\d+)", url).groups()
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("", int(port)))
s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, struct.pack("4s4s", socket.inet_aton(group), socket.inet_aton("0.0.0.0")))
s.settimeout(3)
seen = set()
try:
    while True:
        d = s.recv(65536)
        if d[:4] == b"LC02":
            seen.add(d[8:d.index(b"\0", 8)].decode())
except socket.timeout:
    pass
print("spy heard: " + " ".join(sorted(seen)), flush=True)
PY
chmod +x spy.py
HIL_LCM_SPY="$WORK/spy.py" expect_status 0 "$hil" run short_move.yaml --spy --out spied --port 7762
expect_output "lcm-spy listens; the run goes at 1 x real time"
expect_output "close lcm-spy to end"
grep -q "spy heard: .*HIL_MANIFEST.*HLI_STATE" spied/lcm-spy.out || fail "the spy missed the run's start: $(cat spied/lcm-spy.out)"
expect_status 0 "$hil" compare fast/run.lcmlog spied/run.lcmlog
expect_output "identical"
expect_status 2 "$hil" run short_move.yaml --spy --in-process --out x
expect_output "--spy watches the run on LCM: not with --in-process"

# A log plays in simulated time: 0.2 s simulated at speed 0.5 takes >= 0.4 s.
start=$(date +%s.%N)
expect_status 0 "$hil" replay fast/run.lcmlog --speed 0.5 --url "udpm://239.255.76.67:7763?ttl=0"
end=$(date +%s.%N)
expect_output "s simulated (recorded in"
python3 -c "import sys; s, a, b = map(float, sys.argv[1:]); assert b - a >= 2 * s * 0.95, (b - a, s)" \
  "$simulated" "$start" "$end" || fail "replay at 0.5 was faster than half the simulated time"
echo "paced runs: ok"
