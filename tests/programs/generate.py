#!/usr/bin/env python3
"""Generate and check the NC test corpus in tests/programs/ (TwinCAT 3 CNC / TF5200 dialect).

    python3 tests/programs/generate.py           # write every <name>.nc, then check them
    python3 tests/programs/generate.py --check   # only check the .nc files in this folder

Only the standard library is used. The check reads the written text back,
on its own (it does not trust the generator's state): the words and G/M
codes of the rig's dialect, N numbers increasing, G04 and G92 alone, at
most one block transition G function per block, arc end radius within
0.01 mm of the start radius (R arcs: chord <= 2|R|), feeds 100..6000 mm/min,
every position (arcs sampled) inside the machine's range X 0..600, Y 0..400,
Z -80..150 for every combination of skip levels, M30 at the end. It also
estimates the motion time: feed moves at their programmed F, rapids at the
axes' G00 velocity of config/xyz_machine.yaml (X Y 250 mm/s, Z 150 mm/s),
dwells at their time.

Semantics the check assumes (as in cnc/decoder/line_decoder.cpp and the
TF5200 manual): the program starts at machine X0 Y0 Z0 without a zero
offset; G54 = X100 Y50 Z-20 and G55 = X300 Y50 Z-20 (config/xyz_machine.yaml
zero_offsets); a bare / is skip level 1, as /1; G53 (modal) suppresses
the zero offset; G92 is the additive reference point offset (G90 sets it,
G91 adds to it, nothing moves); G162 (centre I J K relative to the start);
G70 scales lengths and F by 25.4.
"""
import itertools
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ZERO_OFFSETS = {54: (100.0, 50.0, -20.0), 55: (300.0, 50.0, -20.0)}
LIMITS = {'X': (0.0, 600.0), 'Y': (0.0, 400.0), 'Z': (-80.0, 150.0)}
V_RAPID = {'X': 250.0, 'Y': 250.0, 'Z': 150.0}  # mm/s, config/xyz_machine.yaml
MACHINE = ('config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on '
           'config/xyzc_machine.yaml, C not programmed)')

# ----------------------------------------------------------------------------
# number formats of the post styles


def f_strip(v, nd, lead_zero=True):
    """CAM style: nd decimals, trailing zeros dropped; lead_zero=False gives .5 / -.25."""
    s = f"{v:.{nd}f}"
    if '.' in s:
        s = s.rstrip('0').rstrip('.')
    if s in ('-0', '', '-'):
        s = '0'
    if not lead_zero:
        if s.startswith('0.'):
            s = s[1:]
        elif s.startswith('-0.'):
            s = '-' + s[2:]
    return s


def f_fixed(v, nd):
    s = f"{v:.{nd}f}"
    if float(s) == 0.0:
        s = f"{0.0:.{nd}f}"
    return s


def fusion(v):
    return f_strip(v, 3)


def mastercam(v):
    return f_strip(v, 4, lead_zero=False)


def solidcam(v):
    return f_fixed(v, 3)


def fixed4(v):
    return f_fixed(v, 4)


def handwritten(v):
    return f_strip(v, 3)


PLANE_AXES = {17: ('X', 'Y'), 18: ('Z', 'X'), 19: ('Y', 'Z')}
CENTRE_WORD = {'X': 'I', 'Y': 'J', 'Z': 'K'}


class Program:
    """A post: block numbers, modal words suppressed as posts do, rounded positions tracked."""

    def __init__(self, fmt, n_start=10, n_step=10, n_format='N{}', numbered=True, g_two_digits=True,
                 omit_zero_centre=False, feed_fmt=None, scale=1.0):
        self.fmt = fmt
        self.n = n_start
        self.n_step = n_step
        self.n_format = n_format
        self.numbered = numbered
        self.g2 = g_two_digits
        self.omit_zero_centre = omit_zero_centre
        self.feed_fmt = feed_fmt or (lambda f: f_strip(f, 1))
        self.lines = []
        self.pos = {'X': 0.0, 'Y': 0.0, 'Z': 0.0}  # program coordinates as written (rounded)
        self.plane = 17
        self.forget()

    def forget(self):
        """After skippable blocks or unit changes: write every word again."""
        self.modal_g = None
        self.last = {}
        self.last_f = None

    def g(self, n):
        return f"G{n:02d}" if self.g2 else f"G{n}"

    def line(self, text):
        self.lines.append(text)

    def block(self, text, skip=None, numbered=None):
        num = self.numbered if numbered is None else numbered
        s = text
        if num:
            s = self.n_format.format(self.n) + (' ' + text if text else '')
            self.n += self.n_step
        if skip is not None:
            s = (skip + s) if skip == '/' else (skip + ' ' + s)
        self.lines.append(s)

    def set_pos(self, **w):
        """After a block the generator wrote by hand (e.g. G92): where the program stands."""
        for a, v in w.items():
            self.pos[a] = v
            self.last.pop(a, None)

    def move(self, g, pre=(), post=(), comment=None, skip=None, force=(), X=None, Y=None, Z=None, F=None,
             centre=None, R=None):
        parts = list(pre)
        prev_g = self.modal_g
        if g != self.modal_g or 'G' in force:
            parts.append(self.g(g))
            self.modal_g = g
        arc = g in (2, 3)
        plane_axes = PLANE_AXES[self.plane]
        target = dict(self.pos)
        for a, v in (('X', X), ('Y', Y), ('Z', Z)):
            if v is None:
                continue
            s = self.fmt(v)
            target[a] = float(s)
            if s != self.last.get(a) or a in force or (arc and a in plane_axes):
                parts.append(a + s)
                self.last[a] = s
        if arc:
            if R is not None:
                parts.append('R' + self.fmt(R))
            else:
                for a in plane_axes:
                    off = centre[a] - self.pos[a]
                    s = self.fmt(off)
                    if self.omit_zero_centre and float(s) == 0.0:
                        continue
                    parts.append(CENTRE_WORD[a] + s)
                if self.omit_zero_centre and not any(p[0] in 'IJK' for p in parts):
                    parts.append(CENTRE_WORD[plane_axes[0]] + self.fmt(0.0))
        if F is not None:
            fs = self.feed_fmt(F)
            if fs != self.last_f:
                parts.append('F' + fs)
                self.last_f = fs
        parts += list(post)
        words = [p for p in parts if not re.fullmatch(r'G0?[0-3]', p)]
        if not words:  # nothing moves and nothing is said: a post writes no block
            self.modal_g = prev_g
            return
        text = ' '.join(parts)
        if comment:
            text += f" ({comment})"
        self.block(text, skip)
        self.pos = target

    def rapid(self, **kw):
        self.move(0, **kw)

    def lin(self, **kw):
        self.move(1, **kw)


def header(name, what, style, origin, extra=()):
    rule = '; ' + '-' * 74
    out = [rule, f'; {name}.nc', ';']
    for label, text in (('What', what), ('Style', style), ('Origin', origin), ('Machine', MACHINE)):
        out += wrap(label, text)
    out += wrap('Offsets', 'zero offsets of the machine file (zero_offsets): G54 = X100 Y50 Z-20, '
                           'G55 = X300 Y50 Z-20 (machine = program + offset)')
    for label, text in extra:
        out += wrap(label, text)
    out += [rule]
    return out


def wrap(label, text, width=78):
    words = text.split()
    lines, cur = [], f'; {label + ":":9s}'
    for w in words:
        if len(cur) + 1 + len(w) > width:
            lines.append(cur.rstrip())
            cur = '; ' + ' ' * 9 + w
        else:
            cur += ('' if cur.endswith(' ') else ' ') + w
    lines.append(cur.rstrip())
    return lines


ORIGIN = 'written for this project in the style of {}, 2026'


# ----------------------------------------------------------------------------
# 1. contour_2d_arcs.nc -- Fusion 360-like 2D contour


def p_contour_2d_arcs():
    P = Program(fusion, n_start=10, n_step=5)
    P.line('(T1  D=10 CR=0 - ZMIN=-5 - FLAT END MILL)')
    P.block('G90 G94 G17')
    P.block('G71')
    P.line('(2D CONTOUR1)')
    P.block('T1 M06')
    P.block('D1')
    P.block('S12000 M03')
    P.block('G54')
    P.block('M08')
    # tool centre path of a 60 x 40 plate (corner R8) with an R12 notch in the top edge, D10 tool outside
    contour = [
        ('L', -5, 32),
        ('A', 2, 8, 45, (8, 32)),
        ('L', 18, 45),
        ('A', 2, 23, 40, (18, 40)),
        ('A', 3, 37, 40, (30, 40)),
        ('A', 2, 42, 45, (42, 40)),
        ('L', 52, 45),
        ('A', 2, 65, 32, (52, 32)),
        ('L', 65, 8),
        ('A', 2, 52, -5, (52, 8)),
        ('L', 8, -5),
        ('A', 2, -5, 8, (8, 8)),
        ('L', -5, 20),
    ]
    for k, depth in enumerate((-2.5, -5.0)):
        P.rapid(X=-10, Y=10)
        if k == 0:
            P.rapid(Z=15)
        P.rapid(Z=5)
        P.lin(Z=1, F=1000)
        P.lin(Z=depth, F=300)
        P.lin(Y=15, F=2500)
        P.move(3, X=-5, Y=20, centre={'X': -10, 'Y': 20})  # lead-in arc R5
        for seg in contour:
            if seg[0] == 'L':
                P.lin(X=seg[1], Y=seg[2])
            else:
                P.move(seg[1], X=seg[2], Y=seg[3], centre={'X': seg[4][0], 'Y': seg[4][1]})
        P.move(3, X=-10, Y=25, centre={'X': -10, 'Y': 20})  # lead-out arc R5
        P.lin(Y=30)
        P.rapid(Z=5 if k == 0 else 15)
    P.block('M09')
    P.block('M05')
    P.rapid(Z=100)
    P.rapid(X=0, Y=80)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 2. pocket_helix_ramp.nc -- Mastercam-like circular pocket


def p_pocket_helix_ramp():
    P = Program(mastercam, n_start=100, n_step=2, omit_zero_centre=True, feed_fmt=lambda f: f_strip(f, 1, False))
    cx, cy = 52.5, 37.25
    P.line('(PROGRAM NAME - POCKET_HELIX_RAMP)')
    P.line('(DATE=DD-MM-YY - 12-03-26 TIME=HH:MM - 09:41)')
    P.line('(MCAM FILE - BRACKET_BORE)')
    P.line('(NC FILE - POCKET_HELIX_RAMP.NC)')
    P.line('(MATERIAL - ALUMINUM MM - 6061)')
    P.line('( T2 |  8MM FLAT ENDMILL | H2 | D2 )')
    P.block('G71 G00 G17 G40 G90 G94')
    P.block('T2 M06')
    P.rapid(pre=['G90', 'G54'], X=cx + 4, Y=cy, post=['S9500', 'M03'])
    P.rapid(pre=['D2'], Z=25, post=['M08'])
    P.rapid(Z=3)
    P.lin(Z=.5, F=250)
    for z in (-1.0, -2.5, -4.0):  # helical ramp, R4, pitch 1.5, one full turn per block
        P.move(3, X=cx + 4, Y=cy, Z=z, centre={'X': cx, 'Y': cy}, F=900)
    P.move(3, X=cx + 4, Y=cy, centre={'X': cx, 'Y': cy}, F=1500)  # flat turn at depth
    r, d, side = 4.0, 1.75, 1
    while r < 12.75 - 1e-9:  # spiral out: half circles with alternating centres
        start_x = cx + side * r
        end_x = cx - side * (r + d)
        P.move(3, X=end_x, Y=cy, centre={'X': (start_x + end_x) / 2, 'Y': cy})
        r += d
        side = -side
    P.move(3, X=P.pos['X'], Y=cy, centre={'X': cx, 'Y': cy}, comment='FINISH WALL')
    P.lin(X=cx)
    P.rapid(Z=25)
    P.block('M09')
    P.block('M05')
    P.rapid(X=0, Y=100)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 3. radius_arcs.nc -- SolidCAM-like profile programmed with R arcs


def unit(vx, vy):
    n = math.hypot(vx, vy)
    return vx / n, vy / n


def p_radius_arcs():
    P = Program(solidcam, n_start=1, n_step=1, feed_fmt=lambda f: f_strip(f, 0))
    P.line('(SOLIDCAM - LEVER_PLATE.PRZ)')
    P.line('(TOOL 3 - EM D8.000 - FLUTES 3 - H3 D3)')
    P.block('G71 G90 G17 G40 G94')
    P.block('G54')
    P.block('T3 M06')
    P.block('D3')
    P.block('S8000 M03')
    P.block('M08')
    c1, r1 = (40.0, 60.0), 22.0
    c2, r2 = (110.0, 75.0), 12.0

    # --- inner cut-out: rounded triangle in boss 1 (corners R3 tool path), climb CCW, G03 R
    P.line('(-----CONTOUR - F_TRI_CUTOUT-----)')
    corners = [(c1[0] + 6 * math.cos(math.radians(a)), c1[1] + 6 * math.sin(math.radians(a))) for a in (90, 210, 330)]
    rc = 3.0
    normals = []
    for k in range(3):
        a, b = corners[k], corners[(k + 1) % 3]
        ux, uy = unit(b[0] - a[0], b[1] - a[1])
        normals.append((uy, -ux))  # right of CCW travel = outward
    n0 = normals[0]
    v0, v1 = corners[0], corners[1]
    m = ((v0[0] + v1[0]) / 2 + rc * n0[0], (v0[1] + v1[1]) / 2 + rc * n0[1])
    rl = 2.5
    o = (m[0] - rl * n0[0], m[1] - rl * n0[1])
    th_m = math.atan2(n0[1], n0[0])
    s = (o[0] + rl * math.cos(th_m - math.pi / 2), o[1] + rl * math.sin(th_m - math.pi / 2))
    e = (o[0] + rl * math.cos(th_m + math.pi / 2), o[1] + rl * math.sin(th_m + math.pi / 2))
    P.rapid(X=c1[0], Y=c1[1], comment='PRE-DRILLED D10')
    P.rapid(Z=25)
    P.rapid(Z=2)
    P.lin(Z=-6, F=300)
    P.lin(X=s[0], Y=s[1], F=1200)
    P.move(3, X=m[0], Y=m[1], R=rl)
    for k in range(3):
        nxt = (k + 1) % 3
        v = corners[nxt]
        n_in, n_out = normals[k], normals[nxt]
        P.lin(X=v[0] + rc * n_in[0], Y=v[1] + rc * n_in[1])
        P.move(3, X=v[0] + rc * n_out[0], Y=v[1] + rc * n_out[1], R=rc)
    P.lin(X=m[0], Y=m[1])
    P.move(3, X=e[0], Y=e[1], R=rl)
    P.lin(X=c1[0], Y=c1[1])
    P.rapid(Z=2)

    # --- outer profile: two bosses joined by tangents, climb CW, G02 R- round boss 1 (> 180 deg)
    P.line('(-----CONTOUR - F_OUTER_PROFILE-----)')
    dx, dy = c2[0] - c1[0], c2[1] - c1[1]
    dist = math.hypot(dx, dy)
    phi = math.atan2(dy, dx)
    alpha = math.acos((r1 - r2) / dist)
    up, lo = phi + alpha, phi - alpha

    def on(c, r, ang):
        return c[0] + r * math.cos(ang), c[1] + r * math.sin(ang)

    c1_up, c2_up = on(c1, r1, up), on(c2, r2, up)
    c1_lo, c2_lo = on(c1, r1, lo), on(c2, r2, lo)
    mx, my = (c1_lo[0] + c2_lo[0]) / 2, (c1_lo[1] + c2_lo[1]) / 2
    ux, uy = unit(c1_lo[0] - c2_lo[0], c1_lo[1] - c2_lo[1])  # travel along the lower tangent, towards boss 1
    nlx, nly = -uy, ux  # left of travel = outside
    rl = 5.0
    o = (mx + rl * nlx, my + rl * nly)
    th_m = math.atan2(-nly, -nlx)
    s = on(o, rl, th_m - math.pi / 2)
    e = on(o, rl, th_m + math.pi / 2)
    ts = (-math.sin(th_m - math.pi / 2), math.cos(th_m - math.pi / 2))
    start = (s[0] - 6 * ts[0], s[1] - 6 * ts[1])
    for k, depth in enumerate((-3.0, -6.0)):
        P.rapid(X=start[0], Y=start[1])
        P.rapid(Z=1)
        P.lin(Z=depth, F=600)
        P.lin(X=s[0], Y=s[1], F=2800)
        P.move(3, X=mx, Y=my, R=rl)
        P.lin(X=c1_lo[0], Y=c1_lo[1])
        P.move(2, X=c1_up[0], Y=c1_up[1], R=-r1)
        P.lin(X=c2_up[0], Y=c2_up[1])
        P.move(2, X=c2_lo[0], Y=c2_lo[1], R=r2)
        P.lin(X=mx, Y=my)
        P.move(3, X=e[0], Y=e[1], R=rl)
        P.rapid(Z=2 if k == 0 else 25)
    P.block('M09')
    P.block('M05')
    P.rapid(X=0, Y=150)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 4. planes_g18_g19.nc -- hand-written, arcs in G18 (Z-X) and G19 (Y-Z)


def p_planes_g18_g19():
    P = Program(handwritten, n_start=10, n_step=10, omit_zero_centre=True, feed_fmt=lambda f: f_strip(f, 0))
    P.line('; part 60 x 40 x 20, top Z0, zero: front left top corner (G54)')
    P.line('; T5 ball nose D6 - D5 holds the length to the ball CENTRE: programmed points = ball centre')
    P.block('G90 G71 G17 G40 G94 G162')
    P.block('G54')
    P.block('T5 M06')
    P.block('D5')
    P.block('S9000 M03')
    P.block('M08')
    P.line('; --- cove R10 across X 12..28, 4 deep, along Y: G18, ball centre on R7 around X20 Z6')
    cxz = (20.0, 6.0)  # centre (X, Z)
    rr = 7.0
    zs = 3.0  # ball centre on the top face
    half = math.sqrt(rr * rr - (cxz[1] - zs) ** 2)
    xa, xb = cxz[0] - half, cxz[0] + half
    P.rapid(X=xa, Y=6)
    P.rapid(Z=10)
    P.block('G18', numbered=True)
    P.plane = 18
    P.rapid(Z=zs + 2)
    ys = [6 + 4 * k for k in range(8)]
    at_a = True
    for k, y in enumerate(ys):
        if k > 0:
            P.rapid(Z=zs + 2)
            P.rapid(Y=y)
        P.lin(Z=zs, F=600)
        if at_a:
            P.move(2, X=xb, Z=zs, centre={'X': cxz[0], 'Z': cxz[1]}, F=1200)
        else:
            P.move(3, X=xa, Z=zs, centre={'X': cxz[0], 'Z': cxz[1]}, F=1200)
        at_a = not at_a
    P.rapid(Z=10)
    P.line('; --- round-over R5 on the front top edge (Y0 Z0), G19: ball centre on R8 around Y5 Z-5')
    P.block('G19')
    P.plane = 19
    cyz = (5.0, -5.0)
    P.rapid(X=4, Y=-8)
    P.rapid(Z=-5)
    at_face = True
    for k, x in enumerate((4, 16, 28, 40, 52)):
        if k > 0 and at_face:
            P.rapid(X=x)
        elif k > 0:
            P.rapid(Z=6)
            P.rapid(X=x)
            P.lin(Z=3, F=600)
        if at_face:
            P.lin(Y=-3, F=600)
            P.move(2, Y=5, Z=3, centre={'Y': cyz[0], 'Z': cyz[1]}, F=1200)
        else:
            P.move(3, Y=-3, Z=-5, centre={'Y': cyz[0], 'Z': cyz[1]}, F=1200)
            P.lin(Y=-8, F=1500)
        at_face = not at_face
    P.rapid(Z=10)
    P.line('; --- back to G17: R6 ring 0.5 deep round the mark at X47 Y28')
    P.block('G17')
    P.plane = 17
    P.rapid(X=53, Y=28)
    P.rapid(Z=5)
    P.lin(Z=2.5, F=300)  # ball centre 0.5 below the top face
    P.move(3, X=53, Y=28, centre={'X': 47, 'Y': 28}, F=1000)
    P.rapid(Z=50)
    P.block('M09')
    P.block('M05')
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 5. surfacing_3d.nc -- PowerMill-like raster finishing over a gentle bump


def p_surfacing_3d():
    P = Program(fixed4, numbered=False, feed_fmt=lambda f: f_strip(f, 1))
    h, sig, xc, yc, rb = 2.5, 6.0, 25.0, 17.0, 3.0

    def tip(x, y):
        ex = math.exp(-((x - xc) ** 2 + (y - yc) ** 2) / (2 * sig * sig))
        z = h * ex
        gx = -z * (x - xc) / (sig * sig)
        gy = -z * (y - yc) / (sig * sig)
        nn = math.sqrt(gx * gx + gy * gy + 1)
        return x - rb * gx / nn, y - rb * gy / nn, z + rb / nn - rb

    P.line('(PowerMill raster finishing - BUMP_PATCH)')
    P.line('(Tool: BN6 - ball nose D6 - tip programmed - tolerance 0.002)')
    P.line('(Patch X10..X40 Y5..Y29 - stepover 0.8 - point spacing 0.5 - thickness 0)')
    P.block('G90 G71 G17 G40 G94')
    P.block('G54')
    P.block('T6 M06')
    P.block('D6')
    P.block('S14000 M03')
    P.block('M07 (MIST)')
    xs = [10 + 0.5 * k for k in range(61)]
    ys = [5 + 0.8 * k for k in range(31)]
    x0, y0, z0 = tip(xs[0], ys[0])
    P.rapid(X=x0, Y=y0)
    P.rapid(Z=10)
    P.rapid(Z=z0 + 2)
    P.lin(Z=z0, F=800)
    first = True
    for k, y in enumerate(ys):
        row = xs if k % 2 == 0 else xs[::-1]
        for j, x in enumerate(row):
            if first:
                first = False
                continue
            px, py, pz = tip(x, y)
            P.lin(X=px, Y=py, Z=pz, F=3000)
    P.rapid(Z=10)
    P.rapid(Z=50)
    P.block('M09')
    P.block('M05')
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 6. engraving.nc -- VCarve-like text engraving, machine coordinates (no G54)


def p_engraving():
    P = Program(lambda v: f_fixed(v, 3), numbered=False, g_two_digits=False, feed_fmt=lambda f: f_fixed(f, 1))
    P.line('( Toolpath: ENGRAVE TEXT 1 - "TC3 CNC" + frame )')
    P.line('( Tool: V-bit 60 deg, tip 0.2 mm - depth 0.3 mm )')
    P.line('( Material: 80 x 30 x 6 mm acrylic, zero at machine X0 Y0, top face Z0 - no work offset )')
    P.block('G0 G17 G71 G90 G94 G40')
    P.block('T1 M06')
    P.block('S18000 M03')
    P.rapid(Z=5)
    depth, safe = -0.3, 1.0

    def ellipse(cx, cy, rx, ry, a0, a1, step):
        n = int(round(abs(a1 - a0) / step))
        return [(cx + rx * math.cos(math.radians(a0 + (a1 - a0) * i / n)),
                 cy + ry * math.sin(math.radians(a0 + (a1 - a0) * i / n))) for i in range(n + 1)]

    def stroke(pts, flags=None):
        """flags[i]: transition word for the block that ends at pts[i] (None, 'G60' or 'G61')."""
        P.rapid(X=pts[0][0], Y=pts[0][1])
        P.rapid(Z=safe)
        P.lin(Z=depth, F=300)
        for i, (x, y) in enumerate(pts[1:], start=1):
            pre = [flags[i]] if flags and flags[i] else []
            P.lin(pre=pre, X=x, Y=y, F=1500)
        P.rapid(Z=safe)

    def curved(pts, cusps=()):
        flags = ['G61'] * len(pts)
        flags[-1] = None
        for i in cusps:
            flags[i] = 'G60'
        return flags

    P.line('( frame )')
    frame = [(2, 2), (62, 2), (62, 20), (2, 20), (2, 2)]
    stroke(frame, [None, 'G60', 'G60', 'G60', None])
    y0 = 6.0
    letters = []
    for i, ch in enumerate('TC3 CNC'):
        x0 = 5.0 + 8.0 * i
        if ch == 'T':
            letters.append((ch, [[(x0, y0 + 10), (x0 + 6, y0 + 10)], [(x0 + 3, y0 + 10), (x0 + 3, y0)]], None))
        elif ch == 'C':
            pts = ellipse(x0 + 3, y0 + 5, 3, 5, 45, 315, 7.5)
            letters.append((ch, [pts], [curved(pts)]))
        elif ch == '3':
            up = ellipse(x0 + 3, y0 + 7.5, 2.5, 2.5, 150, -90, 10)
            lo = ellipse(x0 + 3, y0 + 2.5, 2.5, 2.5, 90, -150, 10)
            pts = up + lo[1:]
            letters.append((ch, [pts], [curved(pts, cusps=(len(up) - 1,))]))
        elif ch == 'N':
            pts = [(x0, y0), (x0, y0 + 10), (x0 + 6, y0), (x0 + 6, y0 + 10)]
            letters.append((ch, [pts], [[None, 'G60', 'G60', None]]))
    for ch, strokes, flags in letters:
        P.line(f'( letter {ch} )')
        for k, pts in enumerate(strokes):
            stroke(pts, flags[k] if flags else None)
    P.rapid(Z=5)
    P.block('M05')
    P.rapid(X=0, Y=0)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 7. plasma_profile.nc -- SheetCam-like plasma post, no Z motion


def p_plasma_profile():
    P = Program(fusion, n_start=10, n_step=10, n_format='N{:04d}', feed_fmt=lambda f: f_strip(f, 0))
    P.line('(Filename: plasma_profile.tap)')
    P.line('(Post processor: TwinCAT plasma THC - H1/H2 torch, H10/H11 THC, M08/M09 extraction)')
    P.line('(Material: mild steel 3 mm - 45 A - kerf 1.6 - cut F2800)')
    P.line('(Part: FLANGE_100x80 with R30 saddle, 2 holes D16)')
    P.block('G71')
    P.block('G90 G94 G40 G17')
    P.block('G54')
    P.block('M08')
    kerf = 0.8  # half kerf

    def cut_on():
        P.block('H1', numbered=True)
        P.block('G04 X0.3')
        P.block('H10')

    def cut_off():
        P.block('H11')
        P.block('H2')

    for hx in (25.0, 75.0):
        r = 8.0 - kerf
        P.line(f'(Process: plasma inside offset - hole at X{f_strip(hx, 1)} Y40)')
        P.rapid(X=hx + r - 3.5, Y=40 - 3.5)
        cut_on()
        P.move(3, X=hx + r, Y=40, centre={'X': hx + r - 3.5, 'Y': 40}, F=1600)
        P.move(3, X=hx + r, Y=40, centre={'X': hx, 'Y': 40}, F=2000)
        P.move(3, X=hx + r * math.cos(math.radians(20)), Y=40 + r * math.sin(math.radians(20)),
               centre={'X': hx, 'Y': 40}, comment='overburn')
        cut_off()
    P.line('(Process: plasma outside offset - profile)')
    rc = 8.0 + kerf
    C = (50.0, 80.0 + math.sqrt(30 ** 2 - 20 ** 2))
    rs = 30.0 - kerf

    def toward_c(p):
        ux, uy = unit(C[0] - p[0], C[1] - p[1])
        return p[0] + kerf * ux, p[1] + kerf * uy

    q1, q2 = toward_c((30.0, 80.0)), toward_c((70.0, 80.0))
    P.rapid(X=-kerf - 5, Y=35)
    cut_on()
    P.move(3, X=-kerf, Y=40, centre={'X': -kerf - 5, 'Y': 40}, F=2000)
    P.lin(Y=72, F=2800)
    path = [
        ('A', 2, 8, 80 + kerf, (8, 72)),
        ('L', 30, 80 + kerf),
        ('A', 2, q1[0], q1[1], (30, 80)),
        ('A', 3, q2[0], q2[1], C),
        ('A', 2, 70, 80 + kerf, (70, 80)),
        ('L', 92, 80 + kerf),
        ('A', 2, 100 + kerf, 72, (92, 72)),
        ('L', 100 + kerf, 8),
        ('A', 2, 92, -kerf, (92, 8)),
        ('L', 8, -kerf),
        ('A', 2, -kerf, 8, (8, 8)),
        ('L', -kerf, 41, 'overburn'),
    ]
    for seg in path:
        if seg[0] == 'L':
            P.lin(X=seg[1], Y=seg[2], comment=seg[3] if len(seg) > 3 else None)
        else:
            P.move(seg[1], X=seg[2], Y=seg[3], centre={'X': seg[4][0], 'Y': seg[4][1]})
    cut_off()
    P.block('M09')
    P.rapid(X=0, Y=150)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 8. drilling_manual.nc -- drilling written out long-hand (no canned cycles), G54 and G55


def p_drilling_manual():
    P = Program(fusion, n_start=10, n_step=10, feed_fmt=lambda f: f_strip(f, 0))
    P.line('(PLATE A in G54: 4 holes D6.8 on a 40 x 20 rectangle)')
    P.line('(PLATE B in G55: 4 holes D6.8 on PCD 40 at 45 deg)')
    P.line('(drill cycles output long-hand: G00 positioning - G01 feed - G04 dwell - G00 retract)')
    P.block('G90 G71 G17 G40 G94')
    holes_a = [(10.0, 10.0), (50.0, 10.0), (50.0, 30.0), (10.0, 30.0)]
    holes_b = [(30 + 20 * math.cos(math.radians(a)), 30 + 20 * math.sin(math.radians(a))) for a in (45, 135, 225, 315)]

    def spot(x, y):
        P.rapid(X=x, Y=y)
        P.rapid(Z=2)
        P.lin(Z=-1.5, F=500)
        P.block('G04 X0.3')
        P.rapid(Z=2)

    def drill(x, y):
        P.rapid(X=x, Y=y)
        P.rapid(Z=2)
        P.lin(Z=-3, F=600)
        P.rapid(Z=1, comment='chip break')
        P.rapid(Z=-2.5)
        P.lin(Z=-6.5, F=600)
        P.block('G04 X0.2')
        P.rapid(Z=2)

    P.line('(T11 NC SPOT DRILL D10 90 DEG)')
    P.block('T11 M06')
    P.block('D11')
    P.block('S4000 M03')
    P.block('M08')
    P.block('G54')
    P.rapid(X=holes_a[0][0], Y=holes_a[0][1])
    P.rapid(Z=25)
    for x, y in holes_a:
        spot(x, y)
    P.rapid(Z=25)
    P.block('G55')
    P.forget()
    for x, y in holes_b:
        spot(x, y)
    P.rapid(Z=50)
    P.block('M09')
    P.block('M05')
    P.line('(T12 DRILL D6.8 HSS-E)')
    P.block('T12 M06')
    P.block('D12')
    P.block('S2800 M03')
    P.block('M08')
    P.rapid(X=holes_b[-1][0], Y=holes_b[-1][1])
    P.rapid(Z=25)
    for x, y in reversed(holes_b):
        drill(x, y)
    P.rapid(Z=25)
    P.block('G54')
    P.forget()
    for x, y in reversed(holes_a):
        drill(x, y)
    P.rapid(Z=50)
    P.block('M09')
    P.block('M05')
    P.line('(machine coordinates: G53 suppresses the zero offset)')
    P.rapid(pre=['G53'], Z=0, force=('G', 'Z'))
    P.forget()
    P.rapid(X=10, Y=10)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 9. inch_program.nc -- Mastercam-like inch output (G70), back to G71 at the end


def p_inch_program():
    P = Program(mastercam, n_start=100, n_step=2, omit_zero_centre=True, feed_fmt=lambda f: f_strip(f, 1, False))
    P.line('(PROGRAM NAME - INCH_PROGRAM)')
    P.line('(DATE=DD-MM-YY - 02-03-26 TIME=HH:MM - 14:05)')
    P.line('(MATERIAL - ALUMINUM INCH - 6061)')
    P.line('( T7 |  0.25 IN FLAT ENDMILL | H7 | D7 )')
    P.line('(STOCK - 2.0 X 1.5 X .5 - ZERO LOWER LEFT TOP)')
    P.block('G70 G00 G17 G40 G90 G94')
    P.block('T7 M06')
    P.rapid(pre=['G90', 'G54'], X=-.5, Y=-.25, post=['S10000', 'M03'])
    P.rapid(pre=['D7'], Z=1, post=['M08'])
    P.rapid(Z=.1)
    P.lin(Z=-.15, F=20)
    P.lin(X=-.125, F=80)  # onto the left edge, CW profile; corners R.375 (part R.25 + tool R.125)
    P.lin(Y=1.25)
    P.move(2, X=.25, Y=1.625, centre={'X': .25, 'Y': 1.25})
    P.lin(X=1.75)
    P.move(2, X=2.125, Y=1.25, centre={'X': 1.75, 'Y': 1.25})
    P.lin(Y=.25)
    P.move(2, X=1.75, Y=-.125, centre={'X': 1.75, 'Y': .25})
    P.lin(X=.25)
    P.move(2, X=-.125, Y=.25, centre={'X': .25, 'Y': .25})
    P.lin(Y=.5)
    P.lin(X=-.375)
    P.rapid(Z=.1)
    P.line('(BORE D.75 AT X1. Y.75 - PRE-DRILLED)')
    bx, by, br = 1.0, .75, .25
    sx, sy = bx + br * math.cos(math.radians(30)), by + br * math.sin(math.radians(30))
    P.rapid(X=bx, Y=by)
    P.lin(Z=-.25, F=20)
    P.lin(X=sx, Y=sy, F=40)
    P.move(3, X=sx, Y=sy, centre={'X': bx, 'Y': by})
    P.lin(X=bx, Y=by)
    P.rapid(Z=1)
    P.block('M09')
    P.block('M05')
    P.line('(BACK TO METRIC FOR THE PARK POSITION)')
    P.block('G71')
    P.forget()
    P.rapid(Z=50)
    P.rapid(X=0, Y=100)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 10. block_skip.nc -- hand-written, optional blocks / /1 /2


def p_block_skip():
    P = Program(handwritten, n_start=10, n_step=10, feed_fmt=lambda f: f_strip(f, 0))
    P.line('; face 40 x 20 at Z-1 with an end mill D12, then options:')
    P.line(';   skip level 1 (/ and /1): roughing only - no M01 measuring stop, no finishing pass at Z-1.2')
    P.line(';   skip level 2 (/2):       no spring pass round the stock walls at Z-3')
    P.block('G90 G71 G17 G40 G94')
    P.block('G54')
    P.block('T6 M06')
    P.block('D6')
    P.block('S6000 M03')
    P.block('M08')
    P.line('; roughing the face')
    P.rapid(X=-8, Y=4)
    P.rapid(Z=5)
    P.lin(Z=-1, F=600)
    for k, y in enumerate((4, 12, 20)):
        if k:
            P.lin(Y=y)
        P.lin(X=48 if k % 2 == 0 else -8, F=2400)
    P.rapid(Z=5)
    P.line('; optional stop: measure the face depth')
    P.block('M01', skip='/')
    P.line('; optional finishing pass')
    P.forget()
    for kw in (dict(g=0, X=-8, Y=4), dict(g=1, Z=-1.2, F=600), dict(g=1, X=48, F=2000), dict(g=1, Y=20),
               dict(g=1, X=-8), dict(g=0, Z=5)):
        g = kw.pop('g')
        P.move(g, skip='/1', **kw)
    P.forget()
    P.line('; optional spring pass round the stock 40 x 20 (tool centre 6 outside the walls)')
    for kw in (dict(g=0, X=-6, Y=-6), dict(g=1, Z=-3, F=600), dict(g=1, X=46, F=2400), dict(g=1, Y=26),
               dict(g=1, X=-6), dict(g=1, Y=-6), dict(g=0, Z=5)):
        g = kw.pop('g')
        P.move(g, skip='/2', **kw)
    P.forget()
    P.rapid(Z=50)
    P.block('M09')
    P.block('M05')
    P.rapid(X=0, Y=100)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 11. incremental_g91.nc -- hand-written pattern in G91, G92 shifts


def p_incremental_g91():
    P = Program(handwritten, n_start=10, n_step=10, omit_zero_centre=False, feed_fmt=lambda f: f_strip(f, 0))
    P.line('; 6 rounded slots 12 x 10 (tool path, corner R3), D3 end mill, 1.5 deep')
    P.line('; each slot in G91 from its start point; G92 moves the pattern origin:')
    P.line(';   G90 G92 X.. Y.. sets the reference point offset, G91 G92 X.. adds to it')
    P.block('G90 G71 G17 G40 G94')
    P.block('G54')
    P.block('T8 M06')
    P.block('D8')
    P.block('S9000 M03')
    P.block('M08')
    P.rapid(Z=10)

    def slot():
        P.rapid(pre=['G90'], X=3, Y=0, force=('G',))
        P.rapid(Z=2)
        P.block('G91 G01 Z-3.5 F400')
        P.block('X6 F1800')
        P.block('G03 X3 Y3 I0 J3')
        P.block('G01 Y4')
        P.block('G03 X-3 Y3 I-3 J0')
        P.block('G01 X-6')
        P.block('G03 X-3 Y-3 I0 J-3')
        P.block('G01 Y-4')
        P.block('G03 X3 Y-3 I3 J0')
        P.block('G00 Z3.5')
        P.forget()
        P.set_pos(Z=2.0)

    P.block('G90 G92 X10 Y10')
    slot()
    for k in range(2):
        P.block('G91 G92 X22')
        slot()
    P.block('G91 G92 X-44 Y18')
    slot()
    for k in range(2):
        P.block('G91 G92 X22')
        slot()
    P.block('G90 G92 X0 Y0')
    P.forget()
    P.rapid(pre=['G90'], Z=50, force=('G',))
    P.block('M09')
    P.block('M05')
    P.rapid(X=0, Y=100)
    P.block('M30')
    return P.lines


# ----------------------------------------------------------------------------
# 12. mixed_transitions.nc -- contouring, exact stop, tool changes, H functions


def p_mixed_transitions():
    P = Program(fusion, n_start=10, n_step=5)
    P.line('(T2  D=8 CR=0 - FLAT END MILL - CAM PROFILE FACETED TO 4 DEG)')
    P.line('(T4  D=6 CR=0.5 - BULL NOSE - SQUARE POCKET WALL)')
    P.line('(H20/H21 MQL ON/OFF - H100 PART DONE)')
    P.block('G90 G94 G17')
    P.block('G71')
    P.block('G54')
    P.line('(CAM PROFILE - POLYLINE OF CHORDS, CONTOURED)')
    P.block('T2 M06')
    P.block('D2')
    P.block('S10000 M03')
    P.block('H20')
    cx, cy = 40.0, 35.0

    def cam(th):
        r = 18 + 3 * math.cos(3 * th)
        return cx + r * math.cos(th), cy + r * math.sin(th)

    th0 = math.radians(2.0)
    p0 = cam(th0)
    r0, dr0 = 18 + 3 * math.cos(3 * th0), -9 * math.sin(3 * th0)
    tx, ty = unit(dr0 * math.cos(th0) - r0 * math.sin(th0), dr0 * math.sin(th0) + r0 * math.cos(th0))
    o = (p0[0] + 5 * ty, p0[1] - 5 * tx)  # lead arcs R5, centre right of the CCW travel (outside)
    thp = math.atan2(p0[1] - o[1], p0[0] - o[0])
    lead_in = (o[0] + 5 * math.cos(thp + math.pi / 2), o[1] + 5 * math.sin(thp + math.pi / 2))
    lead_out = (o[0] + 5 * math.cos(thp - math.pi / 2), o[1] + 5 * math.sin(thp - math.pi / 2))
    P.block('#CONTOUR MODE [DEV PATH_DEV=0.02]')
    P.rapid(X=lead_in[0], Y=lead_in[1])
    P.rapid(Z=15)
    for k, depth in enumerate((-2.0, -4.0)):
        P.rapid(Z=3)
        P.lin(Z=depth, F=400)
        P.move(2, pre=['G261'] if k == 0 else [], X=p0[0], Y=p0[1], centre={'X': o[0], 'Y': o[1]}, F=3000)
        for i in range(1, 91):
            x, y = cam(th0 + math.radians(4 * i))
            P.lin(X=x, Y=y)
        P.move(2, pre=['G60'], X=lead_out[0], Y=lead_out[1], centre={'X': o[0], 'Y': o[1]})
        P.rapid(Z=3)
        P.rapid(X=lead_in[0], Y=lead_in[1])
    P.block('G260')
    P.rapid(Z=50)
    P.block('H21')
    P.block('M05')
    P.line('(SQUARE POCKET WALL - EXACT STOP AT EVERY BLOCK)')
    P.block('T4 M06')
    P.block('D4')
    P.block('S12000 M03')
    P.block('H20')
    P.forget()
    qx, qy = 100.0, 35.0  # pocket centre
    P.rapid(X=qx, Y=qy, comment='POCKET PRE-ROUGHED')
    P.rapid(Z=15)
    P.rapid(Z=3)
    P.lin(Z=-3, F=300)
    P.block('G360')
    P.lin(X=qx + 9, F=1500)
    for x, y in ((qx + 9, qy + 9), (qx - 9, qy + 9), (qx - 9, qy - 9), (qx + 9, qy - 9), (qx + 9, qy)):
        P.lin(X=x, Y=y)
    P.block('G359')
    P.line('(SECOND WALL PASS WITH R4 CORNERS - G61 CONTOURS ONE BLOCK, G60 STOPS ONE BLOCK)')
    P.lin(pre=['G61'], X=qx + 9, Y=qy + 5)
    P.move(3, X=qx + 5, Y=qy + 9, centre={'X': qx + 5, 'Y': qy + 5}, comment='R4 CORNER')
    P.lin(pre=['G60'], X=qx - 5)
    P.move(3, X=qx - 9, Y=qy + 5, centre={'X': qx - 5, 'Y': qy + 5}, comment='R4 CORNER')
    P.lin(pre=['G61'], X=qx - 9, Y=qy - 5)
    P.lin(X=qx, Y=qy)
    P.rapid(Z=50)
    P.block('H21')
    P.block('M05')
    P.block('H100')
    P.rapid(X=0, Y=150)
    P.block('M30')
    return P.lines


PROGRAMS = [
    ('contour_2d_arcs', p_contour_2d_arcs, True,
     '2D outside profile of a 60 x 40 plate: lines and tangent arcs G02/G03 with I J (corner R13 tool path, '
     'an R12 notch), lead-in and lead-out arcs R5, two depth passes; T1 M06 D1, S M03, coolant M08/M09.',
     'Fusion 360-like post: N numbers step 5, 3 decimals with trailing zeros dropped, modal words '
     'suppressed, arcs with both I and J.', 'Fusion 360 output'),
    ('pocket_helix_ramp', p_pocket_helix_ramp, True,
     'circular pocket D33.5, 4 deep: helical ramp R4 entered above the stock, three full-turn G03 helix '
     'blocks (I only, Z changing, pitch 1.5), a flat turn, spiral-out half circles with alternating centres '
     'and a finishing full circle.',
     'Mastercam-like post: N100 step 2, leading-dot numbers (Z.5), zero centre words omitted, tool '
     'offset as D.', 'Mastercam output'),
    ('radius_arcs', p_radius_arcs, True,
     'lever profile programmed with R arcs: a rounded-triangle cut-out (G03 R3 corners, R2.5 leads) and the '
     'outer profile of two bosses joined by tangents: G02 R-22 round boss 1 (196 deg, > 180 deg), G02 R12 '
     'round boss 2, G03 R5 leads; two depth passes.',
     'SolidCAM-like post: N1 step 1, fixed 3 decimals (X38.440), contour section comments.', 'SolidCAM output'),
    ('planes_g18_g19', p_planes_g18_g19, False,
     'side work with a ball nose: a cove R10 cut in G18 (Z-X plane, arcs with I K, G02 and G03 passes, '
     '129 deg arcs with irrational end points), a round-over R5 on the front edge in G19 (Y-Z plane, J K), '
     'back to G17 for a ring G03 I J; explicit G162.',
     'hand-written shop-floor program: N10 step 10, short numbers, zero centre words omitted, ; notes.',
     'a hand-written shop-floor program'),
    ('surfacing_3d', p_surfacing_3d, False,
     '3D raster finishing of a 30 x 24 mm patch over a Gaussian bump (2.5 high): 31 zig-zag rows, '
     '0.5 mm point spacing, 0.8 mm stepover, ball tip offset along the surface normal, ~1900 short G01 '
     'blocks with X Y Z in 4 decimals at F3000.',
     'PowerMill-like raster finishing: no N numbers in the toolpath, fixed 4 decimals, modal G01 and F.',
     'PowerMill output'),
    ('engraving', p_engraving, False,
     'text engraving "TC3 CNC" in a frame: many short G01 lines (letters sampled every 7.5 or 10 deg), '
     'shallow Z-0.3, G60 exact stop at sharp corners and cusps, G61 on the blocks of curved strokes; '
     'machine coordinates, no zero offset.',
     'Vectric VCarve-like output: no N numbers, G0/G1 short forms, fixed 3 decimals, F with one decimal.',
     'Vectric VCarve output'),
    ('plasma_profile', p_plasma_profile, True,
     'plasma cut of a flange with an R30 saddle and two holes: no Z words at all, torch on/off H1/H2, '
     'THC on/off H10/H11, extraction M08/M09, pierce dwell G04 X0.3 alone in its block, arc lead-ins, '
     'kerf already in the path (no radius compensation), holes G03 then the outside G02.',
     'SheetCam-like plasma post: zero-padded N0010 step 10, 3 decimals.', 'SheetCam output'),
    ('drilling_manual', p_drilling_manual, False,
     'drilling without cycles: G00 positioning, G01 Z feed, G04 dwell at depth, G00 retract, a chip-break '
     'peck; 4 holes in G54 and 4 on a bolt circle in G55 (irrational positions), spot drill T11 and drill '
     'T12; ends with G53 (zero offset suppressed) moves.',
     'generic DIN 66025 post with drilling cycles output long-hand: N10 step 10, 3 decimals.',
     'a generic DIN 66025 post (drilling cycles written out long-hand)'),
    ('inch_program', p_inch_program, True,
     'small profile and bore in G70 (inch): inch coordinates with leading dots (X-.125, I.375), inch/min '
     'feeds F20..F80, a full circle starting at 30 deg; G71 again near the end for metric park moves.',
     'Mastercam-like inch post converted to the TwinCAT words (inch/metric as G70/G71, tool offset as D).',
     'Mastercam (inch) output'),
    ('block_skip', p_block_skip, True,
     'face milling with optional blocks: /N.. M01 (measuring stop) and /1 N.. finishing pass (both skip '
     'level 1: a bare / is level 1), /2 N.. wall spring pass; each option ends where the program goes on, so '
     'every combination of skip levels is a valid path.',
     'hand-written shop-floor program: N10 step 10, ; notes, every word repeated after the optional blocks.',
     'a hand-written shop-floor program'),
    ('incremental_g91', p_incremental_g91, False,
     'a slot repeated 6 times: each slot in G91 (G01 and G03 I J incremental), pattern origins set with '
     'G90 G92 X.. Y.. and moved with G91 G92 X.. (the additive reference point offset of TwinCAT), reset '
     'with G90 G92 X0 Y0; on top of G54.',
     'hand-written shop-floor program: N10 step 10, whole numbers, the slot block-for-block the same.',
     'a hand-written shop-floor program'),
    ('mixed_transitions', p_mixed_transitions, False,
     'block transitions: #CONTOUR MODE [DEV PATH_DEV=0.02], G261 on a faceted cam profile (90 chords of '
     '4 deg, two depths), G260, an exact-stop section G360 .. G359, single blocks with G61 and G60; tool '
     'changes T2 M06 D2 and T4 M06 D4, H functions H20/H21/H100.',
     'Fusion 360-like post for an ISG/TwinCAT control: N10 step 5, 3 decimals.', 'Fusion 360 (TwinCAT post) output'),
]


# ----------------------------------------------------------------------------
# the check: reads the .nc text


class CheckError(Exception):
    pass


G_ALLOWED = {0, 1, 2, 3, 4, 17, 18, 19, 40, 53, 54, 55, 56, 57, 58, 59, 60, 61, 70, 71, 90, 91, 92, 94, 162,
             260, 261, 359, 360}
G_TRANSITION = {60, 61, 260, 261, 359, 360}
M_ALLOWED = {0, 1, 3, 4, 5, 6, 7, 8, 9, 30}
LETTERS = set('NGMXYZIJKRFSTDH')
WORD_RE = re.compile(r'([A-Z])([+-]?(?:\d+\.?\d*|\.\d+))')
CONTOUR_RE = re.compile(r'^(N\d+ )?#CONTOUR MODE \[DEV PATH_DEV=\d*\.?\d+\]$')


def strip_comments(line):
    out, in_paren = [], False
    for c in line:
        if in_paren:
            if c == '(':
                raise CheckError("'(' inside a ( ) comment")
            if c == ')':
                in_paren = False
            continue
        if c == ';':
            break
        if c == '(':
            in_paren = True
            continue
        out.append(c)
    if in_paren:
        raise CheckError('( ) comment not closed on its line')
    return ''.join(out)


def skip_level(code):
    """'/' and '/1' -> '/1', '/2' -> '/2', else None; returns (level, rest)."""
    st = code.lstrip()
    if not st.startswith('/'):
        return None, st
    m = re.match(r'/(\d*)\s*', st)
    return '/' + (m.group(1) or '1'), st[m.end():]  # a bare / is level 1 (docs/DIALECT.md)


def simulate(lines, skipped):
    st = dict(m={'X': 0.0, 'Y': 0.0, 'Z': 0.0}, zero=(0.0, 0.0, 0.0), g92=[0.0, 0.0, 0.0], inch=False,
              absolute=True, plane=17, motion=None, feed=None, last_n=-1)
    res = dict(feed_len=0.0, feed_time=0.0, rapid_time=0.0, dwell=0.0, motion_blocks=0, arcs=0, max_dr=0.0,
               min_xyz=[1e9] * 3, max_xyz=[-1e9] * 3, m30=0)
    axes = 'XYZ'
    code_lines = []
    for idx, raw in enumerate(lines):
        try:
            code = strip_comments(raw)
            if not code.strip():
                continue
            if code.strip().startswith('%'):
                if idx != 0:
                    raise CheckError('%name only on the first line')
                continue
            level, rest = skip_level(code)
            code_lines.append(idx)
            if level is not None and level in skipped:
                continue
            if res['m30']:
                raise CheckError('code after M30')
            if '#' in rest:
                if not CONTOUR_RE.match(rest.strip()):
                    raise CheckError('only #CONTOUR MODE [DEV PATH_DEV=..] is allowed')
                n = re.match(r'N(\d+)', rest.strip())
                if n:
                    check_n(st, int(n.group(1)))
                continue
            words, pos = [], 0
            text = rest.rstrip()
            while pos < len(text):
                if text[pos] == ' ':
                    pos += 1
                    continue
                mm = WORD_RE.match(text, pos)
                if not mm:
                    raise CheckError(f'not a word at "{text[pos:]}"')
                words.append((mm.group(1), mm.group(2)))
                pos = mm.end()
            block(st, res, words)
        except CheckError as e:
            raise CheckError(f'line {idx + 1}: {e}: {raw}')
    if not res['m30']:
        raise CheckError('no M30')
    last = lines[code_lines[-1]]
    if 'M30' not in strip_comments(last):
        raise CheckError('M30 is not the last block')
    return res


def check_n(st, n):
    if n <= st['last_n']:
        raise CheckError(f'N{n} does not increase')
    st['last_n'] = n


def block(st, res, words):
    letters = [w[0] for w in words]
    for L in letters:
        if L not in LETTERS:
            raise CheckError(f'letter {L} is not in the dialect')
    for L in set(letters):
        if L not in 'G' and letters.count(L) > 1:
            raise CheckError(f'{L} twice in one block')
    if 'N' in letters:
        if letters[0] != 'N':
            raise CheckError('N must come first')
        check_n(st, int(words[0][1]))
    gs = []
    for L, v in words:
        if L == 'G':
            if '.' in v:
                raise CheckError('G with decimals')
            g = int(v)
            if g not in G_ALLOWED:
                raise CheckError(f'G{g} is not in the dialect')
            gs.append(g)
        if L == 'M':
            if int(v) not in M_ALLOWED or '.' in v:
                raise CheckError(f'M{v} is not in the dialect')
        if L in 'XYZIJKR':
            if '.' in v and len(v.split('.')[1]) > 4:
                raise CheckError(f'{L}{v}: more than 4 decimals')
    if sum(g in G_TRANSITION for g in gs) > 1:
        raise CheckError('two block transition G functions in one block (20117)')
    if sum(g in (0, 1, 2, 3) for g in gs) > 1:
        raise CheckError('two motion G codes')
    if sum(g in (53, 54, 55, 56, 57, 58, 59) for g in gs) > 1:
        raise CheckError('two zero offsets')
    w = {L: float(v) for L, v in words if L not in 'G'}
    if 70 in gs:
        st['inch'] = True
    if 71 in gs:
        st['inch'] = False
    scale = 25.4 if st['inch'] else 1.0
    if 4 in gs:
        if set(letters) - {'N', 'G', 'X'} or len(gs) != 1 or 'X' not in w:
            raise CheckError('G04 must stand alone: [N..] G04 X<s>')
        if not 0 < w['X'] <= 10:
            raise CheckError('dwell time')
        res['dwell'] += w['X']
        return
    for g in gs:
        if g in (17, 18, 19):
            st['plane'] = g
        elif g in (90, 91):
            st['absolute'] = g == 90
        elif g in (0, 1, 2, 3):
            st['motion'] = g
        elif g == 53:
            st['zero'] = (0.0, 0.0, 0.0)
        elif g in ZERO_OFFSETS:
            st['zero'] = ZERO_OFFSETS[g]
        elif g in (56, 57, 58, 59):
            raise CheckError(f'G{g}: no offset assumed for it')
    if 'F' in w:
        st['feed'] = w['F'] * scale
    if 'M' in w and int(w['M']) == 30:
        res['m30'] = 1
    axes = 'XYZ'
    if 92 in gs:
        if set(letters) & set('IJKRF') or any(g in (0, 1, 2, 3) for g in gs):
            raise CheckError('G92 must not be combined with motion')
        for k, a in enumerate(axes):
            if a in w:
                st['g92'][k] = (0.0 if st['absolute'] else st['g92'][k]) + w[a] * scale
        return
    if not any(a in w for a in axes):
        if set(letters) & set('IJKR'):
            raise CheckError('centre words without motion')
        return
    if st['motion'] is None:
        raise CheckError('axis words without a motion G code')
    off = [st['zero'][k] + st['g92'][k] for k in range(3)]
    start = dict(st['m'])
    prog = {a: start[a] - off[k] for k, a in enumerate(axes)}
    end = dict(start)
    for k, a in enumerate(axes):
        if a in w:
            p = w[a] * scale if st['absolute'] else prog[a] + w[a] * scale
            end[a] = p + off[k]
    g = st['motion']
    res['motion_blocks'] += 1
    pts = [start, end]
    if g == 0:
        if set(letters) & set('IJKR'):
            raise CheckError('I J K R with G00')
        res['rapid_time'] += max(abs(end[a] - start[a]) / V_RAPID[a] for a in axes)
    else:
        if st['feed'] is None:
            raise CheckError('feed motion without F')
        if not 100 - 1e-9 <= st['feed'] <= 6000 + 1e-9:
            raise CheckError(f'feed {st["feed"]:.1f} mm/min outside 100..6000')
        if g == 1:
            if set(letters) & set('IJKR'):
                raise CheckError('I J K R with G01')
            length = math.dist([start[a] for a in axes], [end[a] for a in axes])
        else:
            length, pts = arc(st, res, w, start, end, g, scale, letters)
        res['feed_len'] += length
        res['feed_time'] += length / (st['feed'] / 60.0)
    for p in pts:
        for k, a in enumerate(axes):
            lo, hi = LIMITS[a]
            if not lo - 1e-9 <= p[a] <= hi + 1e-9:
                raise CheckError(f'{a} machine {p[a]:.4f} outside {lo}..{hi}')
            res['min_xyz'][k] = min(res['min_xyz'][k], p[a])
            res['max_xyz'][k] = max(res['max_xyz'][k], p[a])
    st['m'] = end


def arc(st, res, w, start, end, g, scale, letters):
    a1, a2 = PLANE_AXES[st['plane']]
    an = ({'X', 'Y', 'Z'} - {a1, a2}).pop()
    cw1, cw2 = CENTRE_WORD[a1], CENTRE_WORD[a2]
    wrong = {'I', 'J', 'K'} - {cw1, cw2}
    if set(letters) & wrong:
        raise CheckError(f'centre word {wrong} not of plane G{st["plane"]}')
    s = (start[a1], start[a2])
    e = (end[a1], end[a2])
    has_centre = cw1 in w or cw2 in w
    if 'R' in w:
        if has_centre:
            raise CheckError('R with I J K')
        R = w['R'] * scale
        d = math.dist(s, e)
        if d < 1e-9:
            raise CheckError('full circle with R')
        if d > 2 * abs(R) + 1e-3:
            raise CheckError('R arc: chord longer than 2|R|')
        h = math.sqrt(max(R * R - d * d / 4, 0.0))
        mx, my = (s[0] + e[0]) / 2, (s[1] + e[1]) / 2
        plx, ply = -(e[1] - s[1]) / d, (e[0] - s[0]) / d
        sgn = 1 if (g == 3) == (R > 0) else -1
        c = (mx + sgn * h * plx, my + sgn * h * ply)
    elif has_centre:
        c = (s[0] + w.get(cw1, 0.0) * scale, s[1] + w.get(cw2, 0.0) * scale)
    else:
        raise CheckError('arc without I J K or R')
    rs, re_ = math.dist(s, c), math.dist(e, c)
    dr = abs(rs - re_)
    res['max_dr'] = max(res['max_dr'], dr)
    if dr > 0.01:
        raise CheckError(f'end radius {re_:.4f} differs from start radius {rs:.4f}')
    ts = math.atan2(s[1] - c[1], s[0] - c[0])
    te = math.atan2(e[1] - c[1], e[0] - c[0])
    sweep = (te - ts) % (2 * math.pi) if g == 3 else (ts - te) % (2 * math.pi)
    if math.dist(s, e) < 1e-9:
        sweep = 2 * math.pi
    if 'R' in w and ((w['R'] > 0) != (sweep <= math.pi + 1e-6)):
        raise CheckError('R sign does not match the sweep')
    sign = 1 if g == 3 else -1
    pts = []
    n = max(8, int(sweep / (2 * math.pi) * 128))
    for i in range(n + 1):
        t = i / n
        ang = ts + sign * sweep * t
        r = rs + (re_ - rs) * t
        p = dict(start)
        p[a1] = c[0] + r * math.cos(ang)
        p[a2] = c[1] + r * math.sin(ang)
        p[an] = start[an] + (end[an] - start[an]) * t
        pts.append(p)
    res['arcs'] += 1
    length = math.hypot(sweep * (rs + re_) / 2, end[an] - start[an])
    return length, pts


def check_text(name, text):
    if '\r' in text or '\t' in text:
        raise CheckError('CR or TAB in the file')
    if not text.endswith('\n'):
        raise CheckError('no newline at the end')
    lines = text.split('\n')[:-1]
    for k, l in enumerate(lines):
        if l != l.rstrip():
            raise CheckError(f'line {k + 1}: trailing blank')
        if not l:
            raise CheckError(f'line {k + 1}: empty line')
    head = lines[1:] if lines[0].startswith('%') else lines
    if not head[0].startswith(';'):
        raise CheckError('the file does not start with the ; header')
    top = '\n'.join(head[:30])
    for key in ('What:', 'Style:', 'Origin:', 'Machine:'):
        if key not in top:
            raise CheckError(f'header lacks {key}')
    levels = set()
    for l in lines:
        lv, _ = skip_level(strip_comments(l))
        if lv:
            levels.add(lv)
    results = {}
    for k in range(len(levels) + 1):
        for combo in itertools.combinations(sorted(levels), k):
            results[combo] = simulate(lines, set(combo))
    return lines, levels, results


def summary(lines, results):
    r = results[()]
    return dict(lines=len(lines), blocks=r['motion_blocks'], feed_len=r['feed_len'], feed=r['feed_time'],
                rapid=r['rapid_time'], dwell=r['dwell'], max_dr=r['max_dr'], arcs=r['arcs'],
                min=r['min_xyz'], max=r['max_xyz'])


def time_text(s):
    return (f'~{s["feed"] + s["rapid"]:.1f} s of motion ({s["feed"]:.1f} s feed over {s["feed_len"]:.0f} mm, '
            f'{s["rapid"]:.1f} s rapid) + {s["dwell"]:.1f} s dwell, estimated as path length / feed')


def main():
    check_only = '--check' in sys.argv
    if not check_only:
        for name, fn, percent, what, style, cam in PROGRAMS:
            body = fn()
            first = [f'%{name}'] if percent else []
            draft = first + header(name, what, style, ORIGIN.format(cam)) + body
            _, _, results = check_text(name, '\n'.join(draft) + '\n')
            s = summary(draft, results)
            extra = [('Time', time_text(s))]
            lv = sorted(k for k in results if k)
            if lv:
                every = results[tuple(sorted(set().union(*map(set, lv))))]
                extra.append(('Skips', f'with every skip level on: {every["feed_time"] + every["rapid_time"]:.1f} s '
                                       f'of motion; every combination of levels checked'))
            text = '\n'.join(first + header(name, what, style, ORIGIN.format(cam), extra) + body) + '\n'
            with open(os.path.join(HERE, name + '.nc'), 'w') as f:
                f.write(text)
    ok = True
    print(f'{"file":24s} {"lines":>5s} {"motion":>6s} {"feed s":>7s} {"rapid s":>7s} {"dwell":>5s} '
          f'{"arcs":>4s} {"max dr um":>9s}  machine min/max X Y Z')
    for name in sorted(f[:-3] for f in os.listdir(HERE) if f.endswith('.nc')):
        with open(os.path.join(HERE, name + '.nc')) as f:
            text = f.read()
        try:
            lines, levels, results = check_text(name, text)
        except CheckError as e:
            print(f'{name}.nc: FAIL {e}')
            ok = False
            continue
        s = summary(lines, results)
        rng = ' '.join(f'{lo:.1f}/{hi:.1f}' for lo, hi in zip(s['min'], s['max']))
        print(f'{name + ".nc":24s} {s["lines"]:5d} {s["blocks"]:6d} {s["feed"]:7.1f} {s["rapid"]:7.1f} '
              f'{s["dwell"]:5.1f} {s["arcs"]:4d} {s["max_dr"] * 1000:9.2f}  {rng}'
              + (f'  skip levels {sorted(levels)}: {len(results)} variants ok' if levels else ''))
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
