#!/bin/sh
# The last 40 lines of every failed test's output in a ctest LastTest.log.
awk '
  / Testing: / { name = $3 }
  /^Output:$/ { n = 0; inside = 1; getline; next }
  /^<end of output>$/ { inside = 0; next }
  inside { out[n++] = $0; next }
  /^Test Failed\.$/ || /^Test Failed/ {
    print "==== " name ": its last lines ===="
    for (i = (n > 40 ? n - 40 : 0); i < n; i++) print out[i]
  }
' "$1"
