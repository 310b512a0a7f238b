"""READINGS payloads of all robots built with numpy in one go.

Per robot and frame, a loop over its sensors in Python cost more than the physics
of a robot's frame; here every robot with the same sensor layout is one row of a few
numpy arrays, so a frame of 8 robots is a fixed handful of array operations.

Byte for byte what a per-sensor Python loop would send (bridge.py defines the values):
  * joint angles: rint(qpos * 1e6) µrad;
  * accelerometer (MuJoCo axes x y z, noise sigma ACCEL_SIGMA): each reported axis
    clamp(rint(sign * (a + noise) * 1e6)) µm/s² to the WELCOME's range;
  * paw switches: contact force > PAW_THRESHOLD_N;
  * distance sensors: the far end when nothing is hit (-1), else
    clamp(rint((d + noise) * 1e6)) µm.
rint rounds half to even, as Python's round() does. The noise keeps each robot's own
seeded stream in the same order (per frame 3 accelerometer draws, then one per distance
sensor): numpy's Generator draws normals one after another whatever the block size,
so drawing BLOCK frames at a time gives the same numbers.
"""
import numpy as np

PAW_THRESHOLD_N = 0.5  # estimated: a paw "switch" closes with 0.5 N of contact force
ACCEL_SIGMA = 0.05  # m/s², estimated
PSD_SIGMA = 0.001  # m, estimated
BLOCK = 256  # frames of noise drawn at once
READING = np.dtype([("id", "<u4"), ("value", "<i4")])


class Layout:
    """One robot's READINGS: what to read and how (from its Bridge)."""

    def __init__(self, joint_ids, joint_q, accel, paws, psds, sensor_adr, rng):
        self.joint_ids, self.joint_q = np.asarray(joint_ids, np.uint32), np.asarray(joint_q, np.intp)
        self.accel_ids = [a[0] for a in accel]  # (id, axis, sign, lo, hi)
        self.axis = np.array([a[1] for a in accel], np.intp)
        self.sign = np.array([a[2] for a in accel], float)
        self.accel_lo, self.accel_hi = np.array([a[3] for a in accel], float), np.array([a[4] for a in accel], float)
        self.paw_ids = [p[0] for p in paws]
        self.psd_ids = [p[0] for p in psds]  # (id, name, lo, hi)
        self.psd_lo, self.psd_hi = np.array([p[2] for p in psds], float), np.array([p[3] for p in psds], float)
        self.sensor_adr = np.asarray(sensor_adr, np.intp)  # accel x y z, paws, PSDs
        self.rng = rng

    def shape(self):
        return len(self.joint_ids), len(self.accel_ids), len(self.paw_ids), len(self.psd_ids)


class Group:
    """Robots with the same counts of joints and sensors: one row each. The output
    records, their value columns and the index arrays are made once; a frame is a
    dozen numpy calls whatever the number of robots."""

    def __init__(self, robots, layouts, kept):
        self.robots = robots  # robot indices, one per row
        self.layouts = layouts
        m = len(robots)
        j, a, p, d = layouts[0].shape()
        self.a, self.p, self.d = a, p, d
        self.dtype = np.dtype([("nj", "<u2"), ("joints", READING, (j,)), ("ns", "<u2"), ("sensors", READING, (a + p + d,))])
        self.out = out = np.zeros(m, self.dtype)
        out["nj"], out["ns"] = j, a + p + d
        out["joints"]["id"] = [lay.joint_ids for lay in layouts]
        out["sensors"]["id"] = [lay.accel_ids + lay.paw_ids + lay.psd_ids for lay in layouts]
        self.joints = out["joints"]["value"]  # views, looked up once
        sensors = out["sensors"]["value"]
        self.accel, self.paws, self.psds = sensors[:, :a], sensors[:, a:a + p], sensors[:, a + p:]
        stack = lambda name: np.array([getattr(lay, name) for lay in layouts])  # noqa: E731
        self.joint_q, self.sensor_adr, self.sign = stack("joint_q"), stack("sensor_adr"), stack("sign")
        # each reported axis as an index into the (m, 3) accelerations, flattened
        self.axis = (stack("axis") + 3 * np.arange(m)[:, None]).astype(np.intp)
        self.accel_lo, self.accel_hi, self.psd_lo, self.psd_hi = stack("accel_lo"), stack("accel_hi"), stack("psd_lo"), stack("psd_hi")
        # noise, scaled (accel x y z, PSDs): frame `at` of the block is noise[:, at]
        self.noise, self.at = np.empty((m, BLOCK, 3 + d)), BLOCK
        self._refill(kept)

    def _refill(self, kept=None):
        """A new block for every row: a robot's rows not used yet (kept: robot -> rows,
        from its former group) first, then new draws of its stream."""
        for r, (k, lay) in enumerate(zip(self.robots, self.layouts)):
            rest = kept.pop(k, None) if kept is not None else None
            n = 0 if rest is None else len(rest)
            if n:
                self.noise[r, :n] = rest
            z = lay.rng.standard_normal((BLOCK - n, 3 + self.d))
            # 0.0 + sigma * z: Generator.normal(0, sigma) computes exactly this
            self.noise[r, n:, :3] = 0.0 + ACCEL_SIGMA * z[:, :3]
            self.noise[r, n:, 3:] = 0.0 + PSD_SIGMA * z[:, 3:]
        self.at = 0

    def unused(self):
        """robot -> its noise rows not used yet."""
        return {k: self.noise[r, self.at:].copy() for r, k in enumerate(self.robots)}

    def build(self, qpos, sensordata):
        """Every row's payload (bytes) from the current state."""
        if self.at == BLOCK:
            self._refill()
        noise = self.noise[:, self.at]
        self.at += 1
        np.rint(qpos[self.joint_q] * 1e6, out=self.joints, casting="unsafe")
        values = sensordata[self.sensor_adr]
        if self.a:
            acc = (values[:, :3] + noise[:, :3]).take(self.axis)
            self.accel[:] = np.maximum(self.accel_lo, np.minimum(self.accel_hi, np.rint(self.sign * acc * 1e6)))
        if self.p:
            self.paws[:] = values[:, 3:3 + self.p] > PAW_THRESHOLD_N
        if self.d:
            dist = values[:, 3 + self.p:]
            near = np.minimum(self.psd_hi, np.maximum(self.psd_lo, np.rint((dist + noise[:, 3:]) * 1e6)))
            self.psds[:] = np.where(dist < 0, self.psd_hi, near)  # -1: nothing hit
        raw, size = self.out.tobytes(), self.dtype.itemsize
        return [raw[i * size:(i + 1) * size] for i in range(len(self.robots))]


class Replies:
    """READINGS for a set of robots (robot index -> Layout), built all at once.

    Each call draws one frame of noise for every robot it builds, as a per-robot loop
    would. The robots asked for are the same frame after frame (until a runtime
    leaves): their rows are grouped once per set."""

    def __init__(self, layouts, qpos, sensordata):
        self.layouts, self.qpos, self.sensordata = layouts, qpos, sensordata  # MuJoCo's arrays, looked up once
        self.key, self.groups = None, []
        self.kept = {}  # robot -> its noise rows not used yet, while it is in no group

    def build(self, robots):
        """{robot: READINGS payload} for `robots` (indices) in the current state."""
        key = tuple(robots)
        if key != self.key:
            self._regroup(key)
        out = {}
        for g in self.groups:
            out.update(zip(g.robots, g.build(self.qpos, self.sensordata)))
        return out

    def _regroup(self, key):
        for g in self.groups:  # the noise each robot has drawn goes on in its new group
            self.kept.update(g.unused())
        by_shape = {}
        for k in key:
            by_shape.setdefault(self.layouts[k].shape(), []).append(k)
        self.groups = [Group(ks, [self.layouts[k] for k in ks], self.kept) for ks in by_shape.values()]
        self.key = key
