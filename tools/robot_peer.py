#!/usr/bin/env python3
"""Reference peer of the cargo-openr external robot protocol (docs/robot-protocol.md).

Attaches to `cargo openr run --robot-socket PATH` (or `--robot-tcp 127.0.0.1:PORT`),
prints the WELCOME, and acts as a "perfect servo": it owns the clock (lockstep) and
answers every FRAME with READINGS whose measured joint angles are the frame's joint
targets. Optionally records every FRAME as one JSON line. Python 3 standard library
only; a starting point for a physics peer (replace `physics()`).

    python3 tools/robot_peer.py /tmp/robot.sock --record frames.jsonl
    python3 tools/robot_peer.py --tcp 127.0.0.1:7700 --no-clock --frames 100
"""
import argparse
import json
import socket
import struct
import sys

MAGIC = b"ORP1"
VERSION = 1
HEADER = struct.Struct("<4sHHII")  # magic, version, type, length, frame

HELLO, WELCOME, FRAME, READINGS, IMAGE, MIC, SPEAKER, CLOCK, BYE, ERROR = range(1, 11)
ROLE_JOINTS, ROLE_ACCEL, ROLE_SWITCHES, ROLE_PSD, ROLE_CAMERA, ROLE_MIC, ROLE_SPEAKER = (1 << i for i in range(7))
ROLE_NAMES = ["joints", "accel", "switches", "psd", "camera", "mic", "speaker"]
FLAG_CLOCK = 1
FRAME_SENSOR_DUE, FRAME_CAMERA_DUE, FRAME_MIC_DUE, FRAME_READINGS_EXPECTED, FRAME_CAMERA_NEXT = 1, 2, 4, 8, 16
CLASS_NAMES = {1: "joint", 2: "ear", 3: "led2", 4: "led3", 5: "accel", 6: "switch", 7: "psd",
               8: "camera", 9: "mic", 10: "speaker", 11: "other"}


class Reader:
    """Little-endian payload reader."""

    def __init__(self, data):
        self.data, self.pos = data, 0

    def get(self, fmt):
        v = struct.unpack_from("<" + fmt, self.data, self.pos)
        self.pos += struct.calcsize("<" + fmt)
        return v if len(v) > 1 else v[0]

    def str(self):
        n = self.get("H")
        s = self.data[self.pos:self.pos + n].decode()
        self.pos += n
        return s


class Peer:
    def __init__(self, sock):
        self.sock = sock
        self.buf = b""

    def send(self, kind, frame, payload=b""):
        self.sock.sendall(HEADER.pack(MAGIC, VERSION, kind, len(payload), frame) + payload)

    def _read(self, n):
        while len(self.buf) < n:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise EOFError("the runtime closed the connection")
            self.buf += chunk
        data, self.buf = self.buf[:n], self.buf[n:]
        return data

    def recv(self):
        magic, version, kind, length, frame = HEADER.unpack(self._read(HEADER.size))
        if magic != MAGIC or version != VERSION:
            raise ValueError(f"bad header {magic!r} v{version}")
        return kind, frame, self._read(length)


def parse_welcome(p):
    r = Reader(p)
    w = {}
    w["version"], w["revision"], w["roles"], w["flags"] = r.get("HHII")
    w["frame_period_us"], w["last_frame"], w["time_ms"] = r.get("IIQ")
    w["camera_width"], w["camera_height"], w["camera_fps"] = r.get("HHH")
    w["mic_period_frames"], w["mic_block_bytes"], w["mic_rate"], w["mic_channels"], w["mic_bits"] = r.get("HHIHH")
    w["design"] = r.str()
    prims = []
    for _ in range(r.get("H")):
        pid, cls, sensor_index, lo, hi = r.get("IHhii")
        prims.append({"id": pid, "class": CLASS_NAMES.get(cls, cls), "sensor_index": sensor_index,
                      "min_urad": lo, "max_urad": hi, "locator": r.str()})
    if w["revision"] >= 2:  # sensor value ranges and standard gains
        by_id = {p["id"]: p for p in prims}
        for _ in range(r.get("H")):
            pid, lo, hi, gp, gi, gd = r.get("IiiHHH")
            p = by_id.get(pid, {})
            if (lo, hi) != (0, 0):
                p["value_min"], p["value_max"] = lo, hi
            if p.get("class") == "joint":
                p["standard_gain"] = [gp, gi, gd]
    w["primitives"] = prims
    w["roles"] = [ROLE_NAMES[b] for b in range(7) if w["roles"] & (1 << b)]
    w["clock"] = bool(w.pop("flags") & FLAG_CLOCK)
    return w


def parse_frame(frame, p):
    r = Reader(p)
    f = {"frame": frame}
    f["time_ms"], flags, f["motor_power"], f["face_mode"], _ = r.get("QBBBB")
    f["sensor_due"] = bool(flags & FRAME_SENSOR_DUE)
    f["camera_due"] = bool(flags & FRAME_CAMERA_DUE)
    f["mic_due"] = bool(flags & FRAME_MIC_DUE)
    f["readings_expected"] = bool(flags & FRAME_READINGS_EXPECTED)
    f["camera_next"] = bool(flags & FRAME_CAMERA_NEXT)
    joints = []
    for _ in range(r.get("H")):
        pid, target, measured, gp, gi, gd, enabled, _ = r.get("IiiHHHBB")
        joints.append({"id": pid, "target": target, "measured": measured, "gain": [gp, gi, gd], "enabled": bool(enabled)})
    f["joints"] = joints
    leds = []
    for _ in range(r.get("H")):
        pid, value, kind, mode = r.get("IBBH")
        leds.append({"id": pid, "kind": kind, "value": value, "mode": mode})
    f["leds"] = leds
    f["ears"] = [dict(zip(("id", "state"), r.get("II"))) for _ in range(r.get("H"))]
    return f


def readings_payload(joints, sensors=()):
    out = struct.pack("<H", len(joints)) + b"".join(struct.pack("<Ii", i, v) for i, v in joints)
    return out + struct.pack("<H", len(sensors)) + b"".join(struct.pack("<Ii", i, v) for i, v in sensors)


def physics(frame):
    """A perfect servo: every joint is exactly where it was told to be."""
    return [(j["id"], j["target"]) for j in frame["joints"]], []


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("socket", nargs="?", help="the runtime's --robot-socket path")
    ap.add_argument("--tcp", metavar="HOST:PORT", help="attach over TCP instead (the runtime's --robot-tcp)")
    ap.add_argument("--record", metavar="FILE", help="write every FRAME as a JSON line to FILE")
    ap.add_argument("--no-clock", action="store_true", help="do not take the clock (free-running: readings applied when they arrive)")
    ap.add_argument("--frames", type=int, default=0, help="detach (BYE) after this many frames (default: stay until the run ends)")
    ap.add_argument("--name", default="robot_peer.py")
    ap.add_argument("--quiet", action="store_true", help="do not print the WELCOME")
    a = ap.parse_args()
    if a.tcp:
        host, port = a.tcp.rsplit(":", 1)
        sock = socket.create_connection((host, int(port)))
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    elif a.socket:
        sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        sock.connect(a.socket)
    else:
        ap.error("give a socket path or --tcp HOST:PORT")
    peer = Peer(sock)
    name = a.name.encode()
    peer.send(HELLO, 0, struct.pack("<IIH", ROLE_JOINTS, 0 if a.no_clock else FLAG_CLOCK, len(name)) + name)
    kind, _, payload = peer.recv()
    if kind != WELCOME:
        print(f"robot_peer: expected WELCOME, got type {kind}: {payload!r}", file=sys.stderr)
        return 1
    welcome = parse_welcome(payload)
    if not a.quiet:
        print(json.dumps(welcome), flush=True)
    record = open(a.record, "w") if a.record else None
    frames = 0
    try:
        while True:
            try:
                kind, n, payload = peer.recv()
            except EOFError:
                break
            if kind == FRAME:
                f = parse_frame(n, payload)
                if record:
                    record.write(json.dumps(f) + "\n")
                joints, sensors = physics(f)
                if f["readings_expected"] or a.no_clock:
                    peer.send(READINGS, n, readings_payload(joints, sensors))
                frames += 1
                if a.frames and frames >= a.frames:
                    peer.send(BYE, n, struct.pack("<H", 4) + b"done")
                    break
            elif kind == BYE:
                break
            elif kind == ERROR:
                r = Reader(payload)
                code = r.get("H")
                print(f"robot_peer: runtime error {code}: {r.str()}", file=sys.stderr)
                return 2
            # SPEAKER / CLOCK: nothing to do for a perfect servo
    finally:
        if record:
            record.close()
        sock.close()
    if not a.quiet:
        print(f"robot_peer: {frames} frame(s)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
