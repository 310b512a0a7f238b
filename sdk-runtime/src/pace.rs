//! Real-time pacing of the frame thread: a frame starts at an absolute deadline
//! (start + k × period), so a late wake-up never shifts the frames after it.
//!
//! A plain sleep wakes late by the thread's timer slack (50 µs by default) plus the
//! scheduler's wake-up latency, which on a busy machine is what sensor jitter is made
//! of. The frame thread therefore asks for no slack, sleeps until a little before the
//! deadline (`margin`: as early as its recent wake-ups were late, within bounds) and
//! waits out the rest awake, yielding its core to anything runnable meanwhile.
use std::time::Duration;

/// Bounds of the early wake-up: on a quiet machine a wake-up is a few µs late; on a
/// loaded one no margin a robot can afford (it is spent awake, per frame) would cover it.
const MIN_MARGIN: Duration = Duration::from_micros(10);
const MAX_MARGIN: Duration = Duration::from_micros(200);

/// What a wait found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// The deadline was met (the wait returned at or after it).
    OnTime,
    /// The deadline had passed by more than a period: the schedule restarts from now.
    Late,
}

pub struct Pacer {
    period: Duration,
    /// The next frame's deadline, CLOCK_MONOTONIC.
    next: Duration,
    margin: Duration,
}

impl Pacer {
    /// A pacer whose first deadline is one period from now. Call on the thread it paces:
    /// it sets that thread's timer slack.
    pub fn new(period: Duration) -> Pacer {
        // SAFETY: prctl with PR_SET_TIMERSLACK takes one integer argument; it only
        // changes the calling thread's timer slack (1 ns: the smallest allowed).
        unsafe { libc::prctl(libc::PR_SET_TIMERSLACK, 1 as libc::c_ulong, 0, 0, 0) };
        short_slice();
        Pacer { period, next: now(), margin: MIN_MARGIN }
    }

    pub fn period(&self) -> Duration {
        self.period
    }

    /// Waits for the next frame's deadline.
    pub fn wait(&mut self) -> Frame {
        self.next += self.period;
        let now = now();
        if now > self.next + self.period {
            self.next = now;
            return Frame::Late;
        }
        if let Some(wake) = self.next.checked_sub(self.margin).filter(|&w| w > now) {
            sleep_until(wake);
            let woke = self::now();
            self.margin = adapt(self.margin, woke.saturating_sub(wake));
        }
        while self::now() < self.next {
            // Anything runnable on this core (another robot's thread) goes first.
            std::thread::yield_now();
        }
        Frame::OnTime
    }
}

/// The next margin after a wake-up `late` past its target: up at once to cover it,
/// down slowly (1/16 per frame) when wake-ups become prompt again.
fn adapt(margin: Duration, late: Duration) -> Duration {
    let decayed = margin - margin / 16;
    (late + late / 4).max(decayed).clamp(MIN_MARGIN, MAX_MARGIN)
}

/// The time slice a thread that must wake on time asks for: the kernel's minimum.
const SHORT_SLICE_NS: u64 = 100_000;

/// Asks the scheduler for a short time slice for the calling thread. Under EEVDF
/// (Linux ≥ 6.12) a waking thread with a short slice gets an early virtual deadline and
/// preempts a CPU-bound one, instead of waiting for that one's slice to run out: on a
/// loaded machine that is most of a frame thread's wake-up latency. Other kernels ignore
/// the slice or refuse the call; either way nothing else changes.
pub fn short_slice() {
    // SAFETY: getpriority reads the calling thread's nice value (who = 0: this thread).
    let nice = unsafe { libc::getpriority(libc::PRIO_PROCESS, 0) };
    // SAFETY: sched_attr is plain integers; all-zero is a valid value to fill in.
    let mut attr: libc::sched_attr = unsafe { std::mem::zeroed() };
    attr.size = std::mem::size_of::<libc::sched_attr>() as u32;
    attr.sched_policy = libc::SCHED_OTHER as u32;
    // sched_setattr sets the nice value too: keep the thread's own.
    attr.sched_nice = nice;
    attr.sched_runtime = SHORT_SLICE_NS;
    // SAFETY: sched_setattr(pid 0 = this thread, a valid attr of the size it says, flags 0).
    unsafe { libc::syscall(libc::SYS_sched_setattr, 0, &attr as *const libc::sched_attr, 0) };
}

fn now() -> Duration {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `ts` is a valid timespec to write; CLOCK_MONOTONIC always exists on Linux.
    unsafe { libc::clock_gettime(libc::CLOCK_MONOTONIC, &mut ts) };
    Duration::new(ts.tv_sec as u64, ts.tv_nsec as u32)
}

/// Sleeps until `t` on CLOCK_MONOTONIC (absolute, so time spent being woken does not add).
fn sleep_until(t: Duration) {
    let ts = libc::timespec { tv_sec: t.as_secs() as libc::time_t, tv_nsec: t.subsec_nanos() as libc::c_long };
    // SAFETY: `ts` is a valid timespec; no remaining-time output is asked for (null).
    while unsafe { libc::clock_nanosleep(libc::CLOCK_MONOTONIC, libc::TIMER_ABSTIME, &ts, std::ptr::null_mut()) } == libc::EINTR {}
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wait_never_returns_before_its_deadline() {
        let period = Duration::from_millis(1);
        let start = now();
        let mut p = Pacer::new(period);
        for k in 1..=20u32 {
            // Each deadline is start + k periods, however late the previous wake-up was.
            let deadline = p.next + period;
            if p.wait() == Frame::OnTime {
                assert!(now() >= deadline, "frame {k} returned early");
                assert!(deadline >= start + period * k, "the schedule never slips back");
            }
        }
    }

    #[test]
    fn a_wait_past_a_whole_period_is_late_and_restarts_the_schedule() {
        let period = Duration::from_millis(1);
        let mut p = Pacer::new(period);
        std::thread::sleep(period * 3);
        let before = now();
        assert_eq!(p.wait(), Frame::Late);
        assert!(p.next >= before, "the schedule restarts from the wait, not from the missed deadlines");
    }

    #[test]
    fn the_margin_follows_late_wake_ups_within_bounds() {
        let us = Duration::from_micros;
        assert_eq!(adapt(MIN_MARGIN, us(0)), MIN_MARGIN, "never below the minimum");
        assert_eq!(adapt(MIN_MARGIN, us(40)), us(50), "covers a late wake-up at once, with a quarter more");
        assert_eq!(adapt(us(160), us(0)), us(150), "then comes down by a sixteenth per frame");
        assert_eq!(adapt(us(50), us(5000)), MAX_MARGIN, "never above the maximum");
    }

    #[test]
    fn a_thread_gets_the_short_slice_it_asks_for() {
        let slice = std::thread::spawn(|| {
            // SAFETY: reads this thread's nice value.
            let nice = || unsafe { libc::getpriority(libc::PRIO_PROCESS, 0) };
            let before = nice();
            short_slice();
            assert_eq!(nice(), before, "the thread keeps its nice value");
            // Kernels with EEVDF list the slice; older ones have no such line (and no slices).
            let sched = std::fs::read_to_string("/proc/thread-self/sched").unwrap_or_default();
            sched.lines().find(|l| l.starts_with("se.slice")).and_then(|l| l.split(':').nth(1)?.trim().parse::<u64>().ok())
        })
        .join()
        .unwrap();
        if let Some(ns) = slice {
            assert_eq!(ns, SHORT_SLICE_NS);
        }
    }
}
