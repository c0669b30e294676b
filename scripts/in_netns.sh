#!/bin/sh
# Runs a command in a private network namespace with multicast on loopback,
# so that the rig's udpm traffic never leaves it and parallel tests never
# hear each other (needs root, as in CI).
exec unshare -n sh -c 'ip link set lo up && ip link set lo multicast on &&
  ip route add 224.0.0.0/4 dev lo && exec "$@"' in_netns "$@"
