#!/bin/sh
# Runs a command in a private network namespace with multicast on loopback,
# so that the rig's udpm traffic never leaves it and parallel tests never
# hear each other (needs root, as in CI).
#   scripts/in_netns.sh COMMAND...         a new namespace (unshare -n: CAP_SYS_ADMIN)
#   scripts/in_netns.sh --here COMMAND...  the namespace is private already (a
#     container run with --network none, a pod): only its loopback gets the
#     multicast route (CAP_NET_ADMIN, as `docker run --cap-add NET_ADMIN`)
loopback='ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo'
if [ "${1:-}" = "--here" ]; then
  shift
  sh -c "$loopback" && exec "$@"
fi
exec unshare -n sh -c "$loopback"' && exec "$@"' in_netns "$@"
