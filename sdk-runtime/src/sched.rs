//! Turns: at `--speed max` the objects run one message at a time, in the order the
//! messages were sent, so that a run depends on the program and its inputs only (the
//! robot's one CPU runs one object at a time too). Every message sent gets a ticket in
//! one global queue; an object runs a message when its ticket is first in line and
//! nobody holds the turn. The turn is given back while an object waits for the answer
//! to a call or sleeps on virtual time, and the waiter gets it back first (callers when
//! answered, sleepers in order of wake time, then object index). The boot sequence and
//! the frame thread take the turn too while they send, so their messages land between
//! two messages of the objects, never during one.
//!
//! Two ways out keep virtual time going whatever the objects do:
//! * a frame starts when every object is idle, or after [`FRAME_WORK`] messages have
//!   been delivered since the previous frame (counted, so deterministic: objects that
//!   keep messaging each other still see time pass, as on the robot);
//! * an object whose one message runs longer than the watchdog in real time (a busy
//!   loop, a read of the console) loses the turn and runs on outside the turns until
//!   that message returns: the others, and virtual time, go on without it.
//!
//! At other speeds nothing is serialised: messages get no ticket.
use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use openr_sys::Selector;

/// Messages delivered after which the next frame starts even though objects are still
/// busy. The ERS-7's CPU handles roughly 1000 inter-object messages in one 8 ms frame (an
/// estimate: Aperios needs some microseconds per message); a program doing more work
/// than that in a frame would not keep its frame rate on the robot either.
pub const FRAME_WORK: u64 = 1000;

/// How long a holder runs one message before it is looked at for a console read.
const CONSOLE_PROBE: Duration = Duration::from_millis(5);

/// How often waiters look at the watchdog (and at a change of speed) while waiting.
const RECHECK: Duration = Duration::from_millis(20);

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Holder {
    Object(usize),
    /// The boot sequence or the frame thread.
    External,
}

#[derive(Default)]
struct State {
    /// One entry per queued message: the index of the object it waits at, in send order.
    queue: VecDeque<usize>,
    holder: Option<Holder>,
    held_since: Option<Instant>,
    /// (object index, selector) of the message being run by the holder.
    running: Option<(usize, Selector)>,
    /// Objects that get the turn back before any new message: answered callers and
    /// woken sleepers.
    resume: VecDeque<usize>,
    /// Objects waiting for the answer to a call they made holding the turn.
    calling: BTreeSet<usize>,
    /// Objects sleeping on virtual time that held the turn: (wake time, index).
    sleepers: BTreeSet<(Duration, usize)>,
    /// Objects whose message outran the watchdog (they run outside the turns until it
    /// returns), and objects that called exit(): their tickets wait.
    detached: BTreeSet<usize>,
    retired: BTreeSet<usize>,
    /// Messages delivered since the last frame, and per object.
    delivered: u64,
    window: BTreeMap<usize, u64>,
    /// The frame thread, at the end of virtual time, left its turn to the shutdown.
    handed_over: bool,
    /// Objects reported stuck, for the caller to warn about once: (index, selector).
    stuck: Vec<(usize, Selector)>,
    /// What each object past [`BUSY_SLOTS`] is running now (at every speed): index →
    /// selector (the others are in `Sched::busy`).
    busy: BTreeMap<usize, Selector>,
    /// Threads parked on the condition variable: a change wakes them only when there
    /// are any (a futex wake is a system call even with nobody waiting).
    parked: usize,
    /// The frame thread is parked on `frame_cv`.
    frame_parked: bool,
    /// Parked receivers of messages sent while the turn was held, by object index: they
    /// are woken once the turn is given back (see [`Sched::push`]).
    deferred: Vec<(usize, Arc<dyn Wake>)>,
}

impl State {
    /// The first queued message whose object takes part in the turns.
    fn head(&self) -> Option<(usize, usize)> {
        self.queue.iter().enumerate().map(|(pos, &i)| (pos, i)).find(|(_, i)| !self.detached.contains(i) && !self.retired.contains(i))
    }

    fn free(&self) -> bool {
        self.holder.is_none() && self.resume.is_empty()
    }

    fn take(&mut self, h: Holder) {
        self.holder = Some(h);
        self.held_since = Some(Instant::now());
    }

    fn give_back(&mut self) {
        self.holder = None;
        self.held_since = None;
        self.running = None;
    }
}

/// A parked receiver to wake (an object's mailbox).
pub trait Wake: Send + Sync {
    fn wake(&self);
}

/// Objects whose running selector is kept outside the lock (`Sched::busy`).
const BUSY_SLOTS: usize = 256;
/// `Sched::busy`: not running a message.
const IDLE: Selector = Selector::UNDEF;

thread_local! {
    /// The message this thread runs began on the fast path (no ticket, no turn).
    static FAST: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

pub struct Sched {
    state: Mutex<State>,
    /// The selector each object runs now, by index, when not `IDLE`; written by the
    /// object's own thread, read by the shutdown sequence.
    busy: Box<[crate::padded::Line<std::sync::atomic::AtomicU32>]>,
    /// Tickets queued (`State::queue.len()`, kept under the lock): none, and nothing
    /// serialised, lets a message begin and end without the lock.
    tickets: std::sync::atomic::AtomicUsize,
    cv: Condvar,
    /// Where the frame thread parks in `frame_turn`.
    frame_cv: Condvar,
    /// Bumped (under the lock) by every change a waiter may be waiting for: spinning
    /// waiters watch it instead of parking.
    changes: AtomicU64,
    serial: AtomicBool,
    watchdog: Mutex<Duration>,
}

impl Default for Sched {
    fn default() -> Sched {
        Sched {
            state: Mutex::default(),
            busy: (0..BUSY_SLOTS).map(|_| crate::padded::Line(std::sync::atomic::AtomicU32::new(IDLE.0))).collect(),
            tickets: std::sync::atomic::AtomicUsize::new(0),
            cv: Condvar::new(),
            frame_cv: Condvar::new(),
            changes: AtomicU64::new(0),
            serial: AtomicBool::new(false),
            watchdog: Mutex::new(Duration::from_secs(5)),
        }
    }
}

impl Sched {
    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Waits for a change: spins a little first (`spin`), then parks.
    fn wait<'a>(&'a self, s: MutexGuard<'a, State>) -> MutexGuard<'a, State> {
        self.wait_as(s, false)
    }

    /// `wait`; the frame thread (`frame`) parks apart and is woken only by a change
    /// that may let a frame start (see `frame_may_start`), not by every message.
    fn wait_as<'a>(&'a self, s: MutexGuard<'a, State>, frame: bool) -> MutexGuard<'a, State> {
        let seen = self.changes.load(Ordering::Acquire);
        drop(s);
        let changed = crate::spin::poll(|| (self.changes.load(Ordering::Acquire) != seen).then_some(())).is_some();
        let mut s = self.lock();
        if !changed && self.changes.load(Ordering::Acquire) == seen {
            if frame {
                s.frame_parked = true;
                s = self.frame_cv.wait_timeout(s, RECHECK).unwrap_or_else(|p| p.into_inner()).0;
                s.frame_parked = false;
            } else {
                s.parked += 1;
                s = self.cv.wait_timeout(s, RECHECK).unwrap_or_else(|p| p.into_inner()).0;
                s.parked -= 1;
            }
        }
        self.check_watchdog(&mut s);
        s
    }

    /// Whether the parked frame thread should look again: the turn is free and no
    /// message waits, or the frame's share of messages is used up. (Whether the boot
    /// allows frames is not the scheduler's to see: the frame thread looks at it at
    /// least every `RECHECK`.)
    fn frame_may_start(s: &State) -> bool {
        s.frame_parked && s.free() && (s.delivered >= FRAME_WORK || s.head().is_none())
    }

    /// After a change to the state: wakes the waiters, and, when the turn is free, the
    /// receivers whose wake-up waited for it (outside the lock: a woken thread's first
    /// step is to take it).
    fn changed(&self, mut s: MutexGuard<'_, State>) {
        self.changes.fetch_add(1, Ordering::AcqRel);
        let parked = s.parked > 0;
        let frame = Self::frame_may_start(&s);
        let deferred = Self::take_deferred(&mut s);
        drop(s);
        if parked {
            self.cv.notify_all();
        }
        if frame {
            self.frame_cv.notify_one();
        }
        deferred.into_iter().for_each(|(_, w)| w.wake());
    }

    /// `changed` from inside a wait, keeping the lock.
    fn changed_locked(&self, s: &mut State) {
        self.changes.fetch_add(1, Ordering::AcqRel);
        if s.parked > 0 {
            self.cv.notify_all();
        }
        if Self::frame_may_start(s) {
            self.frame_cv.notify_one();
        }
        Self::take_deferred(s).into_iter().for_each(|(_, w)| w.wake());
    }

    fn take_deferred(s: &mut State) -> Vec<(usize, Arc<dyn Wake>)> {
        if s.holder.is_none() {
            std::mem::take(&mut s.deferred)
        } else {
            Vec::new()
        }
    }

    /// A holder past the watchdog loses the turn; so does one waiting for console input
    /// (idle as on the robot, where it would not hold the CPU), without a report.
    fn check_watchdog(&self, s: &mut State) {
        let limit = *self.watchdog.lock().unwrap_or_else(|p| p.into_inner());
        if let (Some(Holder::Object(i)), Some(t)) = (s.holder, s.held_since) {
            if t.elapsed() >= CONSOLE_PROBE && crate::runtime::Runtime::get().is_some_and(|rt| rt.console.blocked_reading(i)) {
                s.detached.insert(i);
                s.give_back();
                self.changed_locked(s);
            } else if t.elapsed() >= limit {
                let sel = s.running.map_or(Selector::UNDEF, |r| r.1);
                s.detached.insert(i);
                s.stuck.push((i, sel));
                s.give_back();
                self.changed_locked(s);
            }
        }
    }

    fn serial(&self) -> bool {
        self.serial.load(Ordering::Acquire)
    }

    /// Serialise (speed `max`) or not.
    pub fn set_serial(&self, on: bool) {
        self.serial.store(on, Ordering::Release);
        self.changed(self.lock());
    }

    pub fn set_watchdog(&self, d: Duration) {
        *self.watchdog.lock().unwrap_or_else(|p| p.into_inner()) = d;
    }

    /// The selector of the message object `index` is running (or waiting to run), if any.
    pub fn running(&self, index: usize) -> Option<Selector> {
        match self.busy.get(index) {
            Some(b) => Some(Selector(b.load(Ordering::Acquire))).filter(|&sel| sel != IDLE),
            None => self.lock().busy.get(&index).copied(),
        }
    }

    fn set_busy(&self, s: &mut State, index: usize, selector: Option<Selector>) {
        match (self.busy.get(index), selector) {
            (Some(b), sel) => b.store(sel.unwrap_or(IDLE).0, Ordering::Release),
            (None, Some(sel)) => drop(s.busy.insert(index, sel)),
            (None, None) => drop(s.busy.remove(&index)),
        }
    }

    /// Objects that outran the watchdog since the last call: (index, selector).
    pub fn take_stuck(&self) -> Vec<(usize, Selector)> {
        std::mem::take(&mut self.lock().stuck)
    }

    /// Queues a ticket for object `index` if `post` (which queues the message and says
    /// whether `receiver` is parked) succeeds; both under one lock, so tickets and
    /// messages are in the same order. A parked receiver is woken outside the lock (a
    /// system call there would keep every other sender and receiver waiting for it).
    ///
    /// While the turn is held, a message can run only after it is given back, so its
    /// parked receiver is woken then: once, instead of once for the message and again
    /// for the turn (the frame thread's sensor and completion events, a notify and its
    /// ready). A receiver outside the turns (past the watchdog) is woken at once.
    ///
    /// Not serialised, a message gets no ticket and is posted outside the lock.
    pub fn push<W: Wake + 'static>(&self, index: usize, receiver: &Arc<W>, post: impl FnOnce() -> Option<bool>) -> bool {
        if !self.serial() {
            let Some(parked) = post() else { return false };
            if parked {
                receiver.wake();
            }
            return true;
        }
        let mut s = self.lock();
        let Some(parked) = post() else { return false };
        s.queue.push_back(index);
        self.tickets.store(s.queue.len(), Ordering::Release);
        let later = s.holder.is_some() && !s.detached.contains(&index);
        if parked && later && !s.deferred.iter().any(|&(i, _)| i == index) {
            s.deferred.push((index, receiver.clone()));
        }
        self.changed(s);
        if parked && !later {
            receiver.wake();
        }
        true
    }

    /// A message begins without the lock when nothing is serialised and no ticket is
    /// left from a serialised spell: it would run at once anyway, and nobody waits for
    /// it to begin or end.
    fn fast(&self, index: usize, selector: Selector) -> bool {
        let Some(b) = self.busy.get(index) else { return false };
        if self.serial() || self.tickets.load(Ordering::Acquire) != 0 {
            return false;
        }
        b.store(selector.0, Ordering::Release);
        true
    }

    /// Object thread, before running a message it received: waits for its turn.
    pub fn begin(&self, index: usize, selector: Selector) {
        let fast = self.fast(index, selector);
        FAST.with(|f| f.set(fast));
        if fast {
            return;
        }
        let mut s = self.lock();
        self.set_busy(&mut s, index, Some(selector));
        loop {
            let ticket = s.queue.iter().position(|&i| i == index);
            // A message sent while nothing was serialised has no ticket: it runs as it
            // would have then.
            if !self.serial() || s.detached.contains(&index) || ticket.is_none() {
                if let Some(pos) = ticket {
                    s.queue.remove(pos);
                    self.tickets.store(s.queue.len(), Ordering::Release);
                }
                return;
            }
            // After FRAME_WORK messages the objects wait for the frame (or the boot
            // sequence) to take its turn, so it comes at the same message every run.
            if s.free() && s.delivered < FRAME_WORK {
                if let Some((pos, i)) = s.head() {
                    if i == index {
                        s.queue.remove(pos);
                        self.tickets.store(s.queue.len(), Ordering::Release);
                        s.take(Holder::Object(index));
                        s.running = Some((index, selector));
                        s.delivered += 1;
                        *s.window.entry(index).or_default() += 1;
                        return;
                    }
                }
            }
            s = self.wait(s);
        }
    }

    /// Object thread, after a message: gives the turn back (or rejoins the turns, after
    /// a message that outran the watchdog).
    pub fn end(&self, index: usize) {
        // Begun on the fast path: it took no turn and nobody waits for its end (the
        // shutdown sequence polls `running`).
        if FAST.with(|f| f.replace(false)) {
            if let Some(b) = self.busy.get(index) {
                b.store(IDLE.0, Ordering::Release);
            }
            return;
        }
        let mut s = self.lock();
        if s.holder == Some(Holder::Object(index)) {
            s.give_back();
        }
        s.detached.remove(&index);
        self.set_busy(&mut s, index, None);
        self.changed(s);
    }

    /// The object called exit(): it never runs again.
    pub fn retire(&self, index: usize) {
        let mut s = self.lock();
        if s.holder == Some(Holder::Object(index)) {
            s.give_back();
        }
        s.retired.insert(index);
        self.changed(s);
    }

    /// Object `index` (after queuing its call) waits for an answer: gives the turn back.
    /// Returns whether it held the turn (then `call_returned` must follow).
    pub fn calling(&self, index: usize) -> bool {
        let mut s = self.lock();
        if s.holder != Some(Holder::Object(index)) {
            return false;
        }
        s.give_back();
        s.calling.insert(index);
        self.changed(s);
        true
    }

    /// The holder answers the call of `caller` (before the answer is sent): the caller
    /// gets the turn next.
    pub fn answered(&self, caller: usize) {
        let mut s = self.lock();
        if s.calling.remove(&caller) {
            s.resume.push_back(caller);
        }
    }

    /// The caller has its answer (or gave up waiting): waits for the turn back.
    pub fn call_returned(&self, index: usize) {
        let mut s = self.lock();
        if s.calling.remove(&index) {
            s.resume.push_back(index); // timed out: nobody answered
        }
        self.resume(s, index);
    }

    /// Object `index` sleeps on virtual time until `until`: gives the turn back.
    pub fn sleeping(&self, index: usize, until: Duration) -> bool {
        let mut s = self.lock();
        if s.holder != Some(Holder::Object(index)) {
            return false;
        }
        s.give_back();
        s.sleepers.insert((until, index));
        self.changed(s);
        true
    }

    /// The sleeper woke: waits until the frame thread has queued it and the turn is free.
    pub fn woke(&self, index: usize) {
        self.resume(self.lock(), index);
    }

    fn resume<'a>(&'a self, mut s: MutexGuard<'a, State>, index: usize) {
        loop {
            if !self.serial() {
                s.resume.retain(|&i| i != index);
                s.sleepers.retain(|&(_, i)| i != index);
                return;
            }
            if s.holder.is_none() && s.resume.front() == Some(&index) {
                s.resume.pop_front();
                s.take(Holder::Object(index));
                return;
            }
            s = self.wait(s);
        }
    }

    /// Frame thread, with the turn: sleepers due by `now` get the turn back in order.
    pub fn wake_sleepers(&self, now: Duration) {
        let mut s = self.lock();
        while let Some(&(t, i)) = s.sleepers.first() {
            if t > now {
                break;
            }
            s.sleepers.pop_first();
            s.resume.push_back(i);
        }
    }

    /// Frame thread at `max`: waits until every object is idle and `may_run()` (the
    /// boot sequence allows frames), or until [`FRAME_WORK`] messages were delivered
    /// since the last frame; then holds the turn. Returns the objects that were still
    /// busy (index, messages since the last frame) in the second case.
    pub fn frame_turn(&self, may_run: impl Fn() -> bool) -> Vec<(usize, u64)> {
        let mut s = self.lock();
        loop {
            if s.free() {
                let idle = s.head().is_none() && may_run();
                if idle || s.delivered >= FRAME_WORK {
                    let busy = if idle { Vec::new() } else { s.window.iter().map(|(&i, &n)| (i, n)).collect() };
                    s.delivered = 0;
                    s.window.clear();
                    s.take(Holder::External);
                    return busy;
                }
            }
            s = self.wait_as(s, true);
        }
    }

    /// Boot sequence: waits until every object is idle (or [`FRAME_WORK`] messages went
    /// by while waiting, or nothing is serialised), then holds the turn.
    pub fn boot_turn(&self) {
        let mut s = self.lock();
        loop {
            if s.handed_over {
                s.handed_over = false;
                s.delivered = 0;
                return;
            }
            if s.free() && (!self.serial() || s.head().is_none() || s.delivered >= FRAME_WORK) {
                s.delivered = 0;
                s.take(Holder::External);
                return;
            }
            s = self.wait(s);
        }
    }

    /// Frame thread, holding the turn when virtual time has ended: keeps it for the
    /// shutdown sequence (`take_over`), so Stop comes at the same message every run.
    pub fn hand_over(&self) {
        let mut s = self.lock();
        s.handed_over = true;
        self.changed(s);
    }

    /// Shutdown at `--speed max`: waits (at most `patience`) for the frame thread to hand
    /// over its turn, then holds it; otherwise takes the turn as `boot_turn` does.
    pub fn take_over(&self, patience: Duration) {
        let deadline = Instant::now() + patience;
        let mut s = self.lock();
        while !s.handed_over && self.serial() && Instant::now() < deadline {
            s = self.wait(s);
        }
        drop(s);
        self.boot_turn();
    }

    /// The boot sequence or the frame thread gives the turn back.
    pub fn release(&self) {
        let mut s = self.lock();
        if s.holder == Some(Holder::External) {
            s.give_back();
        }
        self.changed(s);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    /// A receiver that counts its wake-ups.
    #[derive(Default)]
    struct Counted(std::sync::atomic::AtomicUsize);

    impl Wake for Counted {
        fn wake(&self) {
            self.0.fetch_add(1, Ordering::SeqCst);
        }
    }

    fn nobody() -> Arc<Counted> {
        Arc::default()
    }

    #[test]
    fn a_parked_receiver_is_woken_once_the_turn_is_free() {
        let sched = Sched::default();
        let rx = Arc::new(Counted::default());
        let woken = || rx.0.load(Ordering::SeqCst);
        // Not serialised, or serialised with the turn free: at once.
        assert!(sched.push(1, &rx, || Some(true)));
        assert_eq!(woken(), 1);
        sched.set_serial(true);
        assert!(sched.push(1, &rx, || Some(true)));
        assert_eq!(woken(), 2);
        // A receiver that is not parked needs no wake-up; a refused post queues nothing.
        assert!(sched.push(1, &rx, || Some(false)));
        assert!(!sched.push(1, &rx, || None));
        assert_eq!((woken(), sched.tickets.load(Ordering::SeqCst)), (2, 2), "tickets only when serialised");
        // The turn held: two messages, one wake-up, when the turn is given back.
        let sched = Sched::default();
        sched.set_serial(true);
        sched.boot_turn();
        assert!(sched.push(1, &rx, || Some(true)));
        assert!(sched.push(1, &rx, || Some(true)));
        assert_eq!(woken(), 2, "woken while it could not run");
        sched.release();
        assert_eq!(woken(), 3);
    }

    #[test]
    fn objects_run_in_the_order_their_messages_were_sent() {
        let sched = Arc::new(Sched::default());
        sched.set_serial(true);
        sched.boot_turn();
        for i in [2, 0, 1, 2] {
            assert!(sched.push(i, &nobody(), || Some(false)));
        }
        let log = Arc::new(Mutex::new(Vec::new()));
        let threads: Vec<_> = (0..3)
            .map(|i| {
                let (sched, log) = (sched.clone(), log.clone());
                std::thread::spawn(move || {
                    for _ in 0..if i == 2 { 2 } else { 1 } {
                        sched.begin(i, Selector(1));
                        log.lock().unwrap().push(i);
                        sched.end(i);
                    }
                })
            })
            .collect();
        std::thread::sleep(Duration::from_millis(30));
        assert!(log.lock().unwrap().is_empty(), "nobody runs while the boot holds the turn");
        sched.release();
        for t in threads {
            t.join().unwrap();
        }
        assert_eq!(*log.lock().unwrap(), [2, 0, 1, 2]);
    }

    #[test]
    fn a_frame_starts_after_frame_work_messages_and_names_the_busy() {
        let sched = Arc::new(Sched::default());
        sched.set_serial(true);
        let s2 = sched.clone();
        assert!(sched.push(0, &nobody(), || Some(false)));
        let pingpong = std::thread::spawn(move || {
            for n in 0..2 * FRAME_WORK + 10 {
                let me = (n % 2) as usize;
                s2.begin(me, Selector(4));
                assert!(s2.push(1 - me, &nobody(), || Some(false)));
                s2.end(me);
            }
        });
        let busy = sched.frame_turn(|| true);
        let total: u64 = busy.iter().map(|b| b.1).sum();
        assert_eq!(total, FRAME_WORK, "{busy:?}");
        assert_eq!(busy.iter().map(|b| b.0).collect::<Vec<_>>(), [0, 1]);
        sched.release();
        let busy = sched.frame_turn(|| true);
        assert_eq!(busy.iter().map(|b| b.1).sum::<u64>(), FRAME_WORK, "the next frame after as many messages");
        sched.release();
        pingpong.join().unwrap();
    }

    #[test]
    fn a_holder_past_the_watchdog_loses_the_turn() {
        let sched = Sched::default();
        sched.set_serial(true);
        sched.set_watchdog(Duration::from_millis(50));
        assert!(sched.push(3, &nobody(), || Some(false)));
        sched.begin(3, Selector(1));
        // Object 3 never ends its message: the frame still gets its turn.
        assert!(sched.frame_turn(|| true).is_empty());
        assert_eq!(sched.take_stuck(), [(3, Selector(1))]);
        sched.release();
    }
}
