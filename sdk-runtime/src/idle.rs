//! Waiting for the objects to run out of work. At `--speed max` the frame thread starts
//! the next frame as soon as every object is idle; it sleeps on a condition variable
//! that objects signal when they become idle, instead of polling (a polling frame
//! thread per runtime competes for the cores with the objects it waits for, and with
//! the simulator, when several robots share a machine).
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Condvar, Mutex};
use std::time::Duration;

#[derive(Default)]
pub struct IdleWait {
    waiters: AtomicUsize,
    lock: Mutex<()>,
    cv: Condvar,
}

/// How long a waiter sleeps before it looks again anyway: a safety net for a change of
/// state that signals nobody (it then costs this much, never a hang).
const RECHECK: Duration = Duration::from_millis(2);

impl IdleWait {
    /// Something may have become idle: wakes the waiters, if any (an atomic load when
    /// nobody waits, which is most of the time).
    pub fn notify(&self) {
        if self.waiters.load(Ordering::SeqCst) > 0 {
            let _guard = self.lock.lock().unwrap_or_else(|p| p.into_inner());
            self.cv.notify_all();
        }
    }

    /// Returns once `idle()` holds.
    pub fn wait_until(&self, idle: impl Fn() -> bool) {
        while !idle() {
            let guard = self.lock.lock().unwrap_or_else(|p| p.into_inner());
            self.waiters.fetch_add(1, Ordering::SeqCst);
            // Checked again after registering: a notifier that saw no waiter changed the
            // state before this check, and one that saw us takes the lock we hold.
            if !idle() {
                drop(self.cv.wait_timeout(guard, RECHECK).unwrap_or_else(|p| p.into_inner()));
            }
            self.waiters.fetch_sub(1, Ordering::SeqCst);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicBool;
    use std::sync::Arc;
    use std::time::Instant;

    #[test]
    fn a_notified_change_wakes_the_waiter_at_once() {
        let w = Arc::new(IdleWait::default());
        let busy = Arc::new(AtomicBool::new(true));
        let (w2, busy2) = (w.clone(), busy.clone());
        let t = std::thread::spawn(move || {
            let start = Instant::now();
            w2.wait_until(|| !busy2.load(Ordering::SeqCst));
            start.elapsed()
        });
        std::thread::sleep(Duration::from_millis(50));
        busy.store(false, Ordering::SeqCst);
        w.notify();
        let waited = t.join().unwrap();
        assert!(waited >= Duration::from_millis(50), "returned while busy: {waited:?}");
    }

    #[test]
    fn an_unsignalled_change_is_seen_on_the_recheck() {
        let w = IdleWait::default();
        let calls = AtomicUsize::new(0);
        w.wait_until(|| calls.fetch_add(1, Ordering::SeqCst) >= 3);
        assert!(calls.load(Ordering::SeqCst) >= 4);
    }
}
