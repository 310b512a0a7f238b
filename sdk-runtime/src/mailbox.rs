//! An object's message queue: many senders, one receiver (the object's thread).
//!
//! Made for the hand-off OPEN-R programs live on (a notify answered by a ready, vision →
//! behaviour → motion): the receiver spins a little before it parks (`spin`), and a
//! sender makes a system call only when the receiver is parked. An empty queue is seen
//! without the lock (one atomic load per poll), so a spinning receiver does not slow
//! the sender down.
use std::collections::VecDeque;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Condvar, Mutex, MutexGuard};

/// What the lock guards.
struct Inner<T> {
    queue: VecDeque<T>,
    /// The receiver is parked on `cv` (under the lock, so a sender cannot miss a
    /// receiver about to park).
    parked: bool,
    /// The receiver is gone (its object never loaded): sends fail.
    closed: bool,
}

pub struct Mailbox<T> {
    inner: Mutex<Inner<T>>,
    /// Messages queued: what a spinning receiver polls (a cache line of its own, so
    /// the polling does not contend with senders taking the lock).
    queued: crate::padded::Line<AtomicUsize>,
    cv: Condvar,
}

impl<T> Default for Mailbox<T> {
    fn default() -> Self {
        Mailbox { inner: Mutex::new(Inner { queue: VecDeque::new(), parked: false, closed: false }), queued: Default::default(), cv: Condvar::new() }
    }
}

impl<T> Mailbox<T> {
    fn lock(&self) -> MutexGuard<'_, Inner<T>> {
        self.inner.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Queues `v`; wakes the receiver if it is parked. `Err(v)` once closed.
    pub fn send(&self, v: T) -> Result<(), T> {
        if self.post(v)? {
            self.wake();
        }
        Ok(())
    }

    /// Queues `v` without waking the receiver: `Ok(true)` when it is parked, and then
    /// [`Mailbox::wake`] must follow (later if the message cannot run yet anyway).
    pub fn post(&self, v: T) -> Result<bool, T> {
        let mut g = self.lock();
        if g.closed {
            return Err(v);
        }
        g.queue.push_back(v);
        self.queued.store(g.queue.len(), Ordering::Release);
        Ok(g.parked)
    }

    /// Wakes a receiver that `post` found parked (a spurious wake-up if it no longer
    /// is: it looks at its queue and parks again).
    pub fn wake(&self) {
        self.cv.notify_one();
    }

    /// No receiver will come: later sends fail, queued messages are dropped.
    pub fn close(&self) {
        let mut g = self.lock();
        g.closed = true;
        g.queue.clear();
        self.queued.store(0, Ordering::Release);
    }

    /// The first message, if one is queued.
    pub fn try_recv(&self) -> Option<T> {
        if self.queued.load(Ordering::Acquire) == 0 {
            return None;
        }
        let mut g = self.lock();
        let v = g.queue.pop_front();
        self.queued.store(g.queue.len(), Ordering::Release);
        v
    }

    /// The first message, waiting for one: spins first, then parks.
    pub fn recv(&self) -> T {
        if let Some(v) = crate::spin::poll(|| self.try_recv()) {
            return v;
        }
        let mut g = self.lock();
        loop {
            if let Some(v) = g.queue.pop_front() {
                self.queued.store(g.queue.len(), Ordering::Release);
                return v;
            }
            g.parked = true;
            g = self.cv.wait(g).unwrap_or_else(|p| p.into_inner());
            g.parked = false;
        }
    }

    /// No message waiting.
    pub fn is_empty(&self) -> bool {
        self.queued.load(Ordering::Acquire) == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    #[test]
    fn messages_arrive_in_order_from_many_senders() {
        let mb = Arc::new(Mailbox::default());
        let senders: Vec<_> = (0..4u64)
            .map(|k| {
                let mb = mb.clone();
                std::thread::spawn(move || (0..10_000u64).for_each(|i| mb.send((k, i)).unwrap()))
            })
            .collect();
        let mut next = [0u64; 4];
        for _ in 0..40_000 {
            let (k, i) = mb.recv();
            assert_eq!(i, next[k as usize], "sender {k}'s messages in its order");
            next[k as usize] += 1;
        }
        senders.into_iter().for_each(|t| t.join().unwrap());
        assert!(mb.is_empty() && mb.try_recv().is_none());
    }

    #[test]
    fn a_parked_receiver_is_woken() {
        let mb = Arc::new(Mailbox::<u32>::default());
        let rx = {
            let mb = mb.clone();
            std::thread::spawn(move || (0..3).map(|_| mb.recv()).collect::<Vec<_>>())
        };
        // Long after any spin budget: the receiver is parked when these arrive.
        for v in [7, 8, 9] {
            while !mb.inner.lock().unwrap().parked {
                std::thread::yield_now();
            }
            mb.send(v).unwrap();
        }
        assert_eq!(rx.join().unwrap(), [7, 8, 9]);
    }

    #[test]
    fn a_post_says_the_receiver_is_parked_and_wake_wakes_it() {
        let mb = Arc::new(Mailbox::<u32>::default());
        assert_eq!(mb.post(1), Ok(false), "nobody parked yet");
        assert_eq!(mb.recv(), 1);
        let rx = {
            let mb = mb.clone();
            std::thread::spawn(move || mb.recv())
        };
        while !mb.inner.lock().unwrap().parked {
            std::thread::yield_now();
        }
        assert_eq!(mb.post(5), Ok(true));
        mb.wake();
        assert_eq!(rx.join().unwrap(), 5);
    }

    #[test]
    fn a_closed_mailbox_refuses() {
        let mb = Mailbox::default();
        mb.send(1).unwrap();
        mb.close();
        assert_eq!(mb.send(2), Err(2));
        assert!(mb.try_recv().is_none(), "queued messages dropped");
    }
}
