#!/usr/bin/env python3
"""RIG-6: a real-time run's HIL_RT_STATS over time, from its LCM log (no LCM
module needed: the event log and rt_stats_t are read by hand). One line per
statistics message: the cycle, the ticks and overruns since the last one,
the jitter so far (p50/p99/max are cumulative), each participant's late
answers and longest gap so far. Usage: bench/rt_stats_series.py RUN.lcmlog [EVERY]"""
import struct
import sys


def events(path):
    with open(path, "rb") as f:
        data = f.read()
    i = 0
    while i + 28 <= len(data):
        sync, _num, _t, clen, dlen = struct.unpack(">IqqII", data[i:i + 28])
        if sync != 0xEDA1DA01:
            raise SystemExit(f"{path}: no LCM event at byte {i}")
        channel = data[i + 28:i + 28 + clen].decode()
        payload = data[i + 28 + clen:i + 28 + clen + dlen]
        i += 28 + clen + dlen
        yield channel, payload


def rt_stats(p):
    o = 8  # fingerprint
    _run, _utime, cycle = struct.unpack_from(">qqq", p, o); o += 24
    final, cycle_us = struct.unpack_from(">bi", p, o); o += 5
    (n,) = struct.unpack_from(">i", p, o); o += 4 + n  # scheduling
    ticks, overruns, p50, p99, mx = struct.unpack_from(">qqddd", p, o); o += 40
    (count,) = struct.unpack_from(">h", p, o); o += 2
    names = []
    for _ in range(count):
        (n,) = struct.unpack_from(">i", p, o); o += 4
        names.append(p[o:o + n - 1].decode()); o += n
    cols = []
    for _ in range(7):  # in_time late missing out_of_order duplicate longest_gap watchdog
        cols.append(struct.unpack_from(">" + "q" * count, p, o)); o += 8 * count
    return cycle, final, ticks, overruns, p50, p99, mx, names, cols


def main():
    every = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    last_ticks = last_over = 0
    k = 0
    for channel, payload in events(sys.argv[1]):
        if channel != "HIL_RT_STATS":
            continue
        cycle, final, ticks, over, p50, p99, mx, names, cols = rt_stats(payload)
        k += 1
        if k % every and not final:
            continue
        late = " ".join(f"{n.split()[-1]}:{cols[1][i]}/{cols[5][i]}" for i, n in enumerate(names))
        print(f"cycle {cycle:8d}{' final' if final else ''}: +{ticks - last_ticks} ticks, +{over - last_over} overruns"
              f" (total {over}); jitter so far p50 {p50:.0f} p99 {p99:.0f} max {mx:.0f} us; late/longest gap {late}")
        last_ticks, last_over = ticks, over


main()
