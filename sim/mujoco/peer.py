#!/usr/bin/env python3
"""MuJoCo peer for cargo-openr: a physics-simulated ERS-7 behind the robot protocol.

Attaches to `cargo openr run --robot-socket PATH` (docs/robot-protocol.md), owns the
clock (lockstep: one 8 ms frame at a time), and for every FRAME

  1. loads the frame's PID gains into the MuJoCo position actuators (mapping below)
     and the joint targets into their controls, ear states into the ear flaps;
  2. steps the physics by 8 ms (4 steps of 2 ms);
  3. answers READINGS: all joint angles, the accelerometer, the paw switches and the
     three distance sensors; in frames that take a camera image (30 fps) it first
     sends an IMAGE rendered offscreen from the head camera at 416 x 320.

The model is sim/mujoco/ers7.xml (estimates listed there), placed in
sim/mujoco/scene.xml (field, ball); --robots N adds N-1 passive robots standing on
the field. At exit the peer prints the real-time factor of the physics and the
rendering speed.

Gain mapping (ers7-model 4.5, robot-api 11). The program's PGAIN/DGAIN with the fixed
shifts give servo coefficients P = PGAIN/4, D = DGAIN/2 (Tekkotsu arithmetic): PWM
counts per count of calibrated angle error (1023 counts over the joint's software
range) and per count of error change per 8 ms frame. With full PWM (1023) = the
servo's torque limit tau_max (ers7.xml E11):
    kp = gain_scale * (PGAIN/4) * tau_max / range            [N m / rad]
    kv = gain_scale * (DGAIN/2) * 0.008 s * tau_max / range  [N m s / rad]
gain_scale (--gain-scale) defaults to 4, an ESTIMATE: with 1 (the bare arithmetic)
the weak leg gains Sony's samples stand on leave movelegs' base posture 20 deg off
after its 1 s move (weak leg J1 P=0x10: kp = 4 * 2.0 / 4.276 = 1.87 N m/rad); with 4
the legs reach it within ~1-2 deg and follow its +-20 deg swing, as the samples
expect of a real ERS-7 (weak J1: kp = 7.5 N m/rad). The actuator's
forcerange clips the output at tau_max like a saturated PWM. IGAIN is not modelled
(a MuJoCo position actuator is PD); the joint's own damping and armature (E12) stay.
A joint is driven only when motor power is on, its gain enabled and P > 0 (protocol
FRAME); otherwise kp = kv = 0 (limp, back-drivable).

    MUJOCO_GL=egl python3 sim/mujoco/peer.py /tmp/robot.sock
    python3 sim/mujoco/peer.py --bench 10            # real-time factor without a runtime
"""
import argparse
import math
import os
import socket
import struct
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
os.environ.setdefault("MUJOCO_GL", "egl")

import numpy as np  # noqa: E402
import mujoco  # noqa: E402
import robot_peer as rp  # noqa: E402  (protocol codec: the reference client)

FRAME_S = 0.008
CAMERA_W, CAMERA_H = 416, 320
ACCEL_MAX = 19613300  # µm/s², ±2 g (ers7-model 5.4)
GAIN_SCALE = 4.0  # estimated, see the gain mapping above
PAW_THRESHOLD_N = 0.5  # estimated: a paw "switch" closes with 0.5 N of contact force
EAR_UP = math.radians(15)  # ers7.xml E10
EAR_KP, EAR_KV = 0.5, 0.005  # estimated: a quick snap within a frame or two
# distance sensors (ers7-model 5.3): locator -> (sensor name in ers7.xml, min µm, max µm)
PSDS = {
    "PRM:/p1-Sensor:p1": ("psd_chest", 100000, 900000),
    "PRM:/r1/c1/c2/c3/p1-Sensor:p1": ("psd_near", 50000, 500000),
    "PRM:/r1/c1/c2/c3/p2-Sensor:p2": ("psd_far", 200000, 1500000),
}
PAWS = {"24": "lf_paw", "34": "lr_paw", "44": "rf_paw", "54": "rr_paw"}
ACCEL = {"PRM:/a1-Sensor:a1": (0, 1.0), "PRM:/a2-Sensor:a2": (1, -1.0), "PRM:/a3-Sensor:a3": (2, 1.0)}
# the "stand" posture of ers7-model 4.7 (deg), held by the passive extra robots
STAND = {"11": -20, "12": 0, "13": 25, "14": -5, "61": 5, "62": 0,
         **{f"{leg}{j}": v for leg in "2345" for j, v in zip("123", (-5, 3, 30))}}
STANDARD_P = {"11": 0x0A, "12": 0x08, "13": 0x08, "14": 0x08, "61": 0x0A, "62": 0x0A,
              **{f"{leg}{j}": p for leg in "2345" for j, p in zip("123", (0x1C, 0x14, 0x1C))}}


def build_model(robots=1):
    """scene.xml with `robots` copies of ers7.xml, prefixed r0_, r1_, ..."""
    scene = mujoco.MjSpec.from_file(os.path.join(HERE, "scene.xml"))
    for k in range(robots):
        robot = mujoco.MjSpec.from_file(os.path.join(HERE, "ers7.xml"))
        # robot 0 at the centre facing +x (the ball ahead); others behind it in a row
        frame = scene.worldbody.add_frame(pos=[-0.6 * k, 0.4 * k, 0])
        scene.attach(robot, prefix=f"r{k}_", frame=frame)
    return scene.compile()


class Robot:
    """One ERS-7 in the MuJoCo model: names -> indices, gains, readings."""

    def __init__(self, model, data, prefix):
        self.m, self.d, self.prefix = model, data, prefix
        self.act = {}  # joint number "21" -> (actuator id, qpos adr, dof adr)
        for a in range(model.nu):
            name = model.actuator(a).name
            if name.startswith(prefix + "j"):
                j = model.actuator_trnid[a, 0]
                self.act[name[len(prefix) + 1:]] = (a, model.jnt_qposadr[j], model.jnt_dofadr[j])
        self.root = model.body(prefix + "trunk").id
        self.root_q = model.jnt_qposadr[model.joint(prefix + "root").id]
        self.geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] != 0
                      and model.body_rootid[model.geom_bodyid[g]] == self.root]
        self.sensor = {model.sensor(s).name[len(prefix):]: model.sensor_adr[s]
                       for s in range(model.nsensor) if model.sensor(s).name.startswith(prefix)}
        self.camera = model.camera(prefix + "eye").id

    def set_gain(self, num, kp, kv):
        a = self.act[num][0]
        self.m.actuator_gainprm[a, 0] = kp
        self.m.actuator_biasprm[a, 1] = -kp
        self.m.actuator_biasprm[a, 2] = -kv

    def servo(self, num, p, d, range_rad=None):
        """kp/kv from (already scaled) P and D gains; range: the software range (rad)."""
        a = self.act[num][0]
        if range_rad is None:
            range_rad = self.m.actuator_ctrlrange[a, 1] - self.m.actuator_ctrlrange[a, 0]
        tau = self.m.actuator_forcerange[a, 1]
        self.set_gain(num, p / 4 * tau / range_rad, d / 2 * FRAME_S * tau / range_rad)

    def angle(self, num):
        return self.d.qpos[self.act[num][1]]

    def pose(self, angles, x=None, y=None):
        """Joints to `angles` (num -> rad), still, the lowest point just on the floor."""
        m, d = self.m, self.d
        for num, v in angles.items():
            if num in self.act:
                d.qpos[self.act[num][1]] = v
                d.ctrl[self.act[num][0]] = v
        if x is not None:
            d.qpos[self.root_q:self.root_q + 2] = (x, y)
        d.qpos[self.root_q + 3:self.root_q + 7] = (1, 0, 0, 0)
        d.qvel[:] = 0
        mujoco.mj_forward(m, d)
        d.qpos[self.root_q + 2] += 0.001 - self.lowest()
        mujoco.mj_forward(m, d)

    def lowest(self):
        m, d, low = self.m, self.d, 1e9
        for g in self.geoms:
            z, R, s = d.geom_xpos[g][2], d.geom_xmat[g].reshape(3, 3), m.geom_size[g]
            t = m.geom_type[g]
            if t == mujoco.mjtGeom.mjGEOM_SPHERE:
                b = z - s[0]
            elif t == mujoco.mjtGeom.mjGEOM_CAPSULE:
                b = z - abs(R[2, 2]) * s[1] - s[0]
            elif t == mujoco.mjtGeom.mjGEOM_BOX:
                b = z - (abs(R[2, 0]) * s[0] + abs(R[2, 1]) * s[1] + abs(R[2, 2]) * s[2])
            else:
                b = z - m.geom_rbound[g]
            low = min(low, b)
        return low

    def value(self, name):
        return self.d.sensordata[self.sensor[name]]

    def accel(self):
        adr = self.sensor["accel"]
        return self.d.sensordata[adr:adr + 3]


class Sim:
    def __init__(self, robots=1, camera=True, gain_scale=None):
        self.m = build_model(robots)
        self.d = mujoco.MjData(self.m)
        self.robots = [Robot(self.m, self.d, f"r{k}_") for k in range(robots)]
        self.substeps = max(1, round(FRAME_S / self.m.opt.timestep))
        self.gain_scale = GAIN_SCALE if gain_scale is None else gain_scale
        self.renderer = mujoco.Renderer(self.m, height=CAMERA_H, width=CAMERA_W) if camera else None
        self.vis = mujoco.MjvOption()  # what the camera sees: no rangefinder rays, no sites
        self.vis.flags[mujoco.mjtVisFlag.mjVIS_RANGEFINDER] = 0
        self.physics_s = self.render_s = 0.0
        self.frames = self.images = 0
        for k, r in enumerate(self.robots[1:], 1):
            stand = {n: math.radians(v) for n, v in STAND.items()}
            r.pose(stand, x=-0.6 * k, y=0.4 * k)
            for n in STAND:
                r.servo(n, self.gain_scale * STANDARD_P[n], self.gain_scale * 1)

    def step(self):
        t = time.perf_counter()
        for _ in range(self.substeps):
            mujoco.mj_step(self.m, self.d)
        self.physics_s += time.perf_counter() - t
        self.frames += 1

    def render(self, robot=0):
        t = time.perf_counter()
        self.renderer.update_scene(self.d, camera=self.robots[robot].camera, scene_option=self.vis)
        rgb = self.renderer.render()
        self.render_s += time.perf_counter() - t
        self.images += 1
        return rgb

    def report(self, wall_s=None, out=sys.stderr):
        sim_s = self.frames * FRAME_S
        if not self.frames:
            return
        rtf = sim_s / self.physics_s if self.physics_s else float("inf")
        line = (f"mujoco peer: {self.frames} frames = {sim_s:.2f} s simulated, {len(self.robots)} robot(s); "
                f"physics {self.physics_s:.2f} s wall -> real-time factor {rtf:.1f}")
        if self.images:
            line += (f"; camera {self.images} images in {self.render_s:.2f} s -> {self.images / self.render_s:.0f} fps, "
                     f"physics+camera real-time factor {sim_s / (self.physics_s + self.render_s):.1f}")
        if wall_s:
            line += f"; whole run {wall_s:.2f} s wall -> {sim_s / wall_s:.2f} x real time"
        print(line, file=out, flush=True)


class Bridge:
    """Protocol primitive IDs <-> robot 0 of the simulation."""

    def __init__(self, sim, welcome):
        self.sim, self.robot = sim, sim.robots[0]
        self.joints, self.ranges, self.ears = {}, {}, {}
        self.accel, self.paws, self.psds = [], [], []
        for p in welcome["primitives"]:
            loc, pid = p["locator"], p["id"]
            num = loc.rsplit(":", 1)[-1]
            if p["class"] == "joint" and num in self.robot.act:
                self.joints[pid] = num
                self.ranges[pid] = max((p["max_urad"] - p["min_urad"]) * 1e-6, 1e-3)
            elif p["class"] == "ear" and num in self.robot.act:
                self.ears[pid] = num
            elif loc in ACCEL:
                self.accel.append((pid,) + ACCEL[loc])
            elif p["class"] == "switch" and num in PAWS:
                self.paws.append((pid, PAWS[num]))
            elif loc in PSDS:
                self.psds.append((pid,) + PSDS[loc])
        # send only what the runtime granted (a role held by another peer is an error)
        granted = set(welcome["roles"])
        if "joints" not in granted:
            self.joints = {}
        if "accel" not in granted:
            self.accel = []
        if "switches" not in granted:
            self.paws = []
        if "psd" not in granted:
            self.psds = []
        self.started = False

    def start(self, frame):
        """First frame: the robot takes the runtime's current joint angles (boot pose)."""
        self.robot.pose({self.joints[j["id"]]: j["measured"] * 1e-6 for j in frame["joints"] if j["id"] in self.joints})
        self.started = True

    def apply(self, frame):
        r, power = self.robot, bool(frame["motor_power"])
        scale = self.sim.gain_scale
        for j in frame["joints"]:
            num = self.joints.get(j["id"])
            if num is None:
                continue
            p, _, d = j["gain"]
            if power and j["enabled"] and p > 0:
                r.servo(num, scale * p, scale * d, self.ranges[j["id"]])
            else:
                r.set_gain(num, 0.0, 0.0)
            self.sim.d.ctrl[r.act[num][0]] = j["target"] * 1e-6
        for e in frame["ears"]:
            num = self.ears.get(e["id"])
            if num is not None:
                r.set_gain(num, EAR_KP if power else 0.0, EAR_KV if power else 0.0)
                self.sim.d.ctrl[r.act[num][0]] = EAR_UP if e["state"] else 0.0

    def readings(self):
        r = self.robot
        joints = [(pid, round(r.angle(num) * 1e6)) for pid, num in self.joints.items()]
        acc = r.accel()
        sensors = [(pid, int(max(-ACCEL_MAX, min(ACCEL_MAX, round(sign * acc[axis] * 1e6)))))
                   for pid, axis, sign in self.accel]
        sensors += [(pid, int(r.value(name) > PAW_THRESHOLD_N)) for pid, name in self.paws]
        for pid, name, lo, hi in self.psds:
            dist = r.value(name)
            um = hi if dist < 0 else min(hi, max(lo, round(dist * 1e6)))  # -1: nothing hit
            sensors.append((pid, int(um)))
        return joints, sensors


def connect(a):
    if a.tcp:
        host, port = a.tcp.rsplit(":", 1)
        sock = socket.create_connection((host, int(port)))
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    else:
        sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        for _ in range(100):  # the runtime may still be starting
            try:
                sock.connect(a.socket)
                break
            except (FileNotFoundError, ConnectionRefusedError):
                time.sleep(0.1)
        else:
            sock.connect(a.socket)
    return sock


def run(a):
    sim = Sim(a.robots, camera=not a.no_camera, gain_scale=a.gain_scale)
    peer = rp.Peer(connect(a))
    roles = rp.ROLE_JOINTS | rp.ROLE_ACCEL | rp.ROLE_SWITCHES | rp.ROLE_PSD
    if not a.no_camera:
        roles |= rp.ROLE_CAMERA
    name = b"sim/mujoco/peer.py"
    peer.send(rp.HELLO, 0, struct.pack("<IIH", roles, rp.FLAG_CLOCK, len(name)) + name)
    kind, _, payload = peer.recv()
    if kind != rp.WELCOME:
        print(f"mujoco peer: expected WELCOME, got type {kind}", file=sys.stderr)
        return 1
    welcome = rp.parse_welcome(payload)
    if not a.quiet:
        print(f"mujoco peer: attached to {welcome['design']}, roles {','.join(welcome['roles'])}, "
              f"clock {welcome['clock']}, camera {welcome['camera_width']}x{welcome['camera_height']}"
              f"@{welcome['camera_fps']}", file=sys.stderr, flush=True)
    if welcome["design"] != "ERS-7":
        print("mujoco peer: only the ERS-7 is modelled", file=sys.stderr)
        return 1
    camera = "camera" in welcome["roles"] and sim.renderer is not None
    bridge = Bridge(sim, welcome)
    wall = time.perf_counter()
    code = 0
    try:
        while True:
            try:
                kind, n, payload = peer.recv()
            except (EOFError, ConnectionResetError):
                break
            if kind == rp.FRAME:
                f = rp.parse_frame(n, payload)
                if not bridge.started:
                    bridge.start(f)
                bridge.apply(f)
                sim.step()
                if camera and f["camera_due"]:
                    rgb = sim.render()
                    peer.send(rp.IMAGE, n, struct.pack("<HH", CAMERA_W, CAMERA_H) + rgb.tobytes())
                joints, sensors = bridge.readings()
                peer.send(rp.READINGS, n, rp.readings_payload(joints, sensors))
                if a.frames and sim.frames >= a.frames:
                    peer.send(rp.BYE, n, struct.pack("<H", 4) + b"done")
                    break
            elif kind == rp.BYE:
                break
            elif kind == rp.ERROR:
                r = rp.Reader(payload)
                c = r.get("H")
                print(f"mujoco peer: runtime error {c}: {r.str()}", file=sys.stderr)
                code = 2
                break
    finally:
        peer.sock.close()
        sim.report(time.perf_counter() - wall)
    return code


def bench(a):
    """Stand up from the sleep pose with the standard gains and hold it: a fixed load."""
    sim = Sim(a.robots, camera=not a.no_camera, gain_scale=a.gain_scale)
    r = sim.robots[0]
    r.pose({n: math.radians(v) for n, v in STAND.items()})
    for n in STAND:
        r.servo(n, sim.gain_scale * STANDARD_P[n], sim.gain_scale * 1)
        sim.d.ctrl[r.act[n][0]] = math.radians(STAND[n])
    frames = round(a.bench / FRAME_S)
    for k in range(frames):
        sim.step()
        if sim.renderer is not None and (k * 8) % 33 < 8:  # every 1/30 s, as the runtime asks
            sim.render()
    print(f"mujoco peer bench: trunk height {sim.d.xpos[r.root][2]:.3f} m, accel "
          f"{np.round(r.accel(), 2).tolist()} m/s^2, LF J1/J2/J3 "
          f"{[round(math.degrees(r.angle(n)), 1) for n in ('21', '22', '23')]} deg, paws "
          f"{[int(r.value(p) > PAW_THRESHOLD_N) for p in PAWS.values()]}, near PSD {r.value('psd_near'):.3f} m",
          file=sys.stderr)
    sim.report()
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("socket", nargs="?", help="the runtime's --robot-socket path")
    ap.add_argument("--tcp", metavar="HOST:PORT", help="attach over TCP instead (the runtime's --robot-tcp)")
    ap.add_argument("--no-camera", action="store_true", help="do not render the head camera (the runtime's scene is used)")
    ap.add_argument("--robots", type=int, default=1, help="robots on the field (robot 0 is the program's; others stand)")
    ap.add_argument("--gain-scale", type=float, default=GAIN_SCALE, help=f"multiply kp/kv of the gain mapping (default {GAIN_SCALE}, estimated)")
    ap.add_argument("--frames", type=int, default=0, help="detach (BYE) after this many frames")
    ap.add_argument("--bench", type=float, metavar="SECONDS", help="no runtime: simulate SECONDS standing, print the real-time factor")
    ap.add_argument("--quiet", action="store_true")
    a = ap.parse_args()
    if a.bench:
        return bench(a)
    if not (a.socket or a.tcp):
        ap.error("give a socket path, --tcp HOST:PORT or --bench SECONDS")
    return run(a)


if __name__ == "__main__":
    sys.exit(main())
