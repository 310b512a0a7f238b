//! What the runtime sends a peer goes through a bounded queue and a writer thread of
//! the peer's own: the frame thread never blocks on a socket. A peer that stops
//! reading holds the frame thread at most `PATIENCE` (backpressure for a slow but
//! steady reader), then it is dropped; the socket's write timeout ends its writer.
use std::collections::VecDeque;
use std::io::Write;
use std::sync::{Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant};

/// Bytes queued for one peer before the sender waits.
const BUDGET: usize = 1 << 20;
/// How long a full queue may hold the sender before the peer counts as not reading.
pub const PATIENCE: Duration = Duration::from_secs(2);
/// A write blocked this long fails (set on the socket: the writer thread then ends).
pub const WRITE_TIMEOUT: Duration = Duration::from_secs(2);

#[derive(Default)]
struct State {
    msgs: VecDeque<Vec<u8>>,
    bytes: usize,
    /// No more messages are taken (closed, broken or stalled).
    closed: bool,
    /// The writer thread has ended.
    done: bool,
    /// A write blocked for `WRITE_TIMEOUT`, or the queue stayed full: the peer does not read.
    stalled: bool,
}

#[derive(Default)]
pub struct Outbox {
    st: Mutex<State>,
    cv: Condvar,
}

/// Why a message was not queued.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refused {
    Closed,
    /// The queue stayed full for `PATIENCE`: the peer does not read.
    Stalled,
}

impl Outbox {
    fn lock(&self) -> MutexGuard<'_, State> {
        self.st.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Queues `m`, waiting at most `patience` for room.
    pub fn push(&self, m: Vec<u8>, patience: Duration) -> Result<(), Refused> {
        let deadline = Instant::now() + patience;
        let mut st = self.lock();
        while !st.closed && !st.msgs.is_empty() && st.bytes + m.len() > BUDGET {
            let now = Instant::now();
            if now >= deadline {
                st.closed = true;
                st.stalled = true;
                self.cv.notify_all();
                return Err(Refused::Stalled);
            }
            st = self.cv.wait_timeout(st, deadline - now).unwrap_or_else(|p| p.into_inner()).0;
        }
        if st.closed {
            return Err(if st.stalled { Refused::Stalled } else { Refused::Closed });
        }
        st.bytes += m.len();
        st.msgs.push_back(m);
        self.cv.notify_all();
        Ok(())
    }

    /// Takes no more messages; the writer sends what is queued, then closes.
    pub fn close(&self) {
        self.lock().closed = true;
        self.cv.notify_all();
    }

    /// Waits until the writer has ended, at most `d`.
    pub fn wait_done(&self, d: Duration) {
        let deadline = Instant::now() + d;
        let mut st = self.lock();
        while !st.done {
            let now = Instant::now();
            if now >= deadline {
                return;
            }
            st = self.cv.wait_timeout(st, deadline - now).unwrap_or_else(|p| p.into_inner()).0;
        }
    }

    fn pop(&self) -> Option<Vec<u8>> {
        let mut st = self.lock();
        loop {
            if let Some(m) = st.msgs.pop_front() {
                st.bytes -= m.len();
                self.cv.notify_all();
                return Some(m);
            }
            if st.closed {
                return None;
            }
            st = self.cv.wait(st).unwrap_or_else(|p| p.into_inner());
        }
    }

    /// The writer thread's loop: writes until closed and drained or a write fails
    /// (broken, or blocked for `WRITE_TIMEOUT`); then `end` (shuts the socket).
    pub fn run_writer(&self, w: &mut impl Write, end: impl FnOnce()) {
        let mut stalled = false;
        while let Some(m) = self.pop() {
            if let Err(e) = w.write_all(&m) {
                stalled = matches!(e.kind(), std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut);
                break;
            }
        }
        end();
        let mut st = self.lock();
        st.stalled |= stalled;
        st.closed = true;
        st.done = true;
        st.msgs.clear();
        st.bytes = 0;
        self.cv.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_queue_refuses_after_the_patience() {
        let o = Outbox::default();
        o.push(vec![0; BUDGET], Duration::ZERO).unwrap();
        assert_eq!(o.push(vec![0; 10], Duration::from_millis(20)), Err(Refused::Stalled));
        assert_eq!(o.push(vec![0; 10], Duration::ZERO), Err(Refused::Stalled), "and stays refused");
        let closed = Outbox::default();
        closed.close();
        assert_eq!(closed.push(vec![0; 10], Duration::ZERO), Err(Refused::Closed));
    }

    #[test]
    fn the_writer_drains_then_ends() {
        let o = std::sync::Arc::new(Outbox::default());
        o.push(b"ab".to_vec(), Duration::ZERO).unwrap();
        o.push(b"cd".to_vec(), Duration::ZERO).unwrap();
        o.close();
        let mut out = Vec::new();
        let mut ended = false;
        o.run_writer(&mut out, || ended = true);
        assert_eq!(out, b"abcd");
        assert!(ended);
        o.wait_done(Duration::ZERO);
    }
}
