//! `SetTimeEvent`: messages delivered to an object after a delay, optionally periodic.
use std::collections::{BinaryHeap, HashMap};
use std::cmp::Reverse;
use std::sync::{Condvar, Mutex};
use std::time::{Duration, Instant};

struct Timer {
    dest: usize,
    selector: u32,
    msg: Vec<u8>,
    period: Option<Duration>,
}

#[derive(Default)]
struct State {
    next_id: u32,
    timers: HashMap<u32, Timer>,
    due: BinaryHeap<Reverse<(Instant, u32)>>,
}

pub struct Timers {
    state: Mutex<State>,
    wake: Condvar,
}

impl Timers {
    pub fn new() -> Timers {
        Timers { state: Mutex::new(State::default()), wake: Condvar::new() }
    }

    pub fn add(&self, dest: usize, selector: u32, msg: Vec<u8>, after: Duration, period: Option<Duration>) -> u32 {
        let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        s.next_id = s.next_id.wrapping_add(1).max(1);
        let id = s.next_id;
        s.timers.insert(id, Timer { dest, selector, msg, period });
        s.due.push(Reverse((Instant::now() + after, id)));
        self.wake.notify_one();
        id
    }

    pub fn cancel(&self, id: u32) -> bool {
        self.state.lock().unwrap_or_else(|p| p.into_inner()).timers.remove(&id).is_some()
    }

    /// Runs forever on its own thread, handing due messages to `deliver`.
    pub fn run(&self, deliver: impl Fn(usize, u32, Vec<u8>)) -> ! {
        let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        loop {
            let now = Instant::now();
            match s.due.peek().copied() {
                Some(Reverse((at, id))) if at <= now => {
                    s.due.pop();
                    let Some(t) = s.timers.get(&id) else { continue };
                    let (dest, sel, msg) = (t.dest, t.selector, t.msg.clone());
                    match t.period {
                        Some(p) => s.due.push(Reverse((at + p, id))),
                        None => {
                            s.timers.remove(&id);
                        }
                    }
                    drop(s);
                    deliver(dest, sel, msg);
                    s = self.state.lock().unwrap_or_else(|p| p.into_inner());
                }
                Some(Reverse((at, _))) => s = self.wake.wait_timeout(s, at - now).unwrap_or_else(|p| p.into_inner()).0,
                None => s = self.wake.wait(s).unwrap_or_else(|p| p.into_inner()),
            }
        }
    }
}

impl Default for Timers {
    fn default() -> Timers {
        Timers::new()
    }
}
