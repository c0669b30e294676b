#!/usr/bin/python3
"""LinuxCNC 2.9 reference bench (bench/linuxcnc/README.md). Run it through run.sh.

LinuxCNC is a REFERENCE ONLY: nothing in the project depends on it. This script
translates the project's TwinCAT-dialect NC programs to LinuxCNC's dialect,
runs each one on LinuxCNC's headless simulator (xyz_sim.ini, headless_ui.py)
under G61 and under G64 P0.01, samples every 1 ms servo cycle with the HAL
sampler and prints one line per program and mode:

    program mode time_s v_med v_p5 dev_mm samples

  time_s   (last moving sample - first moving sample + 1) x 1 ms; "moving": the
           commanded XYZ changed since the previous servo cycle
  v_med    median path speed (mm/s) over the feed samples
  v_p5     5th percentile of the path speed (mm/s) over the feed samples
  dev_mm   largest distance of a feed sample's commanded XYZ from the programmed
           path (G1 polyline, G2/G3 arcs; program coordinates = machine - work
           offset); the candidates for a sample are the programmed blocks within
           +-WINDOW motion blocks of the line LinuxCNC reports as executing
  samples  number of feed samples (the base of v_med, v_p5, dev_mm)

  feed samples: moving samples whose motion.motion-type is 2 (linear feed) or
  3 (arc feed), i.e. G1/G2/G3 and the blend arcs LinuxCNC inserts between them
  (a blend arc takes the motion type of the segment before it); motion.motion-type
  and motion.program-line are sampled every servo cycle with the positions.

Path speed is |p[k] - p[k-1]| / 1 ms of the sampled commanded positions, the
speed the axes are really commanded; time is counted in samples, so a loaded
host does not change the figures (a lost sample is reported, never hidden).

Progress goes to stderr, the table to stdout.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
MACHINE_YAML = os.path.join(REPO, "config", "xyz_machine.yaml")
CONFIG_FILES = ["xyz_sim.ini", "xyz_sim.hal", "tool.tbl", "headless_ui.py"]
CORPUS = ["surfacing_3d", "engraving", "plasma_profile", "mixed_transitions", "radius_arcs"]
CHORD = {"chord_circle_9dec": 9, "chord_circle_4dec": 4, "chord_circle_3dec": 3}
DEFAULT_PROGRAMS = list(CHORD) + CORPUS
MODES = {"G61": "G61", "G64": "G64 P0.01"}   # Q (naive CAM tolerance) not given: LinuxCNC then uses Q = P
PERIOD_S = 0.001
WINDOW = 40          # motion blocks either side of the executing line searched for dev_mm


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- machine file
def read_machine(path):
    """The few numbers of config/xyz_machine.yaml the bench needs, without a YAML
    library (the /usr/bin/python3 of the LinuxCNC package may have none)."""
    offsets, axes, cur = {}, {}, None
    section = None
    for raw in open(path):
        line = raw.split("#", 1)[0].rstrip()
        if not line.strip():
            continue
        if not line.startswith(" "):
            section = line.split(":")[0].strip()
            continue
        if section == "zero_offsets":
            m = re.match(r"\s+(G5[4-9])\s*:\s*\{(.*)\}", line)
            if m:
                offsets[m.group(1)] = {k.strip(): float(v) for k, v in
                                       (kv.split(":") for kv in m.group(2).split(","))}
        elif section == "axes":
            m = re.match(r"\s+-\s*name\s*:\s*(\w+)", line)
            if m:
                cur = axes.setdefault(m.group(1), {})
                continue
            m = re.match(r"\s+(v_max|a_max|j_max)\s*:\s*([-\d.eE+]+)", line)
            if m and cur is not None:
                cur[m.group(1)] = float(m.group(2))
    return offsets, axes


def check_ini_limits(ini_path, axes):
    """The INI must carry the machine file's v_max / a_max (mm/s, mm/s^2)."""
    text = open(ini_path).read()
    problems = []
    for j, name in enumerate("XYZ"):
        for sec in ("AXIS_" + name, "JOINT_%d" % j):
            body = re.search(r"^\[%s\]\n(.*?)(?=^\[|\Z)" % sec, text, re.S | re.M).group(1)
            for key, yk in (("MAX_VELOCITY", "v_max"), ("MAX_ACCELERATION", "a_max")):
                v = float(re.search(r"^%s\s*=\s*(\S+)" % key, body, re.M).group(1))
                if abs(v - axes[name][yk]) > 1e-9:
                    problems.append("%s %s = %g but %s %s = %g" % (sec, key, v, name, yk, axes[name][yk]))
    return problems


# ---------------------------------------------------------------- translation
class Refused(Exception):
    pass


WORD = re.compile(r"([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
# TwinCAT block transition words: the bench applies ONE mode to the whole program
# (G61 or G64 P0.01 at its top), so all of them are removed:
#   G60 exact stop (non-modal), G61 (TwinCAT: polynomial contouring at this block's
#   end, non-modal), G260/G261 (contouring off/on), G359/G360 (exact-stop section).
TRANSITION_G = {60, 61, 260, 261, 359, 360}
KEEP_G = {0, 1, 2, 3, 17, 18, 19, 40, 90, 91, 94}
# TwinCAT G word -> LinuxCNC's, and the note printed for it.
G_RENAMED = {
    71: ("G21", "G71 -> G21"),
    70: ("G20", "G70 -> G20"),
    161: ("G90.1", "G161 -> G90.1"),
    162: ("G91.1", "G162 -> G91.1"),
    53: ("G59.3", "G53 (modal) -> G59.3 with zero offset"),
    4: ("G4", "G04 X<s> -> G4 P<s>"),
}
LINUXCNC_M = {2, 3, 4, 5, 6, 7, 8, 9, 30}


def strip_comments(line):
    out, depth = [], 0
    for ch in line:
        if depth == 0 and ch == ";":
            break
        if ch == "(":
            depth += 1
        elif ch == ")" and depth:
            depth -= 1
        elif depth == 0:
            out.append(ch)
    return "".join(out)


def translate(src_lines, offsets, mode_line):
    """TwinCAT (TF5200, docs/DIALECT.md) -> LinuxCNC 2.9 rs274ngc, one output line
    per input line (after the prelude) so line numbers map back. Changes made:
      - '%name' headers and '#...' TwinCAT commands (#HSC, #CONTOUR MODE, ..., also
        after an N number) are dropped;
      - comments '( .. )' and ';' are removed (LinuxCNC 2.9 accepts both, but reads
        '(MSG,', '(DEBUG,', '(PRINT,' ... comments as commands; removing them changes
        no motion);
      - G71 -> G21, G70 -> G20; G161 -> G90.1, G162 -> G91.1 (arc centre modes);
      - G60 G61 G260 G261 G359 G360 (TwinCAT transition words) removed: the bench
        mode (G61 or G64 P0.01) is set once in the prelude;
      - G164 G165 (centre correction) removed; LinuxCNC checks arc end radii itself;
      - G04 X<s> / G04 <s> -> G4 P<s> (dwell);
      - G53, TwinCAT's modal 'no zero offset' (initial state) -> G59.3, whose
        offset the prelude sets to 0 (LinuxCNC's G53 is non-modal);
        G54..G59 are kept, their offsets set by G10 L2 P1..P6 in the prelude from
        config/xyz_machine.yaml (both: machine = program + offset);
      - D words (TwinCAT tool offset number) and H words (H functions for the
        PLC) removed: LinuxCNC reads them only with G41/G42 and G43;
      - M0/M1 removed (a programmed stop would wait for a cycle start the
        headless run never gives) and M functions LinuxCNC does not know (other
        than M2-M9, M30: TwinCAT sends any M to the PLC) removed;
      - a leading block skip '/' or '/n' is removed (TwinCAT's default mask 0 runs
        the block);
      - N words kept (N > 99999 dropped); an M30 is appended if the program has no
        M2/M30.
    Refused (raise Refused): P parameters, V.G.* variables, $ control blocks,
    G74/G92/G100 and any other G word not listed above, letters LinuxCNC has no
    equivalent for (E, L, O, P as a word, A/B/C on this XYZ machine)."""
    notes = set()
    pre = ["G21 G17 G90 G94 G40 G49 G80 G91.1",
           "G92.1"]
    for g, p in (("G54", 1), ("G55", 2), ("G56", 3), ("G57", 4), ("G58", 5), ("G59", 6)):
        o = offsets.get(g, {})
        pre.append("G10 L2 P%d X%g Y%g Z%g" % (p, o.get("X", 0), o.get("Y", 0), o.get("Z", 0)))
    pre += ["G10 L2 P9 X0 Y0 Z0", "G59.3", mode_line]
    out = list(pre)
    has_end = False
    for n, raw in enumerate(src_lines, 1):
        line = raw.rstrip("\r\n")
        body = line.strip()
        head = re.match(r"^(?:/\d*\s*)?(?:N\d+\s*)?", body.upper()).group(0)
        rest = body[len(head):].lstrip()
        if body.startswith("%") or rest.startswith("#"):
            if body.startswith("%"):
                notes.add("'%' header dropped")
            else:
                notes.add("'#' TwinCAT commands dropped (e.g. %s)" % rest.split("[")[0].strip()[:20])
            out.append("")
            continue
        code = strip_comments(body).upper().strip()
        if not code:
            if body:
                notes.add("comments removed")
            out.append("")
            continue
        if body != code:
            notes.add("comments removed")
        if code.startswith("/"):
            code = re.sub(r"^/\d*\s*", "", code)
            notes.add("block skip '/' removed (block runs)")
        if code.startswith("$") or "=" in code or "V." in code or "[" in code:
            raise Refused("line %d: %r: parameters / variables / control blocks are not translated" % (n, raw.strip()))
        code = re.sub(r"\bG0*4\s+([\d.]+)", r"G04 X\1", code)     # G04 <s> -> G04 X<s>
        words = []
        pos = 0
        for m in WORD.finditer(code):
            if code[pos:m.start()].strip():
                raise Refused("line %d: cannot read %r" % (n, code[pos:m.start()]))
            words.append((m.group(1), m.group(2)))
            pos = m.end()
        if code[pos:].strip():
            raise Refused("line %d: cannot read %r" % (n, code[pos:]))
        gs = [float(v) for k, v in words if k == "G"]
        dwell = any(g == 4 for g in gs)
        res = []
        for k, v in words:
            f = float(v)
            if k == "G":
                gi = int(f) if f == int(f) else None
                if gi in KEEP_G or gi in (54, 55, 56, 57, 58, 59):
                    res.append("G%s" % v)
                elif gi in G_RENAMED:
                    word, note = G_RENAMED[gi]
                    res.append(word); notes.add(note)
                elif gi in TRANSITION_G:
                    notes.add("G%d removed (bench mode applies)" % gi)
                elif gi in (164, 165):
                    notes.add("G%d removed" % gi)
                else:
                    raise Refused("line %d: G%s is not translated" % (n, v))
            elif k == "X" and dwell:
                res.append("P%s" % v)
            elif k == "N":
                if f <= 99999:
                    res.append("N%s" % v)
            elif k == "M":
                mi = int(f)
                if mi in LINUXCNC_M:
                    res.append("M%s" % v)
                    has_end |= mi in (2, 30)
                else:
                    notes.add("M%d removed" % mi)
            elif k in "DH":
                notes.add("%s words removed" % k)
            elif k in "XYZIJKRFST":
                res.append(k + v)
            else:
                raise Refused("line %d: word %s%s is not translated" % (n, k, v))
        out.append(" ".join(res))
    if not has_end:
        out.append("M30")
        notes.add("M30 appended")
    return out, len(pre), sorted(notes)


# ---------------------------------------------------------------- programmed path
def programmed_path(lines, offsets):
    """Motion blocks of a translated program, in machine coordinates:
    list of (line_no, kind, start, end, arc) with kind 0 rapid, 1 line, 2 arc;
    arc = (cx, cy, r, a0, sweep) in the XY plane (G17; G18/G19 arcs are refused here)."""
    wcs = {"G54": 1, "G55": 2, "G56": 3, "G57": 4, "G58": 5, "G59": 6, "G59.3": 9}
    table = {9: (0.0, 0.0, 0.0)}
    for g, p in wcs.items():
        if g in offsets:
            o = offsets[g]
            table[p] = (o.get("X", 0.0), o.get("Y", 0.0), o.get("Z", 0.0))
    cur_off = table[9]
    motion, absolute, arc_abs, plane = 1, True, False, 17
    pos = np.zeros(3)             # program coordinates
    blocks = []
    for ln, line in enumerate(lines, 1):
        words = WORD.findall(line)
        if not words:
            continue
        d = {}
        gs = []
        for k, v in words:
            if k == "G":
                gs.append(v)
            else:
                d[k] = float(v)
        gset = set(float(g) for g in gs)
        if 10 in gset or 92.1 in gset:
            if 10 in gset and d.get("L") == 2:
                p = int(d["P"])
                table[p] = (d.get("X", 0.0), d.get("Y", 0.0), d.get("Z", 0.0))
            continue
        new_off = None
        for g in gs:
            gf = float(g)
            if gf in (0, 1, 2, 3):
                motion = int(gf)
            elif gf == 90:
                absolute = True
            elif gf == 91:
                absolute = False
            elif gf == 90.1:
                arc_abs = True
            elif gf == 91.1:
                arc_abs = False
            elif gf in (17, 18, 19):
                plane = int(gf)
            for name, p in wcs.items():
                if abs(gf - float(name[1:])) < 1e-9:
                    new_off = table[p]
        if new_off is not None:
            # LinuxCNC keeps the machine position; the program position changes
            mach = pos + np.array(cur_off)
            cur_off = new_off
            pos = mach - np.array(cur_off)
        if 4 in gset or not any(a in d for a in "XYZ"):
            continue
        start = pos.copy()
        end = pos.copy()
        for i, a in enumerate("XYZ"):
            if a in d:
                end[i] = d[a] if absolute else pos[i] + d[a]
        off = np.array(cur_off)
        arc = None
        kind = {0: 0, 1: 1, 2: 2, 3: 2}[motion]
        if kind == 2:
            if plane != 17:
                raise Refused("line %d: arcs outside G17 are not modelled by the dev_mm check" % ln)
            ccw = motion == 3
            sx, sy, ex, ey = start[0], start[1], end[0], end[1]
            if "R" in d:
                r = abs(d["R"])
                mx, my = (sx + ex) / 2, (sy + ey) / 2
                dx, dy = ex - sx, ey - sy
                half = math.hypot(dx, dy) / 2
                h = math.sqrt(max(r * r - half * half, 0.0))
                ux, uy = dx / (2 * half), dy / (2 * half)
                side = 1.0 if ccw else -1.0          # small arc: centre left of s->e for CCW
                if d["R"] < 0:
                    side = -side
                cx, cy = mx - uy * h * side, my + ux * h * side
            else:
                i_, j_ = d.get("I", 0.0), d.get("J", 0.0)
                cx, cy = (i_, j_) if arc_abs else (sx + i_, sy + j_)
                r = math.hypot(sx - cx, sy - cy)
            a0 = math.atan2(sy - cy, sx - cx)
            a1 = math.atan2(ey - cy, ex - cx)
            if ccw:
                sweep = (a1 - a0) % (2 * math.pi)
                if sweep < 1e-12:
                    sweep = 2 * math.pi
            else:
                sweep = -((a0 - a1) % (2 * math.pi))
                if sweep > -1e-12:
                    sweep = -2 * math.pi
            arc = (cx + off[0], cy + off[1], r, a0, sweep)
        blocks.append((ln, kind, start + off, end + off, arc))
        pos = end
    return blocks


def path_deviation(blocks, xyz, lines_tag):
    """Largest distance of each sample in xyz (N x 3, machine coordinates) from the
    programmed blocks within +-WINDOW blocks of its executing line; returns per-sample d."""
    nb = len(blocks)
    if nb == 0:
        return np.full(len(xyz), np.nan)
    blk_lines = np.array([b[0] for b in blocks])
    S = np.array([b[2] for b in blocks])
    E = np.array([b[3] for b in blocks])
    kind = np.array([b[1] for b in blocks])
    arc = np.array([b[4] if b[4] is not None else (0, 0, 0, 0, 0) for b in blocks], dtype=float)
    base = np.clip(np.searchsorted(blk_lines, lines_tag, side="left"), 0, nb - 1)
    best = np.full(len(xyz), np.inf)
    for k in range(-WINDOW, WINDOW + 1):
        j = np.clip(base + k, 0, nb - 1)
        s, e = S[j], E[j]
        # segment distance (lines and rapids)
        se = e - s
        l2 = np.einsum("ij,ij->i", se, se)
        t = np.where(l2 > 0, np.einsum("ij,ij->i", xyz - s, se) / np.where(l2 > 0, l2, 1), 0.0)
        t = np.clip(t, 0, 1)
        dl = np.linalg.norm(xyz - (s + t[:, None] * se), axis=1)
        # arc distance (XY arc, linear Z)
        cx, cy, r, a0, sw = arc[j].T
        ang = np.arctan2(xyz[:, 1] - cy, xyz[:, 0] - cx)
        rel = np.where(sw >= 0, (ang - a0) % (2 * np.pi), (a0 - ang) % (2 * np.pi))
        inside = rel <= np.abs(sw) + 1e-12
        frac = np.where(np.abs(sw) > 0, rel / np.where(np.abs(sw) > 0, np.abs(sw), 1), 0)
        z = s[:, 2] + frac * (e[:, 2] - s[:, 2])
        rr = np.hypot(xyz[:, 0] - cx, xyz[:, 1] - cy)
        da = np.where(inside, np.hypot(rr - r, xyz[:, 2] - z),
                      np.minimum(np.linalg.norm(xyz - s, axis=1), np.linalg.norm(xyz - e, axis=1)))
        d = np.where(kind[j] == 2, da, dl)
        best = np.minimum(best, d)
    return best


# ---------------------------------------------------------------- one run
def program_source(name):
    if name in CHORD:
        txt = subprocess.run([sys.executable, os.path.join(REPO, "bench", "chord_circle.py"), "--plain",
                              "--decimals", str(CHORD[name])], capture_output=True, text=True, check=True).stdout
        return name, txt.splitlines(True)
    path = name if os.path.exists(name) else os.path.join(REPO, "tests", "programs", name + ".nc")
    if not os.path.exists(path):
        raise Refused("no program %r (names: %s, or a path)" % (name, " ".join(DEFAULT_PROGRAMS)))
    return os.path.splitext(os.path.basename(path))[0], open(path).readlines()


def read_samples(path):
    tags, rows, overrun_lines = [], [], 0
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == "overrun":
            overrun_lines += 1
            continue
        if len(f) != 8:
            continue          # a partial last line
        tags.append(int(f[0]))
        rows.append([float(x) for x in f[1:]])
    return np.array(tags, dtype=np.int64), np.array(rows), overrun_lines


def nobody_uid():
    import pwd
    try:
        return pwd.getpwnam("nobody").pw_uid
    except KeyError:
        return 65534


def run_one(prog, mode, offsets, workdir, timeout, retry=False):
    name, src = program_source(prog)
    out, npre, notes = translate(src, offsets, MODES[mode])
    run = os.path.join(workdir, "%s_%s%s" % (name, mode, "_retry" if retry else ""))
    os.makedirs(run)
    for f in CONFIG_FILES:
        shutil.copy(os.path.join(HERE, f), run)
    os.chmod(os.path.join(run, "headless_ui.py"), 0o755)
    ngc = os.path.join(run, name + ".ngc")
    with open(ngc, "w") as f:
        f.write("\n".join(out) + "\n")
    for nt in notes:
        log("  translate %s: %s" % (name, nt))
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    if os.getuid() == 0:
        # rtapi_app (setuid root) refuses to run for root without a fallback uid; it then
        # works with that uid's file system rights, so its FIFO socket goes to a folder
        # that uid can write (uspace_rtapi_app.cc: RTAPI_UID, RTAPI_FIFO_PATH)
        fifo_dir = os.path.join(run, "rtapi")
        os.makedirs(fifo_dir)
        os.chmod(fifo_dir, 0o777)
        os.chmod(run, 0o755)
        os.chmod(workdir, 0o755)
        env.update(RTAPI_UID=str(nobody_uid()), RTAPI_FIFO_PATH=os.path.join(fifo_dir, "rtapi_fifo"))
    env.update(BENCH_PROGRAM=ngc, BENCH_SAMPLES=os.path.join(run, "samples.txt"),
               BENCH_STATUS=os.path.join(run, "status.json"), BENCH_TIMEOUT=str(timeout))
    t0 = time.time()
    with open(os.path.join(run, "linuxcnc.log"), "w") as lg:
        p = subprocess.run(["/usr/bin/linuxcnc", "-r", os.path.join(run, "xyz_sim.ini")], cwd=run, env=env,
                           stdin=subprocess.DEVNULL, stdout=lg, stderr=subprocess.STDOUT, timeout=timeout + 120)
    wall = time.time() - t0
    status = {}
    if os.path.exists(env["BENCH_STATUS"]):
        status = json.load(open(env["BENCH_STATUS"]))
    if not status.get("ok"):
        tail = open(os.path.join(run, "linuxcnc.log")).read()[-1500:]
        log("  %s %s FAILED (linuxcnc rc %d): %s\n%s" % (name, mode, p.returncode, status.get("errors"), tail))
        return name, None, status, wall
    log_errors = [ln.strip() for ln in open(os.path.join(run, "linuxcnc.log")) if "ERROR" in ln]
    if log_errors:
        status["incomplete"] = "LinuxCNC reported: " + "; ".join(log_errors)[:200]
        log("  %s %s: %s" % (name, mode, status["incomplete"]))
        return name, None, status, wall
    tags, rows, overrun_lines = read_samples(env["BENCH_SAMPLES"])
    lost = int(np.sum(np.diff(tags) - 1)) if len(tags) > 1 else 0
    xyz, vel_pin, line_pin, mtype = rows[:, 0:3], rows[:, 3], rows[:, 4].astype(int), rows[:, 5].astype(int)
    step = np.zeros(len(xyz))
    step[1:] = np.linalg.norm(np.diff(xyz, axis=0), axis=1)
    speed = step / PERIOD_S
    moving = step > 1e-9
    idx = np.nonzero(moving)[0]
    res = {"lost": lost + overrun_lines + (status.get("overruns") or 0)}
    if len(idx) == 0:
        log("  %s %s: no motion sampled" % (name, mode))
        return name, None, status, wall
    res["time_s"] = (idx[-1] - idx[0] + 1) * PERIOD_S
    # the sample numbers (halsampler -t) must be contiguous over the run
    res["contiguous"] = bool(np.all(np.diff(tags[idx[0]:idx[-1] + 1]) == 1))
    feed = moving & ((mtype == 2) | (mtype == 3))
    fs = speed[feed]
    res["samples"] = int(feed.sum())
    res["v_med"] = float(np.median(fs)) if len(fs) else float("nan")
    res["v_p5"] = float(np.percentile(fs, 5)) if len(fs) else float("nan")
    res["rapid_s"] = float((moving & (mtype == 1)).sum() * PERIOD_S)
    res["pin_vel_max_diff"] = float(np.max(np.abs(vel_pin[feed] - fs))) if len(fs) else 0.0
    # the run must have reached the program's end: last sampled position = end of the last
    # programmed motion (LinuxCNC can drop the queue without an error on its error channel)
    try:
        blocks = programmed_path(out, offsets)
    except Refused as ex:
        blocks = None
        log("  end check / dev_mm not computed: %s" % ex)
    if blocks:
        gap = float(np.linalg.norm(xyz[-1] - blocks[-1][3]))
        if gap > 1e-3 or line_pin.max() < blocks[-1][0]:
            status["incomplete"] = ("run ended %.3f mm from the program's last point, last line reached %d of %d"
                                    % (gap, line_pin.max(), blocks[-1][0]))
            log("  %s %s: %s" % (name, mode, status["incomplete"]))
            return name, None, status, wall
    try:
        if blocks is None:
            raise Refused("no programmed path")
        d = path_deviation(blocks, xyz[feed], line_pin[feed])
        res["dev_mm"] = float(np.max(d)) if len(d) else float("nan")
    except Refused as ex:
        log("  dev_mm not computed: %s" % ex)
        res["dev_mm"] = None
    return name, res, status, wall


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("programs", nargs="*", help="program names (%s) or paths of .nc files; default: all"
                    % " ".join(DEFAULT_PROGRAMS))
    ap.add_argument("--modes", default="G61,G64", help="comma list of G61, G64 (default both)")
    ap.add_argument("--timeout", type=float, default=900, help="seconds per run")
    ap.add_argument("--keep", action="store_true", help="keep the temp folder (translated programs, samples, logs)")
    a = ap.parse_args(argv)
    offsets, axes = read_machine(MACHINE_YAML)
    problems = check_ini_limits(os.path.join(HERE, "xyz_sim.ini"), axes)
    if problems:
        for p in problems:
            log("INI does not match config/xyz_machine.yaml: " + p)
        return 2
    log("LinuxCNC reference bench (a reference only, not a dependency of the project)")
    log("limits from %s: %s" % (os.path.relpath(MACHINE_YAML, REPO),
                                ", ".join("%s v_max %g a_max %g" % (k, v["v_max"], v["a_max"]) for k, v in axes.items())))
    progs = a.programs or DEFAULT_PROGRAMS
    modes = [m.strip() for m in a.modes.split(",") if m.strip()]
    for m in modes:
        if m not in MODES:
            log("unknown mode %s (G61, G64)" % m)
            return 2
    workdir = tempfile.mkdtemp(prefix="lcnc_bench_")
    print("program mode time_s v_med v_p5 dev_mm samples", flush=True)
    failures = 0
    t_all = time.time()
    try:
        for prog in progs:
            for mode in modes:
                log("running %s %s ..." % (prog, mode))
                try:
                    name, res, status, wall = run_one(prog, mode, offsets, workdir, a.timeout)
                    if res is None and (status.get("stalled") or status.get("incomplete")):
                        # seen on a heavily loaded host (load 20 on 2 cores): LinuxCNC's task timed out
                        # talking to motion, or motion stopped with a full queue; neither repeated on a rerun
                        log("  %s %s: run stalled or incomplete (%s); running it once more"
                            % (name, mode, status.get("stalled") or status.get("incomplete")))
                        name, res, status, wall = run_one(prog, mode, offsets, workdir, a.timeout, retry=True)
                except Refused as ex:
                    log("  %s: refused by the translator: %s" % (prog, ex))
                    print("%s %s - - - - -   # not translated" % (os.path.basename(prog), mode), flush=True)
                    failures += 1
                    continue
                if res is None:
                    why = "LinuxCNC run failed"
                    if status.get("stalled"):
                        st = status["stalled"]
                        why = ("LinuxCNC planner stalled at line %d of the translated program after %.0f s "
                               "(queue %d, no error)" % (st["current_line"], st["after_s"], st["queue"]))
                    elif status.get("incomplete"):
                        why = "LinuxCNC run incomplete: " + status["incomplete"]
                    elif status.get("errors"):
                        why += ": " + "; ".join(status["errors"])[:200]
                    print("%s %s - - - - -   # %s" % (name, mode, why), flush=True)
                    failures += 1
                    continue
                dev = "-" if res["dev_mm"] is None else "%.4f" % res["dev_mm"]
                note = ""
                if res["lost"] or not res["contiguous"]:
                    note = "   # %d samples lost (sampler overrun): time_s not exact" % res["lost"]
                print("%s %s %.3f %.2f %.2f %s %d%s" % (name, mode, res["time_s"], res["v_med"], res["v_p5"],
                                                        dev, res["samples"], note), flush=True)
                log("  %s %s: wall %.1f s, rapid %.3f s, |current-vel pin - sampled speed| max %.3g mm/s"
                    % (name, mode, wall, res["rapid_s"], res["pin_vel_max_diff"]))
    finally:
        if a.keep:
            log("kept " + workdir)
        else:
            shutil.rmtree(workdir, ignore_errors=True)
    log("wall time %.1f s" % (time.time() - t_all))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
