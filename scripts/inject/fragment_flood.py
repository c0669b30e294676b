#!/usr/bin/env python3
"""RIG-9: a process on the rig's network that sends LCM fragment headers.

Each datagram is the first fragment (LC03, fragment 0 of N) of a message
that announces --announce-mib MiB on one of the rig's channels and is never
sent on: what made a receiver that trusts the announced size allocate it
(issue 33). Every datagram comes from a socket of its own (its own sender to
a receiver) unless --senders says fewer. Sends only to a 239.x group, ttl 0:
run it inside scripts/in_netns.sh.

  fragment_flood.py --port 7800 --count 80 --wait-for HLI_STATE
"""
import argparse
import ipaddress
import socket
import struct
import sys
import time

LC02, LC03 = 0x4C433032, 0x4C433033  # LCM 1.3.1 udpm_util.h
LONG_HEADER = struct.Struct(">IIIIHH")  # magic, seqno, message size, offset, fragment no, fragments
FRAGMENT_MAX_PAYLOAD = 65487  # LCM_FRAGMENT_MAX_PAYLOAD: channel, NUL and data of one fragment
RIG_CHANNELS = "HLI_CONTROL,HLI_STATE,AXIS_X_STATE,AXIS_Y_STATE,AXIS_Z_STATE,AXIS_X_CMD,HIL_PARTICIPANT,HIL_EVENT"


def first_fragment(seqno, channel, announced, payload):
    name = channel.encode() + b"\0"
    fragments = min(65535, -(-(len(name) + announced) // FRAGMENT_MAX_PAYLOAD))
    data = bytes(min(payload, FRAGMENT_MAX_PAYLOAD - len(name), announced))
    return LONG_HEADER.pack(LC03, seqno, announced, 0, 0, fragments) + name + data


def sender(group):
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 0)  # never beyond this host
    s.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
    s.connect(group)
    return s


def wait_for(group, channel, timeout_s):
    """Until a short LCM datagram on `channel` arrives on the group: the run is on."""
    r = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    r.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    r.bind(("", group[1]))
    r.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
                 socket.inet_aton(group[0]) + socket.inet_aton("0.0.0.0"))
    r.settimeout(0.5)
    print(f"fragment_flood: waiting for {channel}", flush=True)  # joined: the run can start
    wanted = channel.encode() + b"\0"
    give_up = time.monotonic() + timeout_s
    while time.monotonic() < give_up:
        try:
            d = r.recv(65536)
        except socket.timeout:
            continue
        if len(d) > 8 and struct.unpack(">I", d[:4])[0] == LC02 and d[8:8 + len(wanted)] == wanted:
            r.close()
            return True
    r.close()
    return False


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--group", default="239.255.76.67")
    p.add_argument("--port", type=int, required=True)
    p.add_argument("--count", type=int, default=10, help="fragment headers per burst")
    p.add_argument("--bursts", type=int, default=1)
    p.add_argument("--interval-s", type=float, default=0.1, help="between bursts")
    p.add_argument("--announce-mib", type=float, default=256, help="the message size each header announces")
    p.add_argument("--payload", type=int, default=1000, help="data bytes after the channel name")
    p.add_argument("--channels", default=RIG_CHANNELS, help="comma-separated, used in turn")
    p.add_argument("--senders", type=int, default=0, help="sockets to send from in turn (0: one per datagram)")
    p.add_argument("--wait-for", default="", help="first wait for a datagram on this channel (the run started)")
    p.add_argument("--timeout-s", type=float, default=60)
    a = p.parse_args()

    if ipaddress.ip_address(a.group) not in ipaddress.ip_network("239.0.0.0/8"):
        sys.exit("fragment_flood: only to an administratively scoped 239.x group")
    group = (a.group, a.port)
    if a.wait_for and not wait_for(group, a.wait_for, a.timeout_s):
        sys.exit(f"fragment_flood: no {a.wait_for} within {a.timeout_s} s")
    channels = a.channels.split(",")
    announced = min(int(a.announce_mib * 1024 * 1024), 0xFFFFFFFF)
    pool = [sender(group) for _ in range(a.senders)]
    sent = 0
    for burst in range(a.bursts):
        for i in range(a.count):
            s = pool[sent % len(pool)] if pool else sender(group)
            s.send(first_fragment(0x40000000 + sent, channels[i % len(channels)], announced, a.payload))
            if not pool:
                s.close()
            sent += 1
        if burst + 1 < a.bursts:
            time.sleep(a.interval_s)
    print(f"fragment_flood: sent {sent} fragment headers of {a.announce_mib:g} MiB each to {a.group}:{a.port}")


if __name__ == "__main__":
    main()
