//! The poll thread's epoll set. An endpoint's socket is armed one-shot, only when an
//! operation parks on it (it was tried at once on the caller's thread and would block),
//! for the events the parked operations need; an event disarms it, and the poll thread
//! re-arms it only if something still waits after it made progress. A socket whose
//! operations finish at once (an echo whose data is already there, a stream of Sends the
//! socket takes) costs no epoll call and never wakes the poll thread. Each endpoint keeps
//! an [`Armed`] record beside its socket, so a socket already armed for what is needed is
//! left alone. Arming polls the socket's state, so readiness that came between the
//! caller's EAGAIN and the arming is not lost.
//!
//! A listening socket is added once, edge-triggered: connections that come while no
//! Listen waits stay queued and are accepted by the next Listen at once; one whose accept
//! failed (no descriptor left) is tried again on the poll thread's timer, as its edge has
//! passed.
use std::io;
use std::os::fd::{AsRawFd, OwnedFd, RawFd};

use super::sys;
use super::EndpointId;

/// What an epoll event is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Token {
    /// The eventfd that makes the poll thread look at its timeout again.
    Wake,
    /// A listening socket, by its host (address, port).
    Listener((u32, u16)),
    /// An endpoint's socket.
    Ep(EndpointId),
}

const WAKE: u64 = u64::MAX;
const LISTENER: u64 = 1 << 62;

impl Token {
    fn encode(self) -> u64 {
        match self {
            Token::Wake => WAKE,
            Token::Listener((addr, port)) => LISTENER | u64::from(addr) << 16 | u64::from(port),
            Token::Ep(id) => u64::from(id.0),
        }
    }

    pub fn decode(v: u64) -> Token {
        if v == WAKE {
            Token::Wake
        } else if v & LISTENER != 0 {
            Token::Listener(((v >> 16) as u32, v as u16))
        } else {
            Token::Ep(EndpointId(v as u32))
        }
    }
}

/// Whether and for what an endpoint's socket is armed.
#[derive(Default, Clone, Copy)]
pub struct Armed {
    /// The socket is in the epoll set (arming it again is a modification).
    in_set: bool,
    /// The events it will report once (0: disarmed).
    events: u32,
}

impl Armed {
    /// Its event came: the kernel disarmed it (one-shot).
    pub fn fired(&mut self) {
        self.events = 0;
    }

    /// Whether the socket was ever put in the epoll set.
    #[cfg(test)]
    pub fn in_set(&self) -> bool {
        self.in_set
    }
}

/// Readable (a Receive, a Listen waits).
pub const IN: u32 = libc::EPOLLIN as u32;
/// Writable (a Send or a Connect waits).
pub const OUT: u32 = libc::EPOLLOUT as u32;

pub struct Poller {
    ep: OwnedFd,
    wake: OwnedFd,
    /// The tests' switch: every epoll_ctl fails (EINVAL) from now on, while epoll_wait
    /// still reports what was armed before.
    #[cfg(test)]
    refuse_ctl: std::sync::atomic::AtomicBool,
}

impl Poller {
    pub fn new() -> io::Result<Poller> {
        // SAFETY: plain syscalls making fresh descriptors.
        let ep = sys::owned(unsafe { libc::epoll_create1(libc::EPOLL_CLOEXEC) }).map_err(io::Error::from_raw_os_error)?;
        // SAFETY: as above.
        let wake = sys::owned(unsafe { libc::eventfd(0, libc::EFD_NONBLOCK | libc::EFD_CLOEXEC) }).map_err(io::Error::from_raw_os_error)?;
        let poller = Poller {
            ep,
            wake,
            #[cfg(test)]
            refuse_ctl: Default::default(),
        };
        // Level-triggered: it stays readable until drained.
        poller.ctl(libc::EPOLL_CTL_ADD, poller.wake.as_raw_fd(), IN, Token::Wake).map_err(io::Error::from_raw_os_error)?;
        Ok(poller)
    }

    /// A poller whose "epoll set" is an eventfd: every epoll_ctl and epoll_wait on it
    /// fails (EINVAL), as the tests of those failures want.
    #[cfg(test)]
    pub fn refusing() -> io::Result<Poller> {
        // SAFETY: plain syscalls making fresh descriptors.
        let ep = sys::owned(unsafe { libc::eventfd(0, libc::EFD_CLOEXEC) }).map_err(io::Error::from_raw_os_error)?;
        // SAFETY: as above.
        let wake = sys::owned(unsafe { libc::eventfd(0, libc::EFD_NONBLOCK | libc::EFD_CLOEXEC) }).map_err(io::Error::from_raw_os_error)?;
        Ok(Poller { ep, wake, refuse_ctl: Default::default() })
    }

    /// Makes every later epoll_ctl fail (EINVAL) as `refusing`'s do, while the poll
    /// thread still gets the events of the sockets armed so far: an operation that was
    /// parked before is refused when it has to be armed again.
    #[cfg(test)]
    pub fn refuse_from_now(&self) {
        self.refuse_ctl.store(true, std::sync::atomic::Ordering::SeqCst);
    }

    fn ctl(&self, op: libc::c_int, fd: RawFd, events: u32, token: Token) -> Result<(), i32> {
        #[cfg(test)]
        if self.refuse_ctl.load(std::sync::atomic::Ordering::SeqCst) {
            return Err(libc::EINVAL);
        }
        let mut ev = libc::epoll_event { events, u64: token.encode() };
        // SAFETY: `ev` is a live local the kernel only reads.
        sys::check(unsafe { libc::epoll_ctl(self.ep.as_raw_fd(), op, fd, &mut ev) }).map(drop)
    }

    /// Adds a listening socket, readable edge-triggered, for good.
    pub fn add_listener(&self, fd: RawFd, key: (u32, u16)) -> Result<(), i32> {
        self.ctl(libc::EPOLL_CTL_ADD, fd, IN | libc::EPOLLET as u32, Token::Listener(key))
    }

    /// Arms `fd` to report `want` once (with what `armed` has already), unless it is
    /// armed for that already. An errno is returned: the caller must fail what waits on
    /// the socket. (`armed.in_set` is always right: a socket is added once, by the endpoint
    /// that owns it, and leaves the set when it is closed.)
    pub fn arm(&self, fd: RawFd, token: Token, armed: &mut Armed, want: u32) -> Result<(), i32> {
        if want & !armed.events == 0 {
            return Ok(());
        }
        let events = armed.events | want;
        let flags = events | libc::EPOLLONESHOT as u32;
        let op = if armed.in_set { libc::EPOLL_CTL_MOD } else { libc::EPOLL_CTL_ADD };
        self.ctl(op, fd, flags, token)?;
        *armed = Armed { in_set: true, events };
        Ok(())
    }

    /// Waits up to `timeout` ms (-1: no limit) and fills `events`; Err(errno) on failure
    /// (EINTR included).
    pub fn wait(&self, events: &mut [libc::epoll_event], timeout: i32) -> Result<usize, i32> {
        // SAFETY: `events` is a live array of `events.len()` entries the kernel may fill.
        sys::check(unsafe { libc::epoll_wait(self.ep.as_raw_fd(), events.as_mut_ptr(), events.len() as i32, timeout) }).map(|n| n as usize)
    }

    /// Makes the poll thread recompute its timeout (a delayed reply became due earlier).
    pub fn wake(&self) {
        let one: u64 = 1;
        // SAFETY: writes 8 bytes from `one`.
        unsafe { libc::write(self.wake.as_raw_fd(), (&one as *const u64).cast(), 8) };
    }

    pub fn drain_wake(&self) {
        let mut v: u64 = 0;
        // SAFETY: reads 8 bytes into `v`.
        unsafe { libc::read(self.wake.as_raw_fd(), (&mut v as *mut u64).cast(), 8) };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_round_trip() {
        for t in [
            Token::Wake,
            Token::Listener((0x7f00_0001, 54321)),
            Token::Listener((u32::MAX, u16::MAX)),
            Token::Ep(EndpointId(7)),
            Token::Ep(EndpointId(u32::MAX)),
        ] {
            assert_eq!(Token::decode(t.encode()), t);
        }
    }
}
