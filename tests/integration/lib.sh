# Shared by the integration tests. The caller sets HIL_BIN (folder of the
# built executables), HIL_SOURCE (source tree) and WORK (a fresh folder).
set -eu
hil="$HIL_BIN/hil"
rm -rf "$WORK" && mkdir -p "$WORK"

fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_status N CMD...: runs CMD, output to $WORK/last.out, status must be N.
expect_status() {
  want=$1; shift
  set +e; "$@" >"$WORK/last.out" 2>&1; got=$?; set -e
  cat "$WORK/last.out"
  [ "$got" -eq "$want" ] || fail "'$*' exited with $got, expected $want"
}

# expect_output TEXT: the last command's output contains TEXT.
expect_output() {
  grep -qF -- "$1" "$WORK/last.out" || fail "output lacks '$1'"
}
