"""One runtime's robot: protocol primitive IDs <-> a Robot of the World.

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
expect of a real ERS-7 (weak J1: kp = 7.5 N m/rad). The actuator's forcerange clips
the output at tau_max like a saturated PWM. IGAIN is not modelled (a MuJoCo position
actuator is PD); the joint's own damping and armature (ers7.xml E12) stay. A joint is
driven only when motor power is on, its gain enabled and P > 0 (protocol FRAME);
otherwise kp = kv = 0 (limp, back-drivable).

Sensor noise (seeded, so a run is reproducible for a given --seed): ESTIMATES, the
spec gives none -- accelerometer sigma 0.05 m/s^2 per axis (a MEMS part of the era at
125 Hz), distance sensors sigma 1 mm. Joint angles are reported exactly. replies.py
builds the READINGS (every robot at once, with numpy).
"""
import math
import struct

import numpy as np

from replies import Layout
from robot_peer import FRAME_CAMERA_DUE, FRAME_CAMERA_NEXT
from world import servo_gains

GAIN_SCALE = 4.0  # estimated, see above
EAR_UP = math.radians(15)  # ers7.xml E10
EAR_KP, EAR_KV = 0.5, 0.005  # estimated: a quick snap within a frame or two
# distance sensors (ers7-model 5.3): locator -> sensor name in ers7.xml; their ranges
# (and the accelerometer's) come with the WELCOME (revision 2)
PSDS = {
    "PRM:/p1-Sensor:p1": "psd_chest",
    "PRM:/r1/c1/c2/c3/p1-Sensor:p1": "psd_near",
    "PRM:/r1/c1/c2/c3/p2-Sensor:p2": "psd_far",
}
PAWS = {"24": "lf_paw", "34": "lr_paw", "44": "rf_paw", "54": "rr_paw"}
# accelerometer locator -> (MuJoCo axis, sign): a1 forward, a2 right (MuJoCo y is left), a3 up
ACCEL = {"PRM:/a1-Sensor:a1": (0, 1.0), "PRM:/a2-Sensor:a2": (1, -1.0), "PRM:/a3-Sensor:a3": (2, 1.0)}
# the "stand" posture of ers7-model 4.7 (deg) and the standard P gains, for robots
# without a program (bench) -- keys are OPEN-R joint numbers
STAND = {"11": -20, "12": 0, "13": 25, "14": -5, "61": 5, "62": 0,
         **{f"{leg}{j}": v for leg in "2345" for j, v in zip("123", (-5, 3, 30))}}
STANDARD_P = {"11": 0x0A, "12": 0x08, "13": 0x08, "14": 0x08, "61": 0x0A, "62": 0x0A,
              **{f"{leg}{j}": p for leg in "2345" for j, p in zip("123", (0x1C, 0x14, 0x1C))}}


def stand(robot, gain_scale=GAIN_SCALE):
    """Put a robot without a program in the stand posture, servos holding it."""
    robot.pose({n: math.radians(v) for n, v in STAND.items()})
    for n in STAND:
        robot.servo(n, gain_scale * STANDARD_P[n], gain_scale * 1)


# FRAME payload (docs/robot-protocol.md) read with numpy: one frame of 8 robots is
# parsed and applied in tens of microseconds, not milliseconds of per-field Python.
FRAME_HEAD = struct.Struct("<QBBBBH")  # time_ms, flags, motor_power, face_mode, reserved, joint count
JOINT = np.dtype([("id", "<u4"), ("target", "<i4"), ("measured", "<i4"), ("p", "<u2"), ("i", "<u2"),
                  ("d", "<u2"), ("enabled", "u1"), ("reserved", "u1")])
EAR = np.dtype([("id", "<u4"), ("state", "<u4")])
LED_SIZE = 8
COUNT = struct.Struct("<H")


class Frame:
    """One FRAME: number, time, camera due (now / next frame), motor power, joints and
    ears (numpy records)."""

    __slots__ = ("frame", "time_ms", "camera_due", "camera_next", "motor_power", "joints", "ears")

    def __init__(self, frame, payload):
        try:
            self.time_ms, flags, power, _, _, n = FRAME_HEAD.unpack_from(payload, 0)
            at = FRAME_HEAD.size
            self.joints = np.frombuffer(payload, JOINT, n, at)
            at += n * JOINT.itemsize
            (leds,) = COUNT.unpack_from(payload, at)
            at += COUNT.size + leds * LED_SIZE
            (ears,) = COUNT.unpack_from(payload, at)
            self.ears = np.frombuffer(payload, EAR, ears, at + COUNT.size)
        except (struct.error, ValueError):
            raise ValueError(f"malformed FRAME {frame} ({len(payload)} bytes)") from None
        self.frame, self.motor_power = frame, bool(power)
        self.camera_due, self.camera_next = bool(flags & FRAME_CAMERA_DUE), bool(flags & FRAME_CAMERA_NEXT)


class Bridge:
    def __init__(self, robot, welcome, gain_scale=GAIN_SCALE, seed=0, index=0):
        self.robot, self.gain_scale = robot, gain_scale
        self.rng = np.random.default_rng([seed, index])
        self.joints, self.ranges, self.ears = {}, {}, {}
        self.accel, self.paws, self.psds = [], [], []
        granted = set(welcome["roles"])
        if welcome["revision"] < 2:
            raise ValueError(f"the runtime speaks protocol revision {welcome['revision']}; the bridge needs 2 (sensor ranges in WELCOME)")
        for p in welcome["primitives"]:
            loc, pid = p["locator"], p["id"]
            num = loc.rsplit(":", 1)[-1]
            if p["class"] == "joint" and num in robot.act and "joints" in granted:
                self.joints[pid] = num
                self.ranges[pid] = max((p["max_urad"] - p["min_urad"]) * 1e-6, 1e-3)
            elif p["class"] == "ear" and num in robot.act:
                self.ears[pid] = num
            elif loc in ACCEL and "accel" in granted:
                self.accel.append((pid,) + ACCEL[loc] + (p["value_min"], p["value_max"]))
            elif p["class"] == "switch" and num in PAWS and "switches" in granted:
                self.paws.append((pid, PAWS[num]))
            elif loc in PSDS and "psd" in granted:
                self.psds.append((pid, PSDS[loc], p["value_min"], p["value_max"]))
        # readings: joint IDs and their qpos addresses, in a fixed order
        self.joint_ids = np.array(list(self.joints), np.uint32)
        self.joint_q = np.array([robot.act[n][1] for n in self.joints.values()], np.intp)
        # sensors' sensordata addresses (accel x y z first, then paws, PSDs)
        self.sensor_adr = np.array([robot.sensor["accel"] + k for k in range(3)]
                                   + [robot.sensor[name] for _, name in self.paws]
                                   + [robot.sensor[p[1]] for p in self.psds], np.intp)
        # MuJoCo arrays looked up once (each attribute access makes a new numpy view)
        self.ctrl = robot.d.ctrl
        self.layout = None  # (joint IDs of the frames, their rows we drive, actuators, tau/range)
        self.gains = None  # the last frame's raw gains and motor power, as applied
        self.started = False

    def start(self, frame):
        """First frame: the robot takes the runtime's current joint angles (boot pose)."""
        self.robot.pose({self.joints[int(j["id"])]: int(j["measured"]) * 1e-6
                         for j in frame.joints if int(j["id"]) in self.joints})
        self.started = True

    def _rows(self, ids):
        """Index arrays for a frame's joint list (the runtime sends the same list every
        frame, so they are worked out once)."""
        key = ids.tobytes()
        if self.layout is None or self.layout[0] != key:
            rows = [i for i, pid in enumerate(ids.tolist()) if pid in self.joints]
            act = np.array([self.robot.act[self.joints[int(ids[i])]][0] for i in rows], np.intp)
            ranges = np.array([self.ranges[int(ids[i])] for i in rows])
            self.layout = (key, np.array(rows, np.intp), act, self.robot.m.actuator_forcerange[act, 1] / ranges)
        return self.layout[1:]

    def apply(self, frame):
        """The frame's gains, joint targets and ear states to the robot's actuators."""
        r, power = self.robot, frame.motor_power
        rows, act, tau_per_rad = self._rows(frame.joints["id"])
        j = frame.joints[rows]
        gains = (j["p"].tobytes(), j["d"].tobytes(), j["enabled"].tobytes(), power)
        if gains != self.gains:  # programs load gains once in a while, not every frame
            self.gains = gains
            driven = (j["enabled"] != 0) & (j["p"] > 0) & power
            kp, kv = servo_gains(self.gain_scale * j["p"], self.gain_scale * j["d"], tau_per_rad)
            kp, kv = np.where(driven, kp, 0.0), np.where(driven, kv, 0.0)
            r.m.actuator_gainprm[act, 0] = kp
            r.m.actuator_biasprm[act, 1] = -kp
            r.m.actuator_biasprm[act, 2] = -kv
        self.ctrl[act] = j["target"] * 1e-6
        for pid, state in frame.ears.tolist():
            num = self.ears.get(pid)
            if num is not None:
                r.set_gain(num, EAR_KP if power else 0.0, EAR_KV if power else 0.0)
                r.target(num, EAR_UP if state else 0.0)

    def readings_layout(self):
        """What its READINGS hold and where they come from (replies.py builds them):
        joint angles, then accelerometer, paw switches, distance sensors."""
        return Layout(self.joint_ids, self.joint_q, self.accel, self.paws, self.psds, self.sensor_adr, self.rng)
