"""One runtime connection's messages (docs/robot-protocol.md), read into a buffer kept
for the connection: a frame's header and payload usually come in one recv_into, with
no new bytes object per read and no concatenation of the unread rest (the reference
codec tools/robot_peer.py does both; 8 robots x 125 frames a second add up)."""
import robot_peer as rp

INITIAL = 1 << 16  # a FRAME of the ERS-7 is ~700 bytes; a bigger message grows the buffer


class BadHeader(Exception):
    """The stream is not (or no longer) the protocol: says what came instead."""


class Wire:
    def __init__(self, sock):
        self.sock = sock
        self.buf = bytearray(INITIAL)
        self.view = memoryview(self.buf)
        self.start = self.end = 0  # unread bytes: buf[start:end]

    def send(self, kind, frame, payload=b""):
        self.sock.sendall(rp.HEADER.pack(rp.MAGIC, rp.VERSION, kind, len(payload), frame) + payload)

    def _fill(self, n):
        """At least n unread bytes from buf[start]."""
        if self.start + n > len(self.buf):  # room at the end: move the rest to the front
            rest = self.end - self.start
            if n > len(self.buf):
                # A new buffer (the old one may still be exported by the last payload).
                buf = bytearray(max(n, 2 * len(self.buf)))
                buf[:rest] = self.view[self.start:self.end]
                self.buf, self.view = buf, memoryview(buf)
            else:
                self.buf[:rest] = self.buf[self.start:self.end]
            self.start, self.end = 0, rest
        while self.end - self.start < n:
            got = self.sock.recv_into(self.view[self.end:])
            if not got:
                raise EOFError("the runtime closed the connection")
            self.end += got

    def recv(self):
        """(type, frame, payload) of the next message. The payload is a view into the
        buffer, valid until the next recv (a FRAME is applied before that); other
        messages get bytes."""
        size = rp.HEADER.size
        self._fill(size)
        magic, version, kind, length, frame = rp.HEADER.unpack_from(self.buf, self.start)
        if magic != rp.MAGIC or version != rp.VERSION:
            got = bytes(self.view[self.start:self.start + size])
            raise BadHeader(f"bad message header: expected magic {rp.MAGIC!r} version {rp.VERSION}, "
                            f"got magic {magic!r} version {version} (bytes {got.hex(' ')})")
        self._fill(size + length)
        at = self.start + size
        self.start = at + length
        if self.start == self.end:
            self.start = self.end = 0
        payload = self.view[at:at + length]
        return kind, frame, payload if kind == rp.FRAME else bytes(payload)
