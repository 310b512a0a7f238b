//! Spin, then park. On this kind of machine a futex wake-up costs 5–60 µs (the sleeper
//! is scheduled back in), while an OPEN-R object usually gets its next message within
//! microseconds of handling the last one (vision → behaviour → motion chains, a notify
//! answered by a ready). A waiter therefore polls for a short while before it parks;
//! a sender then finds it awake and makes no system call at all.
//!
//! Spinning takes a core, so at most `cores − 1` threads of the process spin at once
//! (none on one core), and each for at most the budget; with every slot taken a waiter
//! spins its first few microseconds (the slot's holder is often the thread about to
//! send to it), then polls yielding its core at each round up to [`SHARED_SPIN`] (the
//! default budget: the cap only shortens a longer `OPENR_SPIN_US`), then parks. A thread whose spins
//! keep coming up empty (an object that gets a message a frame, not a chain of them)
//! spins only now and then, to notice when that changes. `OPENR_SPIN_US` sets the budget (0: never
//! spin).
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// Long enough to cover a message's typical turnaround, short enough that an idle
/// object gives its core back well within a frame (8 ms).
const DEFAULT_BUDGET: Duration = Duration::from_micros(50);

/// How long a waiter spins before it also yields its core at each round.
const PURE_SPIN: Duration = Duration::from_micros(3);

/// How long a waiter that found every slot taken polls before it parks (at most the
/// budget). At `--speed max` a frame hands the turn along a chain (frame thread →
/// OVirtualRobotComm → the program's objects → back), one thread holding the slot: the
/// next message often comes 5–20 µs later, and a park there costs a wake-up of 5–60 µs.
/// Measured with movelegs (host time per frame, 7 runs each): 3 µs → 12.7 µs a frame,
/// 10 → 8–9, 20 → 5.4–5.5, 50 → 4.8–5.0 (bench, 3 runs: 4.75–4.80; 16 camera robots in
/// real time still 0 late frames). Past `PURE_SPIN` the poll yields its core each
/// round, so on a busy machine it mostly lets others run (notify→ready with two CPU
/// hogs on the 2 cores: 2.9 µs, the blocking channel's 11.8). The same as the default
/// budget, so it only caps a longer `OPENR_SPIN_US`.
const SHARED_SPIN: Duration = DEFAULT_BUDGET;

/// Empty spins in a row after which a thread spins only on every [`PROBE`]th wait.
const MISSES: u32 = 3;
const PROBE: u32 = 8;

static SPINNING: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// This thread's empty spins in a row, and waits since it last spun.
    static HISTORY: Cell<(u32, u32)> = const { Cell::new((0, 0)) };
}

struct Config {
    budget: Duration,
    slots: usize,
}

fn config() -> &'static Config {
    static CONFIG: OnceLock<Config> = OnceLock::new();
    CONFIG.get_or_init(|| {
        let budget = std::env::var("OPENR_SPIN_US").ok().and_then(|v| v.trim().parse().ok()).map_or(DEFAULT_BUDGET, Duration::from_micros);
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        Config { budget, slots: cores.saturating_sub(1) }
    })
}

/// Gives the spin slot back however the spin ends.
struct Slot(&'static AtomicUsize);

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::AcqRel);
    }
}

fn take_slot(spinning: &'static AtomicUsize, slots: usize) -> Option<Slot> {
    spinning.fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| (n < slots).then_some(n + 1)).ok().map(|_| Slot(spinning))
}

/// Polls `poll` until it gives a value or the budget is spent; `None` means: park now.
pub fn poll<T>(poll: impl FnMut() -> Option<T>) -> Option<T> {
    let (spin, history) = plan(HISTORY.with(Cell::get));
    if !spin {
        HISTORY.with(|h| h.set(history));
        return None;
    }
    let got = poll_with(&SPINNING, config(), poll);
    HISTORY.with(|h| h.set(if got.is_some() { (0, 0) } else { (history.0.saturating_add(1), 0) }));
    got
}

/// Whether to spin this time, given (empty spins in a row, waits since the last spin);
/// and the history to keep if not.
fn plan((misses, skipped): (u32, u32)) -> (bool, (u32, u32)) {
    if misses >= MISSES && skipped + 1 < PROBE {
        (false, (misses, skipped + 1))
    } else {
        (true, (misses, skipped))
    }
}

fn poll_with<T>(spinning: &'static AtomicUsize, c: &Config, poll: impl FnMut() -> Option<T>) -> Option<T> {
    if c.budget.is_zero() {
        return None;
    }
    let Some(_slot) = take_slot(spinning, c.slots) else {
        // Every slot taken — typically by the very thread this one answered, about to
        // find its answer and send the next message (a notify/ready ping-pong, a
        // frame's chain): a short poll still catches that without a wake-up.
        if c.slots == 0 {
            return None; // one core: whoever would answer cannot run meanwhile
        }
        return spin(SHARED_SPIN.min(c.budget), poll);
    };
    spin(c.budget, poll)
}

/// Polls until `poll` gives a value or `budget` has passed; past `PURE_SPIN` it also
/// yields the core at each round.
fn spin<T>(budget: Duration, mut poll: impl FnMut() -> Option<T>) -> Option<T> {
    let start = Instant::now();
    loop {
        // The clock is read once per batch: it costs more than a poll.
        for _ in 0..16 {
            if let Some(v) = poll() {
                return Some(v);
            }
            std::hint::spin_loop();
        }
        let spent = start.elapsed();
        if spent >= budget {
            return None;
        }
        // Past the first microseconds the thread we wait for may be queued behind us on
        // this very core (cores oversubscribed): let it run.
        if spent >= PURE_SPIN {
            std::thread::yield_now();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_are_bounded_and_given_back() {
        static MINE: AtomicUsize = AtomicUsize::new(0);
        let a = take_slot(&MINE, 1).expect("a free slot");
        assert!(take_slot(&MINE, 1).is_none(), "one slot only");
        drop(a);
        assert!(take_slot(&MINE, 1).is_some(), "given back on drop");
        assert!(take_slot(&MINE, 0).is_none(), "no slot on one core");
    }

    #[test]
    fn poll_returns_what_arrives_and_gives_up_after_the_budget() {
        static MINE: AtomicUsize = AtomicUsize::new(0);
        let c = Config { budget: Duration::from_millis(1), slots: 1 };
        let mut n = 0;
        let got = poll_with(&MINE, &c, || {
            n += 1;
            (n == 5).then_some(n)
        });
        assert_eq!(got, Some(5));
        let start = Instant::now();
        assert_eq!(poll_with(&MINE, &c, || None::<()>), None);
        assert!(start.elapsed() >= c.budget);
        assert_eq!(MINE.load(Ordering::Acquire), 0, "the slot is given back");
        // Every slot taken: a value that comes within SHARED_SPIN is still caught, and
        // the wait ends soon after SHARED_SPIN, not after the (here very long) budget.
        let long = Config { budget: Duration::from_secs(10), slots: 1 };
        let held = take_slot(&MINE, 1).expect("the one slot");
        let mut n = 0;
        let got = poll_with(&MINE, &long, || {
            n += 1;
            (n == 3).then_some(n)
        });
        assert_eq!(got, Some(3));
        let start = Instant::now();
        assert_eq!(poll_with(&MINE, &long, || None::<()>), None);
        let waited = start.elapsed();
        assert!(waited >= SHARED_SPIN && waited < long.budget / 2, "{waited:?}");
        drop(held);
        let never = Config { budget: Duration::ZERO, slots: 1 };
        assert_eq!(poll_with(&MINE, &never, || Some(1)), None, "a zero budget never spins");
    }

    #[test]
    fn a_thread_whose_spins_come_up_empty_spins_only_now_and_then() {
        let mut h = (0, 0);
        for _ in 0..MISSES {
            assert!(plan(h).0, "spins while its spins pay");
            h = (h.0 + 1, 0); // came up empty
        }
        let spins: Vec<bool> = (0..2 * PROBE)
            .map(|_| {
                let (spin, next) = plan(h);
                h = if spin { (h.0 + 1, 0) } else { next };
                spin
            })
            .collect();
        assert_eq!(spins.iter().filter(|&&s| s).count(), 2, "one wait in {PROBE} probes: {spins:?}");
        assert!(plan((0, 0)).0, "a spin that found something resets the history");
    }
}
