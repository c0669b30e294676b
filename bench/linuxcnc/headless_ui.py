#!/usr/bin/python3
"""Headless DISPLAY for the LinuxCNC reference bench (bench/linuxcnc/README.md).

LinuxCNC starts it as `headless_ui.py -ini <file>` once everything is up (the
technique of LinuxCNC's own tests/*/test-ui.py). It
  1. leaves E-stop, switches the machine on and homes all joints (instant:
     HOME_SEARCH_VEL = 0 in the INI), sets feed and rapid override to 100 %;
  2. starts `halsampler -t` on the sampler FIFO, then enables the sampler;
  3. opens the program $BENCH_PROGRAM (already translated to LinuxCNC's dialect,
     work offsets set by G10 L2 lines at its top) and runs it in AUTO mode;
  4. waits for the interpreter to become idle and the motion queue to drain,
     disables the sampler, waits for halsampler to empty the FIFO, stops it;
  5. writes a JSON status to $BENCH_STATUS and exits, which makes the
     linuxcnc script shut LinuxCNC down.
Timing is NOT measured here: the figures come from the per-servo-cycle samples.
Must be run by /usr/bin/python3 (the linuxcnc module is built for it).
"""
import json
import os
import signal
import subprocess
import sys
import time

import linuxcnc

PROGRAM = os.environ["BENCH_PROGRAM"]
SAMPLES = os.environ["BENCH_SAMPLES"]
STATUS = os.environ["BENCH_STATUS"]
TIMEOUT = float(os.environ.get("BENCH_TIMEOUT", "900"))

status = {"ok": False, "errors": [], "messages": [], "overruns": None}


def log(msg):
    print("[headless_ui] " + msg, file=sys.stderr, flush=True)


def finish(code):
    with open(STATUS, "w") as f:
        json.dump(status, f)
    sys.exit(code)


def halcmd(*args):
    return subprocess.run(["halcmd"] + list(args), capture_output=True, text=True, check=True).stdout.strip()


c = linuxcnc.command()
s = linuxcnc.stat()
e = linuxcnc.error_channel()


def drain_errors():
    bad = False
    while True:
        m = e.poll()
        if not m:
            return bad
        kind, text = m
        if kind in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
            status["errors"].append(text)
            log("LinuxCNC error: " + text)
            bad = True
        else:
            status["messages"].append(text)


def wait_for(cond, timeout, what):
    t0 = time.time()
    while time.time() - t0 < timeout:
        s.poll()
        if cond():
            return True
        if drain_errors():
            return False
        time.sleep(0.01)
    status["errors"].append("timeout waiting for " + what)
    log("timeout waiting for " + what)
    return False


# 1. machine on, homed, overrides 100 %
for attempt in range(100):
    try:
        s.poll()
        break
    except linuxcnc.error:
        time.sleep(0.1)
c.state(linuxcnc.STATE_ESTOP_RESET)
c.wait_complete()
c.state(linuxcnc.STATE_ON)
c.wait_complete()
if not wait_for(lambda: s.task_state == linuxcnc.STATE_ON, 10, "machine on"):
    finish(1)
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
c.home(-1)
c.wait_complete()
if not wait_for(lambda: all(s.homed[j] for j in range(3)), 10, "homing"):
    finish(1)
c.feedrate(1.0)
c.rapidrate(1.0)
c.set_feed_override(1)
c.wait_complete()
s.poll()
status["feedrate"] = s.feedrate
status["rapidrate"] = s.rapidrate
status["max_velocity"] = s.max_velocity
if abs(s.feedrate - 1.0) > 1e-9 or abs(s.rapidrate - 1.0) > 1e-9:
    status["errors"].append("override not 100 %%: feed %g rapid %g" % (s.feedrate, s.rapidrate))
    finish(1)

# 2. sampler on
with open(SAMPLES, "w") as out:
    sampler = subprocess.Popen(["halsampler", "-t"], stdout=out)
time.sleep(0.2)
halcmd("setp", "sampler.0.enable", "1")

# 3. run the program
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()
c.program_open(PROGRAM)
c.wait_complete()
c.auto(linuxcnc.AUTO_RUN, 0)
t_start = time.time()
started = wait_for(lambda: s.interp_state != linuxcnc.INTERP_IDLE, 10, "program start")

# 4. wait for the end: interpreter idle, queue empty, in position.
# A stall watchdog: LinuxCNC 2.9's planner was seen to stop for good with a full
# queue (no error, no motion; G61 on the 10,000-chord circle). No motion for
# STALL_S seconds while segments are queued ends the run as "stalled" (no program
# here dwells that long).
STALL_S = float(os.environ.get("BENCH_STALL_S", "30"))


def wait_end():
    t0 = last_move = time.time()
    last_pos = None
    while time.time() - t0 < TIMEOUT:
        s.poll()
        if drain_errors():
            return False
        if (s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0 and s.inpos
                and s.exec_state == linuxcnc.EXEC_DONE):
            return True
        pos = tuple(s.position[:3])
        if pos != last_pos or s.queue == 0 or s.current_vel != 0:
            last_pos, last_move = pos, time.time()
        elif time.time() - last_move > STALL_S:
            status["stalled"] = {"motion_line": s.motion_line, "current_line": s.current_line,
                                 "queue": s.queue, "queue_full": bool(s.queue_full),
                                 "position": list(pos), "after_s": time.time() - t0}
            status["errors"].append("stalled: no motion for %g s with %d segments queued, at line %d"
                                    % (STALL_S, s.queue, s.current_line))
            log(status["errors"][-1])
            return False
        time.sleep(0.01)
    status["errors"].append("timeout waiting for program end")
    return False


ok = started and wait_end()
status["wall_run_s"] = time.time() - t_start
time.sleep(0.1)                      # a few idle samples after the end
halcmd("setp", "sampler.0.enable", "0")
for _ in range(500):                 # halsampler empties the FIFO
    if int(halcmd("getp", "sampler.0.curr-depth")) == 0:
        break
    time.sleep(0.01)
time.sleep(0.2)
status["overruns"] = int(halcmd("getp", "sampler.0.overruns"))
sampler.send_signal(signal.SIGTERM)   # the halsampler this script started
try:
    sampler.wait(5)
except subprocess.TimeoutExpired:
    sampler.kill()
drain_errors()
s.poll()
if ok and not status["errors"]:
    status["ok"] = True
if not ok:
    c.abort()
    c.wait_complete()
finish(0 if status["ok"] else 1)
