//! `SetTimeEvent`: messages delivered to an object after a delay of virtual time,
//! optionally periodic. The frame thread fires what is due after each frame.
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};
use std::sync::Mutex;
use std::time::Duration;

use openr_sys::{Selector, TimerId};

struct Timer {
    dest: usize,
    selector: Selector,
    msg: Vec<u8>,
    period: Option<Duration>,
}

#[derive(Default)]
struct State {
    next_id: u32,
    timers: HashMap<TimerId, Timer>,
    due: BinaryHeap<Reverse<(Duration, TimerId)>>,
}

#[derive(Default)]
pub struct Timers {
    state: Mutex<State>,
}

impl Timers {
    pub fn new() -> Timers {
        Timers::default()
    }

    /// Adds a timer due `after` the virtual time `now`.
    pub fn add(&self, now: Duration, dest: usize, selector: Selector, msg: Vec<u8>, after: Duration, period: Option<Duration>) -> TimerId {
        let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        s.next_id = s.next_id.wrapping_add(1).max(1);
        let id = TimerId(s.next_id);
        s.timers.insert(id, Timer { dest, selector, msg, period: period.filter(|p| !p.is_zero()) });
        s.due.push(Reverse((now + after, id)));
        id
    }

    pub fn cancel(&self, id: TimerId) -> bool {
        self.state.lock().unwrap_or_else(|p| p.into_inner()).timers.remove(&id).is_some()
    }

    /// Hands every message due at virtual time `now` to `deliver`.
    pub fn fire_due(&self, now: Duration, deliver: impl Fn(usize, Selector, Vec<u8>)) {
        let mut due = Vec::new();
        {
            let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
            while let Some(&Reverse((at, id))) = s.due.peek() {
                if at > now {
                    break;
                }
                s.due.pop();
                let Some(t) = s.timers.get(&id) else { continue };
                due.push((t.dest, t.selector, t.msg.clone()));
                match t.period {
                    Some(p) => s.due.push(Reverse((at + p, id))),
                    None => {
                        s.timers.remove(&id);
                    }
                }
            }
        }
        for (dest, sel, msg) in due {
            deliver(dest, sel, msg);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex as M;

    #[test]
    fn one_shot_periodic_and_cancelled() {
        let t = Timers::new();
        let ms = Duration::from_millis;
        let a = t.add(ms(0), 1, Selector(10), vec![1], ms(16), None);
        let _b = t.add(ms(0), 1, Selector(11), vec![2], ms(8), Some(ms(8)));
        let c = t.add(ms(0), 1, Selector(12), vec![3], ms(8), None);
        assert!(t.cancel(c));
        let got = M::new(Vec::new());
        for f in 1..=3 {
            t.fire_due(ms(8 * f), |_, sel, _| got.lock().unwrap().push((f, sel.0)));
        }
        assert_eq!(*got.lock().unwrap(), [(1, 11), (2, 10), (2, 11), (3, 11)]);
        assert!(!t.cancel(a), "a one-shot timer is gone once fired");
    }
}
