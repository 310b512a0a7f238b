"""The simulated world: a scene (field, ball, start places) with N ERS-7s in it.

`World(scene, robots)` builds one MuJoCo model from a scene file (default
sim/mujoco/scene.xml) and `robots` copies of sim/mujoco/ers7.xml prefixed r0_, r1_, ...
Robot k starts at the scene's site `start<k>` (position and heading) if there is one,
else in a row behind robot 0 (which stands at the origin facing +x).

Collisions: every robot touches the world (floor, ball, goals) and every other robot,
never itself (MuJoCo would otherwise collide neighbouring leg parts). Robot k's geoms
get contype bit k+1 and conaffinity "world and every other robot"; world geoms
collide with everything. This allows 30 robots (32-bit masks, bit 0 = world).
"""
import copy
import math
import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import mujoco
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENE = os.path.join(HERE, "scene.xml")
FRAME_S = 0.008  # one OPEN-R sensor frame
MAX_ROBOTS = 30
CAMERA_W, CAMERA_H = 416, 320  # ers7-model 9.1: the sensor's resolution
# Rendering detail for software GL (Mesa llvmpipe), whose vertex stage is single-threaded
# and the bound with several robots in view: 10 slices per sphere/capsule instead of
# MuJoCo's 28 and undivided box faces (numquads 1, the lights are directional) give
# 1.6x the images per second of 8 robots (419 -> 661/s); the ball keeps a round outline.
RENDER_SLICES, RENDER_STACKS, RENDER_QUADS = 10, 5, 1
SENSORS_OFF = int(mujoco.mjtDisableBit.mjDSBL_SENSOR)


class SceneError(Exception):
    pass


class RenderError(Exception):
    """Offscreen rendering is not available (no EGL/OSMesa, or a bad MUJOCO_GL)."""


def start_places(scene_path, robots):
    """(x, y, yaw) of each robot: the scene's `start<k>` sites, else a default row."""
    try:
        m = mujoco.MjModel.from_xml_path(scene_path)
    except Exception as e:  # MuJoCo's message names the file, line and problem
        raise SceneError(f"{scene_path}: not a MuJoCo scene: {e}") from None
    if m.nu or any(m.joint(j).name.endswith("root") for j in range(m.njnt)):
        raise SceneError(f"{scene_path}: a scene holds the field only; the peer adds the robots")
    places = []
    for k in range(robots):
        try:
            s = m.site(f"start{k}")
        except KeyError:
            places.append((-0.6 * k, 0.4 * k, 0.0))
            continue
        places.append((float(m.site_pos[s.id][0]), float(m.site_pos[s.id][1]), yaw_of(m.site_quat[s.id])))
    return places


def build_model(scene_path=DEFAULT_SCENE, robots=1):
    if not 1 <= robots <= MAX_ROBOTS:
        raise SceneError(f"{robots} robots: the world holds 1 to {MAX_ROBOTS}")
    places = start_places(scene_path, robots)
    scene = mujoco.MjSpec.from_file(scene_path)
    for k, (x, y, yaw) in enumerate(places):
        robot = mujoco.MjSpec.from_file(os.path.join(HERE, "ers7.xml"))
        frame = scene.worldbody.add_frame(pos=[x, y, 0], quat=[math.cos(yaw / 2), 0, 0, math.sin(yaw / 2)])
        scene.attach(robot, prefix=f"r{k}_", frame=frame)
    m = scene.compile()
    q = m.vis.quality
    q.numslices, q.numstacks, q.numquads = RENDER_SLICES, RENDER_STACKS, RENDER_QUADS
    _collision_masks(m, robots)
    return m, places


def _collision_masks(m, robots):
    every_robot = sum(1 << (k + 1) for k in range(robots))
    roots = {m.body(f"r{k}_trunk").id: k for k in range(robots)}
    for g in range(m.ngeom):
        k = roots.get(m.body_rootid[m.geom_bodyid[g]])
        if k is None:
            if m.geom_contype[g] or m.geom_conaffinity[g]:  # lines and markers stay ghosts
                m.geom_contype[g], m.geom_conaffinity[g] = 1, 1 | every_robot
        else:
            bit = 1 << (k + 1)
            m.geom_contype[g], m.geom_conaffinity[g] = bit, 1 | (every_robot & ~bit)
    # The broadphase first filters body pairs by the OR of their geoms' masks.
    m.body_contype[:] = 0
    m.body_conaffinity[:] = 0
    for g in range(m.ngeom):
        b = m.geom_bodyid[g]
        m.body_contype[b] |= m.geom_contype[g]
        m.body_conaffinity[b] |= m.geom_conaffinity[g]


class Robot:
    """One ERS-7 in the model: joint numbers -> indices, servo gains, sensors, pose."""

    def __init__(self, model, data, prefix):
        self.m, self.d, self.prefix = model, data, prefix
        self.act = {}  # joint number "21" -> (actuator id, qpos adr, dof adr)
        for a in range(model.nu):
            name = model.actuator(a).name
            if name.startswith(prefix + "j"):
                j = model.actuator_trnid[a, 0]
                self.act[name[len(prefix) + 1:]] = (a, model.jnt_qposadr[j], model.jnt_dofadr[j])
        self.root = model.body(prefix + "trunk").id
        root_joint = model.joint(prefix + "root").id
        self.root_q = model.jnt_qposadr[root_joint]
        self.root_v = model.jnt_dofadr[root_joint]
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
        self.set_gain(num, *servo_gains(p, d, self.m.actuator_forcerange[a, 1] / range_rad))

    def target(self, num, rad):
        self.d.ctrl[self.act[num][0]] = rad

    def angle(self, num):
        return self.d.qpos[self.act[num][1]]

    def pose(self, angles):
        """Joints to `angles` (num -> rad), the body level and still, the lowest point just
        on the floor (where the robot starts: x, y and heading are kept)."""
        m, d = self.m, self.d
        for num, v in angles.items():
            if num in self.act:
                d.qpos[self.act[num][1]] = v
                d.ctrl[self.act[num][0]] = v
        yaw = yaw_of(d.qpos[self.root_q + 3:self.root_q + 7])
        d.qpos[self.root_q + 3:self.root_q + 7] = (math.cos(yaw / 2), 0, 0, math.sin(yaw / 2))
        d.qvel[self.root_v:self.root_v + 6] = 0
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

    def place(self):
        """Trunk position (m) and orientation quaternion (w, x, y, z)."""
        q = self.d.qpos[self.root_q:self.root_q + 7]
        return q[:3], q[3:]

    def push(self, force):
        """Apply `force` (N, world frame) at the trunk's centre (zero to stop)."""
        self.d.xfrc_applied[self.root, :3] = force


class World:
    """Model + data + robots, stepped one 8 ms frame at a time, with a camera renderer."""

    def __init__(self, scene=DEFAULT_SCENE, robots=1, camera=True, camera_threads=None):
        self.m, self.places = build_model(scene, robots)
        self.d = mujoco.MjData(self.m)
        mujoco.mj_forward(self.m, self.d)
        self.robots = [Robot(self.m, self.d, f"r{k}_") for k in range(robots)]
        self.substeps = max(1, round(FRAME_S / self.m.opt.timestep))
        self.cameras = Cameras(self.m, self.robots, camera_threads) if camera else None
        self.ball_q = None
        try:
            self.ball_q = self.m.jnt_qposadr[self.m.joint("ball").id]
        except KeyError:
            pass
        self.physics_s = 0.0
        self.frames = self.images = 0

    def close(self):
        if self.cameras is not None:
            self.cameras.close()
            self.cameras = None

    def place_ball(self, x, y):
        if self.ball_q is None:
            raise SceneError("the scene has no ball (a free joint named `ball`)")
        self.d.qpos[self.ball_q:self.ball_q + 2] = (x, y)
        mujoco.mj_forward(self.m, self.d)

    def ball(self):
        return None if self.ball_q is None else self.d.qpos[self.ball_q:self.ball_q + 3]

    def field(self):
        """The scene's fixed shapes as seen from above, for a top-down drawing (the
        view's field, docs/recording.md): each plane or box of the world body with its
        centre, half sizes (m), heading (rad) and colour; the ball's radius."""
        m, d, shapes = self.m, self.d, []
        kinds = {int(mujoco.mjtGeom.mjGEOM_PLANE): "plane", int(mujoco.mjtGeom.mjGEOM_BOX): "box"}
        for g in range(m.ngeom):
            kind = kinds.get(int(m.geom_type[g]))
            if m.geom_bodyid[g] != 0 or kind is None:
                continue
            R = d.geom_xmat[g].reshape(3, 3)
            shapes.append({"kind": kind, "pos": [round(float(v), 5) for v in d.geom_xpos[g]],
                           "size": [round(float(v), 5) for v in m.geom_size[g]],
                           "yaw": round(math.atan2(R[1, 0], R[0, 0]), 5), "rgba": [round(float(v), 3) for v in m.geom_rgba[g]]})
        field = {"shapes": shapes, "robots": len(self.robots)}
        try:
            field["ball_radius"] = round(float(m.geom_size[m.geom("ball").id][0]), 5)
        except KeyError:
            pass
        return field

    def step(self):
        """One frame. Sensors are computed on the last substep only: the readings see
        that one, and nothing in the dynamics reads sensordata (the rangefinders' ray
        casts and the accelerometer's extra pass are most of a robot's sensor cost)."""
        t = time.perf_counter()
        flags = self.m.opt.disableflags
        self.m.opt.disableflags = flags | SENSORS_OFF
        try:
            for _ in range(self.substeps - 1):
                mujoco.mj_step(self.m, self.d)
        finally:
            self.m.opt.disableflags = flags
        mujoco.mj_step(self.m, self.d)
        self.physics_s += time.perf_counter() - t
        self.frames += 1

    def expose(self, robots, deliver):
        """Takes the pictures of the head cameras of `robots` (indices) in the current
        state and develops them on the camera threads while the caller goes on (and may
        step): deliver(robot, rgb) runs on the thread that drew it (rgb: CAMERA_H x
        CAMERA_W x 3, rows from the top). Returns the futures; wait() on them."""
        self.cameras.update(self.d, robots)
        self.images += len(robots)
        return self.cameras.submit(robots, deliver)

    def report(self, wall_s=None):
        sim_s = self.frames * FRAME_S
        if not self.frames:
            return "mujoco peer: no frame simulated"
        rtf = sim_s / self.physics_s if self.physics_s else float("inf")
        line = (f"mujoco peer: {self.frames} frames = {sim_s:.2f} s simulated, {len(self.robots)} robot(s); "
                f"physics {self.physics_s:.2f} s wall -> real-time factor {rtf:.1f}")
        if self.images:
            draw_s = self.cameras.draw_s
            line += (f"; camera {self.images} images ({self.cameras.describe()}) drawn in {draw_s:.2f} s -> "
                     f"{self.images / draw_s:.0f} per second of a thread")
        if wall_s:
            line += f"; whole run {wall_s:.2f} s wall -> {sim_s / wall_s:.2f} x real time"
        return line


def servo_gains(p, d, tau_per_rad):
    """Position actuator kp, kv from (already scaled) P and D gains and the actuator's
    torque limit per radian of software range (bridge.py: gain mapping); numbers or
    numpy arrays."""
    return p / 4 * tau_per_rad, d / 2 * FRAME_S * tau_per_rad


def wait(futures):
    for f in futures:
        f.result()  # re-raises a rendering or delivery error here


def yaw_of(quat):
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


class Cameras:
    """Offscreen head-camera rendering on a pool of threads, each with its own GL context
    (MuJoCo releases the GIL while Mesa renders, so software GL uses every core).

    `update` (the stepping thread, between physics steps) copies what each due camera
    sees into that robot's own MjvScene; `render` draws those scenes on the pool, so the
    drawing never reads MjData. Each scene holds only the geoms whose bounding sphere
    meets the camera's view: software GL pays per geom drawn, seen or not, so culling
    the robots behind and beside a camera makes 8 robots cost what 1 does (2.4 -> 0.8 ms
    per image in a row of 8)."""

    HIDDEN = 5  # a geom group the camera's MjvOption does not show (MuJoCo hides 3-5)

    def __init__(self, model, robots, threads=None):
        # A private copy: culling rewrites its geom groups, never the stepped model's.
        self.m = copy.copy(model)
        self.m.vis.global_.offwidth, self.m.vis.global_.offheight = CAMERA_W, CAMERA_H
        self.groups = self.m.geom_group.copy()
        self.rbound = self.m.geom_rbound.copy()
        self.robots = robots
        self.cams, self.scenes = [], []
        for r in robots:
            cam = mujoco.MjvCamera()
            cam.type, cam.fixedcamid = mujoco.mjtCamera.mjCAMERA_FIXED, r.camera
            self.cams.append(cam)
            self.scenes.append(mujoco.MjvScene(self.m, maxgeom=self.m.ngeom + 100))
        self.vis = mujoco.MjvOption()  # what a camera sees: no rangefinder rays, no sites
        self.vis.flags[mujoco.mjtVisFlag.mjVIS_RANGEFINDER] = 0
        self.vis.sitegroup[:] = 0
        self.vis.geomgroup[self.HIDDEN] = 0
        self.rect = mujoco.MjrRect(0, 0, CAMERA_W, CAMERA_H)
        self.threads = threads or min(len(robots), os.cpu_count() or 1)
        self.local = threading.local()
        self.stats_lock, self.draw_s = threading.Lock(), 0.0
        self.pool = ThreadPoolExecutor(self.threads, thread_name_prefix="camera")
        try:  # one GL context per thread, made now: a missing GL fails before any robot attaches
            self._on_each_thread(self._open)
        except Exception as e:
            self._on_each_thread(self._free)
            self.pool.shutdown()
            raise RenderError(f"cannot render offscreen with MUJOCO_GL={os.environ.get('MUJOCO_GL', '')}: {e}") from None

    def describe(self):
        return f"{CAMERA_W}x{CAMERA_H}, {self.threads} render thread(s)"

    def _on_each_thread(self, fn):
        """Runs fn once on every pool thread (each call holds its thread at a barrier
        until all have started, so no thread takes two)."""
        barrier = threading.Barrier(self.threads)

        def call():
            try:
                fn()
            finally:
                barrier.wait(timeout=10)

        for f in [self.pool.submit(call) for _ in range(self.threads)]:
            f.result()

    def _open(self):
        from mujoco import gl_context  # after MUJOCO_GL is final
        t = self.local
        t.gl = gl_context.GLContext(CAMERA_W, CAMERA_H)
        t.gl.make_current()  # stays current: this thread draws with no other context
        t.ctx = mujoco.MjrContext(self.m, mujoco.mjtFontScale.mjFONTSCALE_100)
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, t.ctx)
        t.raw = np.empty((CAMERA_H, CAMERA_W, 3), np.uint8)  # GL rows: bottom first
        t.rgb = np.empty_like(t.raw)

    def _free(self):
        t = self.local
        if getattr(t, "ctx", None) is not None:
            t.ctx.free()  # EGL frees a context only on the thread that made it
            t.ctx = None
        if getattr(t, "gl", None) is not None:
            t.gl.free()
            t.gl = None

    def update(self, d, robots):
        """Copies the view of each of `robots` (indices) from `d` into its scene."""
        for k in robots:
            cam = self.robots[k].camera
            self.m.geom_group[:] = np.where(self._in_view(d, cam), self.groups, self.HIDDEN)
            mujoco.mjv_updateScene(self.m, d, self.vis, None, self.cams[k], mujoco.mjtCatBit.mjCAT_ALL, self.scenes[k])

    def _in_view(self, d, cam):
        """Geoms whose bounding sphere meets the view pyramid of camera `cam` (planes,
        which have no bound, always)."""
        v = (d.geom_xpos - d.cam_xpos[cam]) @ d.cam_xmat[cam].reshape(3, 3)  # x right, y up, z back
        depth = -v[:, 2]
        ty = math.tan(math.radians(self.m.cam_fovy[cam]) / 2)
        tx = ty * CAMERA_W / CAMERA_H
        r = self.rbound
        return ((r == 0) | ((depth + r > 0)
                            & (np.abs(v[:, 0]) - tx * depth <= r * math.hypot(1, tx))
                            & (np.abs(v[:, 1]) - ty * depth <= r * math.hypot(1, ty))))

    def _draw(self, k, deliver):
        t = self.local
        start = time.perf_counter()
        mujoco.mjr_render(self.rect, self.scenes[k], t.ctx)
        mujoco.mjr_readPixels(t.raw, None, self.rect, t.ctx)
        np.copyto(t.rgb, t.raw[::-1])
        with self.stats_lock:
            self.draw_s += time.perf_counter() - start
        deliver(k, t.rgb)  # t.rgb is reused once deliver returns

    def submit(self, robots, deliver):
        """Draws the scenes of `robots` (updated before) on the pool; deliver(k, rgb)
        runs on the drawing thread. Returns the futures."""
        return [self.pool.submit(self._draw, k, deliver) for k in robots]

    def close(self):
        self._on_each_thread(self._free)
        self.pool.shutdown()
