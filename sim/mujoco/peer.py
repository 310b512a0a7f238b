#!/usr/bin/env python3
"""MuJoCo peer for cargo-openr: physics-simulated ERS-7s behind the robot protocol.

Attaches to one or more runtimes (`cargo openr run --robot-socket PATH --robot-wait`,
docs/robot-protocol.md) -- runtime k drives robot k of one shared world -- and owns
their clocks (lockstep). Every 8 ms frame it

  1. waits for the FRAME of every attached runtime; loads each frame's PID gains into
     its robot's position actuators (bridge.py: gain mapping), its joint targets into
     their controls and its ear states into the ear flaps;
  2. steps the physics of the whole world by 8 ms (4 steps of 2 ms);
  3. answers each runtime with READINGS: joint angles, accelerometer, paw switches,
     distance sensors -- in frames that take a camera image (30 fps) after the IMAGE
     of its head camera (416 x 320, offscreen), exposed as the frame began and drawn
     on a camera thread while the runtime worked on the frame before (serve()).

The world (world.py) is a scene (default sim/mujoco/scene.xml: field, goals, ball) with
the robots in it; robots beyond the attached runtimes stand still in the stand posture.
The run is deterministic: the same programs, scene, seed and options give the same
readings, byte for byte. At exit the peer prints the real-time factor of the physics
and the rendering speed.

    MUJOCO_GL=egl python3 sim/mujoco/peer.py /tmp/r0.sock [/tmp/r1.sock ...]
    python3 sim/mujoco/peer.py --bench 10 --robots 4  # real-time factor, no runtime
"""
import argparse
import json
import os
import signal
import socket
import struct
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
# No __pycache__ beside the sources: sdk-runtime embeds this directory, and a new cache
# file there would rebuild the runtime and reinstall the SDK root.
sys.dont_write_bytecode = True
os.environ.setdefault("MUJOCO_GL", "egl")
# Mesa's llvmpipe draws on the calling thread: the camera threads are the parallelism,
# and llvmpipe's own raster threads would only compete with them and the runtimes for
# the cores (paired runs: 1 robot 16.8-17.2x -> 17.0-18.2x, 8 robots 2.2-2.9x -> 2.5-3.0x).
os.environ.setdefault("LP_NUM_THREADS", "0")
# numpy's BLAS would start a thread per core for the camera culling's small matrix
# products and spin them between frames: the cores belong to the physics, the cameras
# and the runtimes. Must be set before numpy is imported.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import robot_peer as rp  # noqa: E402  (protocol codec: the reference client)

# Exit status 3: MuJoCo or offscreen GL is not usable here (cargo openr says how to install).
UNAVAILABLE = 3
try:
    from bridge import GAIN_SCALE, Bridge, Frame, stand  # noqa: E402  (these import numpy and mujoco)
    from world import CAMERA_H, CAMERA_W, DEFAULT_SCENE, FRAME_S, RenderError, SceneError, World, wait  # noqa: E402
    from fieldcam import FieldCamera  # noqa: E402
    from replies import Replies  # noqa: E402
    from wire import BadHeader, Wire  # noqa: E402
except (ImportError, RuntimeError) as e:  # RuntimeError: mujoco rejects MUJOCO_GL
    print(f"mujoco peer: error: {sys.executable} cannot import MuJoCo: {e}", file=sys.stderr)
    sys.exit(UNAVAILABLE)

PUSH_S = 0.1  # a --push lasts 100 ms
# IMAGE: the protocol header and the picture's size, then the RGB bytes (sent without a copy)
IMAGE_HEAD = struct.Struct(rp.HEADER.format + "HH")
IMAGE_SIZE = 4 + CAMERA_W * CAMERA_H * 3


def send_parts(sock, parts):
    """sendall for a list of buffers (sendmsg may take only part of them)."""
    parts = [memoryview(p) for p in parts]
    while parts:
        sent = sock.sendmsg(parts)
        while parts and sent >= len(parts[0]):
            sent -= len(parts[0])
            parts.pop(0)
        if parts:
            parts[0] = parts[0][sent:]


class Link:
    """One runtime connection and the robot it drives."""

    def __init__(self, sock, index):
        self.peer, self.index = Wire(sock), index
        self.bridge = self.frame = None
        self.camera = False
        self.open = True

    def hello(self, want_camera, quiet):
        roles = rp.ROLE_JOINTS | rp.ROLE_ACCEL | rp.ROLE_SWITCHES | rp.ROLE_PSD
        if want_camera:
            roles |= rp.ROLE_CAMERA
        name = f"sim/mujoco/peer.py robot {self.index}".encode()
        self.peer.send(rp.HELLO, 0, struct.pack("<IIH", roles, rp.FLAG_CLOCK, len(name)) + name)
        try:
            kind, _, payload = self.recv()
        except (EOFError, ConnectionResetError):
            raise ProtocolError(f"robot {self.index}: the runtime closed the connection before its WELCOME") from None
        if kind != rp.WELCOME:
            raise ProtocolError(f"robot {self.index}: expected WELCOME, got message type {kind}")
        w = rp.parse_welcome(payload)
        if not quiet:
            print(f"mujoco peer: robot {self.index} attached to {w['design']}, roles {','.join(w['roles'])}, "
                  f"clock {w['clock']}", file=sys.stderr, flush=True)
        if w["design"] != "ERS-7":
            raise ProtocolError(f"robot {self.index}: the runtime runs an {w['design']}; only the ERS-7 is modelled")
        if not w["clock"]:
            raise ProtocolError(f"robot {self.index}: another peer owns the runtime's clock")
        self.camera = want_camera and "camera" in w["roles"]
        return w

    def next_frame(self):
        """The runtime's next FRAME (parsed), or None once it has left."""
        while self.open:
            try:
                kind, n, payload = self.recv()
            except (EOFError, ConnectionResetError):
                break
            if kind == rp.FRAME:
                try:
                    return Frame(n, payload)
                except ValueError as e:
                    raise ProtocolError(f"robot {self.index}: {e}") from None
            if kind == rp.BYE:
                break
            if kind == rp.ERROR:
                r = rp.Reader(payload)
                code = r.get("H")
                raise ProtocolError(f"robot {self.index}: runtime error {code}: {r.str()}")
        self.close()
        return None

    def recv(self):
        try:
            return self.peer.recv()
        except BadHeader as e:
            raise ProtocolError(f"robot {self.index}: {e}") from None

    def close(self):
        if self.open:
            self.open = False
            self.peer.sock.close()


class ProtocolError(Exception):
    pass


def connect(path=None, tcp=None):
    if tcp:
        host, port = tcp.rsplit(":", 1)
        sock = socket.create_connection((host, int(port)))
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        return sock
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    # Room for two whole pictures: a camera thread hands its IMAGE to the kernel and is
    # free, instead of waiting for the runtime to read it (the kernel caps this at
    # net.core.wmem_max).
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 2 * IMAGE_SIZE)
    deadline = time.monotonic() + 60  # the runtime may still be loading its objects
    while True:
        try:
            sock.connect(path)
            return sock
        except (FileNotFoundError, ConnectionRefusedError):
            if time.monotonic() > deadline:
                raise
            time.sleep(0.05)


class Pushes:
    """--push T:FX,FY,FZ[@ROBOT]: a 100 ms shove of the trunk starting at virtual time T."""

    def __init__(self, specs, robots):
        self.items = []
        for s in specs:
            try:
                when, rest = s.split(":", 1)
                force, _, who = rest.partition("@")
                f = [float(v) for v in force.split(",")]
                k = int(who) if who else 0
                if len(f) != 3 or not 0 <= k < robots:
                    raise ValueError
            except ValueError:
                raise SceneError(f"--push {s}: expected TIME:FX,FY,FZ[@ROBOT] (seconds, newtons, robot 0..{robots - 1})") from None
            self.items.append((float(when), f, k))

    def apply(self, world, t):
        """Forces for the frame that starts at virtual time t (s); pushes that overlap on
        one robot add up."""
        if not self.items:
            return
        force = [[0.0, 0.0, 0.0] for _ in world.robots]
        for when, f, k in self.items:
            if when <= t < when + PUSH_S:
                force[k] = [a + b for a, b in zip(force[k], f)]
        for r, f in zip(world.robots, force):
            r.push(f)


def camera_pose(world, k):
    """Robot k's head camera: position and orientation (MuJoCo camera frame: looks
    along -z, x right, y up; xmat row-major)."""
    cam = world.robots[k].camera
    return {"pos": _r(world.d.cam_xpos[cam]), "xmat": _r(world.d.cam_xmat[cam])}


def state_line(world, frame, t_ms, pictures):
    """Ground truth for --state at the end of a frame: every robot's trunk position and
    orientation, its head camera's pose, the ball; for a robot whose camera took a
    picture in the frame also `picture`, the camera's pose when it was exposed (as
    the frame began)."""
    robots = []
    for k, r in enumerate(world.robots):
        pos, quat = r.place()
        robots.append({"pos": _r(pos), "quat": _r(quat), "camera": camera_pose(world, k)})
        if k in pictures:
            robots[-1]["picture"] = pictures[k]
    line = {"frame": frame, "time_ms": t_ms, "robots": robots}
    ball = world.ball()
    if ball is not None:
        line["ball"] = _r(ball)
    return json.dumps(line)


def _r(values):
    return [round(float(v), 5) for v in values]


def parse_xy(s):
    try:
        x, y = (float(v) for v in s.split(","))
        return x, y
    except ValueError:
        raise argparse.ArgumentTypeError(f"`{s}`: expected X,Y in metres (e.g. 0.3,0)") from None


def make_world(a, links):
    robots = max(a.robots or 1, links)
    world = World(a.scene, robots, camera=not a.no_camera, camera_threads=a.camera_threads)
    try:
        for r in world.robots[links:]:
            stand(r, a.gain_scale)
        if a.ball:
            world.place_ball(*a.ball)
    except Exception:
        world.close()
        raise
    return world


def run(a):
    # Ctrl-C reaches the runtimes too: they stop, close their connections, and the peer
    # ends after the last one (reporting) instead of dying with a traceback.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    targets = [(p, None) for p in a.socket] or [(None, a.tcp)]
    pushes = Pushes(a.push, max(a.robots or 1, len(targets)))  # option errors before the world
    world = make_world(a, len(targets))  # scene errors before attaching
    links, state, fieldcam, wall = [], None, None, time.perf_counter()
    try:
        links = [Link(connect(p, t), k) for k, (p, t) in enumerate(targets)]
        for link in links:
            w = link.hello(not a.no_camera, a.quiet)
            link.bridge = Bridge(world.robots[link.index], w, a.gain_scale, a.seed, link.index)
        if a.field:
            with open(a.field, "w") as f:
                f.write(json.dumps(world.field()) + "\n")
        # Line by line: a live view (cargo openr run --view) follows the file.
        state = open(a.state, "w", buffering=1) if a.state else None
        if a.field_camera or a.field_pictures:
            fieldcam = FieldCamera(world, a.field_camera, a.field_pictures)
        wall = time.perf_counter()
        serve(a, world, links, pushes, state, fieldcam)
    except (BrokenPipeError, ConnectionResetError):
        pass  # a runtime ended between its FRAME and our answer
    finally:
        for link in links:
            link.close()
        if state:
            state.close()
        if fieldcam:
            fieldcam.close()
        report = world.report(time.perf_counter() - wall)
        world.close()
        if not a.quiet:
            print(report, file=sys.stderr, flush=True)
    return 0


def serve(a, world, links, pushes, state, fieldcam=None):
    """The lockstep: one FRAME from every attached runtime, one physics step, answers.

    Pictures show the state a camera frame begins with. A FRAME announcing a picture in
    the next frame (flag camera_next) has it exposed right after this frame's step and
    drawn on a camera thread while the runtime works; the IMAGE goes out the moment it is
    drawn, and the READINGS of its frame wait for it. A picture nobody announced (the
    first frame, an older runtime) is exposed as its frame begins, alongside the step."""
    ahead, ahead_poses = [], {}  # pictures exposed for the next frame, their camera poses
    early = {}  # --pipeline: robot -> READINGS of the state the next frame begins with
    replies = Replies({link.index: link.bridge.readings_layout() for link in links}, world.d.qpos, world.d.sensordata)
    while True:
        live = [(link, link.next_frame()) for link in links if link.open]
        live = [(link, f) for link, f in live if f is not None]
        if not live:
            return
        for link, f in live:
            if not link.bridge.started:
                link.bridge.start(f)
                if a.pipeline:
                    early.update(replies.build([link.index]))  # before the next robot's start pose
        due = {link.index for link, f in live if link.camera and f.camera_due}
        pictures, poses = ahead, ahead_poses
        late = {link.index: f.frame for link, f in live if link.index in due and link.index not in poses}
        if late:
            pictures = pictures + take_pictures(world, links, late)
            poses = {**poses, **{k: camera_pose(world, k) for k in late}}
        if a.pipeline:
            # The state the frame begins with, answered before the step: the runtime runs
            # its objects while the physics steps (the frame's commands show one frame on).
            answer(live, due, pictures, lambda link: early[link.index])
        for link, f in live:
            link.bridge.apply(f)
        t_ms = live[0][1].time_ms
        pushes.apply(world, t_ms / 1000.0)
        world.step()
        if a.pipeline:
            early = replies.build([link.index for link, f in live])
        else:
            now = replies.build([link.index for link, f in live])
            answer(live, due, pictures, lambda link: now[link.index])
        if state:
            state.write(state_line(world, live[0][1].frame, t_ms, poses) + "\n")
        if fieldcam and fieldcam.due(t_ms):
            fieldcam.shoot(world.d, live[0][1].frame, t_ms)
        if a.frames and world.frames >= a.frames:
            for link, f in live:
                link.peer.send(rp.BYE, f.frame, struct.pack("<H", 4) + b"done")
            return
        # The state now is the one the next frame begins with.
        soon = {link.index: (f.frame + 1) & 0xFFFFFFFF for link, f in live if link.camera and f.camera_next}
        ahead = take_pictures(world, links, soon) if soon else []
        ahead_poses = {k: camera_pose(world, k) for k in soon}


def answer(live, due, pictures, readings):
    """READINGS for every live robot (readings(link): its payload); a robot whose camera
    took a picture in the frame gets them once the picture has gone out."""
    for link, f in live:
        if link.index not in due:
            link.peer.send(rp.READINGS, f.frame, readings(link))
    wait(pictures)
    for link, f in live:
        if link.index in due:
            link.peer.send(rp.READINGS, f.frame, readings(link))


def take_pictures(world, links, frames):
    """Exposes the cameras of the robots in `frames` (robot -> frame number of the
    picture) now; each IMAGE is sent from the camera thread that draws it. Returns the
    futures."""

    def deliver(k, rgb):
        send_parts(links[k].peer.sock, [IMAGE_HEAD.pack(rp.MAGIC, rp.VERSION, rp.IMAGE, IMAGE_SIZE, frames[k], CAMERA_W, CAMERA_H),
                                        memoryview(rgb).cast("B")])

    return world.expose(list(frames), deliver)


def bench(a):
    """No runtime: all robots stand up from the stand pose with the standard gains and
    hold it for a.bench seconds, each head camera rendered at 30 fps: a fixed load. The
    cameras are timed as `cargo openr run --sim` times them (robot k's phase (k mod 4)
    x 8 ms) and drawn while the physics steps, as in a run."""
    world = make_world(a, 0)
    frames = round(a.bench / FRAME_S)
    wall = time.perf_counter()

    def images(n, k):  # the runtime's frame clock: pictures taken by the end of frame n
        return (n * 8 + (k % 4) * 8) * 30 // 1000

    for n in range(1, frames + 1):
        due = [k for k in range(len(world.robots)) if images(n, k) > images(n - 1, k)]
        pictures = world.expose(due, lambda robot, rgb: None) if world.cameras is not None and due else []
        world.step()
        wait(pictures)
    pos, _ = world.robots[0].place()
    print(f"mujoco peer bench: robot 0 trunk height {pos[2]:.3f} m", file=sys.stderr)
    print(world.report(time.perf_counter() - wall), file=sys.stderr)
    world.close()
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("socket", nargs="*", help="runtime k's --robot-socket path drives robot k")
    ap.add_argument("--tcp", metavar="HOST:PORT", help="attach to one runtime over TCP instead (its --robot-tcp)")
    ap.add_argument("--scene", default=DEFAULT_SCENE, help="MuJoCo scene file: field, objects, `start<k>` sites (default sim/mujoco/scene.xml)")
    ap.add_argument("--robots", type=int, help="robots in the world (default: one per runtime; the others stand)")
    ap.add_argument("--no-camera", action="store_true", help="do not render the head cameras (the runtime's scene is used)")
    ap.add_argument("--camera-threads", type=int, help="render threads (default: one per core, at most one per robot)")
    ap.add_argument("--gain-scale", type=float, default=GAIN_SCALE, help=f"multiply kp/kv of the gain mapping (default {GAIN_SCALE}, estimated)")
    ap.add_argument("--seed", type=int, default=0, help="seed of the sensor noise (default 0)")
    ap.add_argument("--ball", type=parse_xy, metavar="X,Y", help="put the ball here (m; robot 0 starts at 0,0 facing +x)")
    ap.add_argument("--push", action="append", default=[], metavar="T:FX,FY,FZ[@ROBOT]", help="shove a robot's trunk for 100 ms at virtual time T s with this force (N)")
    ap.add_argument("--state", metavar="FILE", help="write the ground truth (trunk and camera poses, ball) of every frame as JSON lines")
    ap.add_argument("--field", metavar="FILE", help="write the scene's fixed shapes seen from above (planes, boxes; the ball's radius) as JSON")
    ap.add_argument("--field-camera", metavar="FILE", help="the field camera's newest picture (PNG, replaced 5 times a second of virtual time)")
    ap.add_argument("--field-pictures", metavar="DIR", help="keep every picture of the field camera here (NNNNNN.png, index.jsonl)")
    ap.add_argument("--pipeline", action="store_true",
                    help="answer each frame with the state it begins with and step the physics while the runtime works "
                         "(faster; a command shows in the readings one frame later)")
    ap.add_argument("--frames", type=int, default=0, help="detach (BYE) after this many frames")
    ap.add_argument("--bench", type=float, metavar="SECONDS", help="no runtime: simulate SECONDS standing, print the real-time factor")
    ap.add_argument("--quiet", action="store_true")
    a = ap.parse_args()
    try:
        if a.bench:
            return bench(a)
        if not (a.socket or a.tcp):
            ap.error("give the runtimes' socket paths, --tcp HOST:PORT or --bench SECONDS")
        return run(a)
    except RenderError as e:
        print(f"mujoco peer: error: {e}", file=sys.stderr)
        return UNAVAILABLE
    except (SceneError, ProtocolError) as e:
        print(f"mujoco peer: error: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"mujoco peer: error: cannot attach: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
