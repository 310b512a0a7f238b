//! Streaming sends. A TCP endpoint's socket has TCP_NODELAY, so a small Send (an echo, a
//! request, a reply line) leaves at once. A program that streams — an 8 KiB Send, its
//! answer, the next 8 KiB Send a few microseconds later (an FTP RETR, pictures sent to a
//! PC) — then makes one segment and one wake-up of the receiver per Send; with Nagle's
//! algorithm the kernel joins the chunks while earlier data is unacknowledged (the robot
//! stack's default, as any BSD-style stack's). On loopback that is 1.2–1.3 GB/s instead of
//! 0.8–0.9 for ftpd's 64 MiB RETR.
//!
//! So: a big Send that comes right after the answer of another big one turns
//! TCP_NODELAY off; a small Send, a Receive or a Close turns it back on (which makes the
//! kernel send what it holds at once), and so does [`PUSH_AFTER`] without a Send, so
//! that the end of a stream never waits for an acknowledgement (up to 40 ms with a
//! delayed ACK) — about this long (the poll thread's timer counts whole milliseconds:
//! at most 2 ms).
use std::os::fd::RawFd;
use std::time::{Duration, Instant};

use crate::sys;

/// A Send at least this big may be part of a stream.
const CHUNK: usize = 2048;
/// The next big Send comes within this of the last one's answer: a stream.
const BACK_TO_BACK: Duration = Duration::from_micros(500);
/// A stream with no Send for this long is pushed out.
pub(super) const PUSH_AFTER: Duration = Duration::from_millis(1);

/// One endpoint's streaming state.
#[derive(Debug, Default)]
pub(super) struct Stream {
    /// TCP_NODELAY is off.
    joining: bool,
    /// When the last big Send was answered.
    last_big: Option<Instant>,
}

impl Stream {
    /// Before a Send of `size` bytes on `fd`: when it makes the endpoint stream, the time
    /// by which to look whether the stream has stopped.
    pub(super) fn before_send(&mut self, fd: RawFd, size: usize, now: Instant) -> Option<Instant> {
        if size < CHUNK {
            self.push(fd);
            return None;
        }
        if self.joining || !self.last_big.is_some_and(|t| now.saturating_duration_since(t) <= BACK_TO_BACK) {
            return None;
        }
        sys::set_int_opt(fd, libc::IPPROTO_TCP, libc::TCP_NODELAY, 0);
        self.joining = true;
        Some(now + PUSH_AFTER)
    }

    /// A Send of `size` bytes was answered at `now` (all of it written).
    pub(super) fn sent(&mut self, size: usize, now: Instant) {
        self.last_big = (size >= CHUNK).then_some(now);
    }

    /// Sends at once whatever the kernel holds back (a Receive, a Close, a small Send).
    pub(super) fn push(&mut self, fd: RawFd) {
        if self.joining {
            sys::set_int_opt(fd, libc::IPPROTO_TCP, libc::TCP_NODELAY, 1);
            self.joining = false;
        }
    }

    /// The poll thread's check: a stream with no Send for [`PUSH_AFTER`] is pushed; else
    /// when to look again.
    pub(super) fn check(&mut self, fd: RawFd, now: Instant) -> Option<Instant> {
        if !self.joining {
            return None;
        }
        let due = self.last_big.map_or(now, |t| t + PUSH_AFTER);
        if due <= now {
            self.push(fd);
            return None;
        }
        Some(due)
    }

    /// Joins (or stays joined) as a big Send answered at `now` and the next one right
    /// after it do.
    #[cfg(test)]
    pub(super) fn join(&mut self, fd: RawFd, now: Instant) {
        self.sent(CHUNK, now);
        self.before_send(fd, CHUNK, now);
        assert!(self.joining, "back to back: a stream");
    }

    /// Whether TCP_NODELAY is off now.
    #[cfg(test)]
    pub(super) fn joining(&self) -> bool {
        self.joining
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::net::{Ipv4Addr, TcpListener, TcpStream};
    use std::os::fd::AsRawFd;

    /// The socket's TCP_NODELAY, as the kernel has it.
    fn nodelay(fd: RawFd) -> bool {
        crate::sys::int_opt(fd, libc::IPPROTO_TCP, libc::TCP_NODELAY).expect("getsockopt TCP_NODELAY") != 0
    }

    #[test]
    fn big_sends_back_to_back_turn_nodelay_off_until_a_small_send_a_push_or_a_pause() {
        let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
        let sock = TcpStream::connect(server.local_addr().unwrap()).unwrap();
        sock.set_nodelay(true).unwrap();
        let fd = sock.as_raw_fd();
        let t0 = Instant::now();
        let at = |us: u64| t0 + Duration::from_micros(us);
        let mut s = Stream::default();

        assert_eq!(s.before_send(fd, 8192, at(0)), None, "a first big Send: no stream yet");
        s.sent(8192, at(10));
        assert_eq!(s.before_send(fd, 8192, at(10) + BACK_TO_BACK + Duration::from_micros(1)), None, "too late after the last one");
        s.sent(8192, at(1000));
        assert_eq!(s.before_send(fd, 8192, at(1100)), Some(at(1100) + PUSH_AFTER), "back to back: a stream");
        assert!(s.joining() && !nodelay(fd));
        s.sent(8192, at(1110));
        assert_eq!(s.before_send(fd, 8192, at(1120)), None, "already joining");
        assert!(!nodelay(fd));

        // The poll thread's look: not yet, then pushed after PUSH_AFTER without a Send.
        s.sent(8192, at(1130));
        assert_eq!(s.check(fd, at(1200)), Some(at(1130) + PUSH_AFTER));
        assert_eq!(s.check(fd, at(1130) + PUSH_AFTER), None);
        assert!(!s.joining() && nodelay(fd), "pushed");
        assert_eq!(s.check(fd, at(9000)), None, "nothing to look at");

        // A small Send (or a Receive or a Close: `push`) ends a stream at once.
        assert!(s.before_send(fd, 8192, at(1130) + PUSH_AFTER + Duration::from_micros(1)).is_none(), "the last big one is past");
        s.sent(8192, at(5000));
        assert!(s.before_send(fd, 8192, at(5100)).is_some());
        assert_eq!(s.before_send(fd, 100, at(5200)), None);
        assert!(!s.joining() && nodelay(fd), "a small Send goes out at once");
        s.sent(100, at(5210));
        assert_eq!(s.before_send(fd, 8192, at(5220)), None, "a small Send is no stream's");
        s.sent(8192, at(6000));
        assert!(s.before_send(fd, 4096, at(6100)).is_some());
        s.push(fd);
        assert!(!s.joining() && nodelay(fd));
    }
}
