#!/bin/sh
# LinuxCNC 2.9 reference bench: runs the project's NC programs on LinuxCNC's
# headless simulator and prints "program mode time_s v_med v_p5 dev_mm samples".
# LinuxCNC is a REFERENCE ONLY, never a dependency of the project.
# Usage: bench/linuxcnc/run.sh [--modes G61,G64] [--keep] [PROGRAM ...]   (README.md)
# The table goes to stdout, progress to stderr. Uses no network (safe in a network
# namespace); runs as root or as a user.
HERE=$(cd "$(dirname "$0")" && pwd)
if [ ! -x /usr/bin/linuxcnc ]; then
    echo "bench/linuxcnc: /usr/bin/linuxcnc is missing: LinuxCNC (Debian package linuxcnc-uspace) is not installed;" >&2
    echo "bench/linuxcnc: it is only a reference for comparison, nothing to do." >&2
    exit 0
fi
if ! /usr/bin/python3 -c 'import linuxcnc, numpy' 2>/dev/null; then
    echo "bench/linuxcnc: /usr/bin/python3 cannot import the linuxcnc module (and numpy); LinuxCNC install incomplete, nothing to do." >&2
    exit 0
fi
if [ -e /tmp/linuxcnc.lock ]; then
    # the linuxcnc script would otherwise clean up (kill) the running instance
    echo "bench/linuxcnc: /tmp/linuxcnc.lock exists: another LinuxCNC is running; not starting." >&2
    exit 1
fi
exec /usr/bin/python3 "$HERE/bench.py" "$@"
