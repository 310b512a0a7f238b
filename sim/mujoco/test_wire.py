"""wire.py against a real socket pair: messages split across reads, the buffer's
compaction, growth past its first 64 KiB, and the errors (a bad header, EOF).
Run: PYTHONPATH=sim/mujoco:tools python3 -m unittest sim/mujoco/test_wire.py"""
import socket
import threading
import unittest

import robot_peer as rp
import wire


def message(kind, frame, payload):
    return rp.HEADER.pack(rp.MAGIC, rp.VERSION, kind, len(payload), frame) + payload


class WireTest(unittest.TestCase):
    def setUp(self):
        self.a, self.b = socket.socketpair()
        self.w = wire.Wire(self.b)

    def tearDown(self):
        self.a.close()
        self.b.close()

    def feed(self, data, piece):
        """Writes `data` from another thread, `piece` bytes per send."""
        def run():
            for i in range(0, len(data), piece):
                self.a.sendall(data[i:i + piece])
        t = threading.Thread(target=run)
        t.start()
        return t

    def test_messages_split_at_every_byte_arrive_whole(self):
        msgs = [(rp.FRAME, k, bytes([k % 256]) * (k * 37 % 900)) for k in range(40)]
        t = self.feed(b"".join(message(*m) for m in msgs), 1)
        for kind, frame, payload in msgs:
            got = self.w.recv()
            self.assertEqual((got[0], got[1], bytes(got[2])), (kind, frame, payload))
        t.join()

    def test_compaction_keeps_the_unread_rest(self):
        # Many ~700-byte frames sent in 4000-byte pieces: the unread rest keeps
        # reaching the buffer's end and moving to its front.
        msgs = [(rp.FRAME, k, bytes((k + i) % 251 for i in range(700))) for k in range(400)]
        t = self.feed(b"".join(message(*m) for m in msgs), 4000)
        for kind, frame, payload in msgs:
            got = self.w.recv()
            self.assertEqual((got[1], bytes(got[2])), (frame, payload))
        t.join()
        self.assertEqual(len(self.w.buf), wire.INITIAL, "no growth for small messages")

    def test_a_message_bigger_than_the_buffer_grows_it(self):
        big = bytes(i % 253 for i in range(3 * wire.INITIAL + 5))
        t = self.feed(message(rp.FRAME, 1, b"x" * 100) + message(7, 2, big) + message(rp.FRAME, 3, b"after"), 1000)
        self.assertEqual(bytes(self.w.recv()[2]), b"x" * 100)
        kind, frame, payload = self.w.recv()
        self.assertEqual((kind, frame), (7, 2))
        self.assertIsInstance(payload, bytes, "a message other than FRAME is bytes, not a view")
        self.assertEqual(payload, big)
        self.assertEqual(bytes(self.w.recv()[2]), b"after")
        t.join()
        self.assertGreaterEqual(len(self.w.buf), len(big) + rp.HEADER.size)

    def test_a_bad_header_says_what_came(self):
        self.a.sendall(b"HTTP/1.1 200 OK\r\n\r\n")
        with self.assertRaises(wire.BadHeader) as e:
            self.w.recv()
        self.assertIn("got magic b'HTTP'", str(e.exception))

    def test_eof_in_the_middle_of_a_message(self):
        self.a.sendall(message(rp.FRAME, 9, b"y" * 50)[:30])
        self.a.shutdown(socket.SHUT_WR)
        with self.assertRaises(EOFError):
            self.w.recv()


if __name__ == "__main__":
    unittest.main()
