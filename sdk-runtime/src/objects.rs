//! The run's loaded objects, read on every message (`Runtime::send` finds the
//! destination here) and appended to only while the boot sequence loads them.
//!
//! Readers take no lock and write no shared memory: a lock's reader count, or an `Arc`
//! cloned per send, is a cache line that the two objects of a notify/ready hand-off
//! would pass between their cores on every message. Each load publishes a new list;
//! the ones it replaces are kept (a reader may still be looking at one) until the
//! runtime itself is dropped — a few dozen small lists per run at most.
use std::sync::atomic::{AtomicPtr, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

use crate::object::ObjectSlot;

type List = Vec<Arc<ObjectSlot>>;

pub struct Objects {
    /// The newest list: an element of `lists`, so never null and never freed while
    /// `self` lives.
    current: AtomicPtr<List>,
    /// Every list published so far, the newest last (also serialises `push`).
    lists: Mutex<Vec<Box<List>>>,
}

impl Default for Objects {
    fn default() -> Self {
        let mut first = Box::new(List::new());
        let current = AtomicPtr::new(&mut *first);
        Objects { current, lists: Mutex::new(vec![first]) }
    }
}

impl Objects {
    fn lists(&self) -> MutexGuard<'_, Vec<Box<List>>> {
        self.lists.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Every object loaded so far, in load order (`ObjectSlot::index`).
    pub fn all(&self) -> &[Arc<ObjectSlot>] {
        // SAFETY: `current` points into a box of `lists`, which are never changed after
        // they are published and only freed when `self` is dropped (no `&self` left).
        unsafe { &*self.current.load(Ordering::Acquire) }
    }

    /// The object with OID `oid`.
    pub fn get(&self, oid: usize) -> Option<&Arc<ObjectSlot>> {
        // A handful of objects: a scan beats hashing.
        self.all().iter().find(|s| s.oid == oid)
    }

    /// Appends the slot `make` builds for the next index; returns it.
    pub fn push(&self, make: impl FnOnce(usize) -> Arc<ObjectSlot>) -> Arc<ObjectSlot> {
        let mut lists = self.lists();
        let mut next = Box::new(lists.last().map_or_else(List::new, |l| List::clone(l)));
        let slot = make(next.len());
        next.push(slot.clone());
        self.current.store(&mut *next, Ordering::Release);
        lists.push(next);
        slot
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slot(index: usize) -> Arc<ObjectSlot> {
        Arc::new(ObjectSlot::new(index, 0x8000_0040 + 8 * index, format!("/MS/OPEN-R/MW/OBJS/O{index}.BIN")))
    }

    #[test]
    fn a_reader_keeps_its_list_while_objects_are_added() {
        let objects = Objects::default();
        assert!(objects.all().is_empty() && objects.get(0x8000_0040).is_none());
        let first = objects.push(slot);
        let seen = objects.all();
        for _ in 0..40 {
            objects.push(slot);
        }
        assert_eq!(seen.len(), 1, "an earlier list stays as it was, and alive");
        assert!(Arc::ptr_eq(&seen[0], &first));
        assert_eq!(objects.all().len(), 41);
        let found = objects.get(0x8000_0040 + 8 * 17).expect("loaded");
        assert_eq!((found.index, found.bin.as_str()), (17, "/MS/OPEN-R/MW/OBJS/O17.BIN"));
        assert!(objects.all().iter().enumerate().all(|(i, s)| s.index == i), "indices in load order");
    }

    #[test]
    fn readers_on_other_threads_see_whole_lists() {
        let objects = Arc::new(Objects::default());
        let reader = {
            let objects = objects.clone();
            std::thread::spawn(move || {
                let mut last = 0;
                while last < 200 {
                    let all = objects.all();
                    assert!(all.len() >= last, "lists only grow");
                    assert!(all.iter().enumerate().all(|(i, s)| s.index == i));
                    last = all.len();
                }
            })
        };
        for _ in 0..200 {
            objects.push(slot);
        }
        reader.join().unwrap();
    }
}
