//! Ctrl-C and SIGTERM: blocked in every thread and collected by the main thread, which
//! then runs the shutdown sequence (Stop all, Destroy all) and exits 0. SIGUSR1 is the
//! robot's pause button (robot-api 9.3): each one presses or releases it.
use std::time::Duration;

use crate::error::{ErrorKind, Result};

pub struct Termination {
    set: libc::sigset_t,
}

/// Blocks SIGINT/SIGTERM/SIGHUP/SIGUSR1 for this thread and every thread it creates later.
pub fn block_termination() -> Result<Termination> {
    // SAFETY: sigset_t is plain C data, initialised by sigemptyset before use; the mask change
    // is this thread's own.
    unsafe {
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        for s in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP, libc::SIGUSR1] {
            libc::sigaddset(&mut set, s);
        }
        if libc::pthread_sigmask(libc::SIG_BLOCK, &set, std::ptr::null_mut()) != 0 {
            return Err(ErrorKind::Runtime("cannot block SIGINT/SIGTERM".into()).into());
        }
        Ok(Termination { set })
    }
}

impl Termination {
    /// Waits up to `d` for one of the blocked signals.
    pub fn wait(&self, d: Duration) -> Option<i32> {
        let ts = libc::timespec { tv_sec: d.as_secs() as libc::time_t, tv_nsec: d.subsec_nanos() as libc::c_long };
        // SAFETY: `self.set` is an initialised sigset; `ts` lives for the call; no siginfo is asked for.
        let sig = unsafe { libc::sigtimedwait(&self.set, std::ptr::null_mut(), &ts) };
        (sig > 0).then_some(sig)
    }
}
