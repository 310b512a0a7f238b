"""The field camera of the view (`cargo openr run --sim mujoco --view / --record`): the
whole scene rendered offscreen from above and behind the field's long side, FIELD_FPS
pictures a second of virtual time (each ~50 ms of a core on software GL), each written
as a PNG.

`FieldCamera(world, live, record)`: `live` is a file replaced by every new picture
(written beside it, then renamed: a reader never sees half of one); `record` a
directory that keeps them all, `NNNNNN.png` from 1, indexed in `index.jsonl` (`n`,
`time_ms`, `frame`, `file`). The scene is copied from MjData on the stepping thread and
drawn on a thread of its own with its own GL context, like the head cameras (world.py).
"""
import json
import os
import struct
import zlib
from concurrent.futures import ThreadPoolExecutor

import mujoco
import numpy as np

from world import RenderError

FIELD_W, FIELD_H = 480, 320
FIELD_FPS = 5


def png(rgb):
    """RGB rows (top first, H x W x 3 uint8) as PNG bytes: zlib's fastest level, as the
    runtime's recorder writes its camera pictures."""
    h, w, _ = rgb.shape
    raw = np.concatenate([np.zeros((h, 1), np.uint8), rgb.reshape(h, w * 3)], axis=1).tobytes()

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    head = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", head) + chunk(b"IDAT", zlib.compress(raw, 1)) + chunk(b"IEND", b"")


class FieldCamera:
    def __init__(self, world, live=None, record=None):
        self.live, self.record = live, record
        self.m = world.m
        self.m.vis.global_.offwidth = max(self.m.vis.global_.offwidth, FIELD_W)
        self.m.vis.global_.offheight = max(self.m.vis.global_.offheight, FIELD_H)
        self.cam = mujoco.MjvCamera()
        self.cam.type = mujoco.mjtCamera.mjCAMERA_FREE
        lo, hi = _extent(world)
        self.cam.lookat[:] = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2 - 0.05 * (hi[1] - lo[1]), 0]
        self.cam.distance = 0.82 * max(hi[0] - lo[0], 1.0)
        self.cam.azimuth, self.cam.elevation = 90.0, -55.0
        self.vis = mujoco.MjvOption()
        self.vis.flags[mujoco.mjtVisFlag.mjVIS_RANGEFINDER] = 0
        self.vis.sitegroup[:] = 0
        self.scene = mujoco.MjvScene(self.m, maxgeom=self.m.ngeom + 100)
        self.pool = ThreadPoolExecutor(1, thread_name_prefix="fieldcam")
        self.pending = None
        self.pictures = 0
        self.index = None
        if record:
            os.makedirs(record, exist_ok=True)
            self.index = open(os.path.join(record, "index.jsonl"), "w", buffering=1)
        try:
            self.pool.submit(self._open).result()
        except Exception as e:
            self.pool.shutdown()
            raise RenderError(f"cannot render the field camera offscreen: {e}") from None

    def _open(self):
        from mujoco import gl_context
        self.gl = gl_context.GLContext(FIELD_W, FIELD_H)
        self.gl.make_current()
        self.ctx = mujoco.MjrContext(self.m, mujoco.mjtFontScale.mjFONTSCALE_100)
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self.ctx)
        self.rect = mujoco.MjrRect(0, 0, FIELD_W, FIELD_H)
        self.raw = np.empty((FIELD_H, FIELD_W, 3), np.uint8)

    @staticmethod
    def due(t_ms):
        """A picture at the end of the frame that ends at t_ms (8 ms frames)."""
        return (t_ms * FIELD_FPS) // 1000 > ((t_ms - 8) * FIELD_FPS) // 1000

    def shoot(self, d, frame, t_ms):
        """Copies the scene from `d` now and draws and writes it on the camera's thread."""
        if self.pending is not None:
            self.pending.result()  # the scene is free again (re-raises a drawing error)
        mujoco.mjv_updateScene(self.m, d, self.vis, None, self.cam, mujoco.mjtCatBit.mjCAT_ALL, self.scene)
        self.pictures += 1
        self.pending = self.pool.submit(self._draw, self.pictures, frame, t_ms)

    def _draw(self, n, frame, t_ms):
        mujoco.mjr_render(self.rect, self.scene, self.ctx)
        mujoco.mjr_readPixels(self.raw, None, self.rect, self.ctx)
        data = png(self.raw[::-1])
        if self.live:
            part = self.live + ".part"
            with open(part, "wb") as f:
                f.write(data)
            os.replace(part, self.live)
        if self.record:
            name = f"{n:06d}.png"
            with open(os.path.join(self.record, name), "wb") as f:
                f.write(data)
            self.index.write(json.dumps({"n": n, "time_ms": t_ms, "frame": frame, "file": name}) + "\n")

    def close(self):
        if self.pending is not None:
            self.pending.result()

        def free():
            self.ctx.free()
            self.gl.free()

        self.pool.submit(free).result()
        self.pool.shutdown()
        if self.index:
            self.index.close()


def _extent(world):
    """The xy box of the scene's fixed shapes (world.field()), else 6 x 4 m."""
    shapes = world.field()["shapes"]
    if not shapes:
        return (-3.0, -2.0), (3.0, 2.0)
    xs = [s["pos"][0] + k * s["size"][0] for s in shapes for k in (-1, 1)]
    ys = [s["pos"][1] + k * s["size"][1] for s in shapes for k in (-1, 1)]
    return (min(xs), min(ys)), (max(xs), max(ys))
