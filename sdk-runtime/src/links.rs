//! The connections of CONNECT.CFG that the boot sequence made, each with a count of the
//! messages the runtime delivered on it: notifications (subject → observer) and ready
//! messages (observer → subject). The registry knows a service by its Control/Connect
//! entry; its Notify/Ready entries the runtime learns from the first message between the
//! two objects to another entry (object-model 2.8). [`Links::count`] runs on every send,
//! so it scans a short list and bumps atomics, with no lock.
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering};
use std::sync::OnceLock;

use openr_sys::Selector;

use crate::runtime::Service;

/// `entry` before the first message: `Selector::UNDEF`, which no entry has.
const UNSET: u32 = Selector::UNDEF.0;

/// One way of a connection: messages from object `from` to object `to`'s entry `entry`.
/// A cache line of its own: the two ways of a link are counted by different threads.
#[derive(Debug)]
#[repr(align(64))]
pub struct Way {
    from: usize,
    to: usize,
    /// The registered entry (Control, Connect): the handshake, not counted.
    registered: Selector,
    /// The entry's selector (`Selector.0`, atomic), or `UNSET`.
    entry: AtomicU32,
    /// Messages delivered this way.
    pub count: AtomicU64,
}

impl Way {
    fn new(from: &Service, to: &Service) -> Way {
        Way { from: from.oid, to: to.oid, registered: to.selector, entry: AtomicU32::new(UNSET), count: AtomicU64::new(0) }
    }

    fn is(&self, sender: usize, dest: usize, selector: Selector) -> bool {
        self.from == sender && self.to == dest && self.registered != selector
    }
}

/// One made connection and its counts.
#[derive(Debug)]
pub struct Link {
    /// CONNECT.CFG's names: `object.service.type.S` and `object.service.type.O`.
    pub subject: String,
    pub observer: String,
    /// Notifications, to the observer.
    pub notify: Way,
    /// Ready (assert/deassert) messages, to the subject.
    pub ready: Way,
}

/// Every made connection, fixed once the connection phase ends.
#[derive(Debug, Default)]
pub struct Links {
    made: OnceLock<Vec<Link>>,
}

impl Links {
    /// The connection phase's result: `(subject, observer)` services that connected.
    pub fn set(&self, made: Vec<(Service, Service)>) {
        let links = made.into_iter().map(|(s, o)| Link { notify: Way::new(&s, &o), ready: Way::new(&o, &s), subject: s.name, observer: o.name }).collect();
        let _ = self.made.set(links);
    }

    /// The connections (none before the connection phase ends).
    pub fn all(&self) -> &[Link] {
        self.made.get().map_or(&[], Vec::as_slice)
    }

    /// Counts a message `sender` (an OID, asked only for a message to a connected
    /// object) sent to `(dest, selector)`.
    pub fn count(&self, sender: impl Fn() -> Option<usize>, dest: usize, selector: Selector) {
        let Some(links) = self.made.get() else { return };
        if !links.iter().any(|l| l.notify.to == dest || l.ready.to == dest) {
            return;
        }
        let Some(sender) = sender() else { return };
        let ways = || links.iter().flat_map(|l| [&l.notify, &l.ready]).filter(|w| w.is(sender, dest, selector));
        // The way whose entry this is; else the first between these objects whose entry
        // is not known yet takes it.
        let way = ways()
            .find(|w| w.entry.load(Ordering::Relaxed) == selector.0)
            .or_else(|| ways().find(|w| w.entry.compare_exchange(UNSET, selector.0, Ordering::Relaxed, Ordering::Relaxed).is_ok()));
        if let Some(w) = way {
            w.count.fetch_add(1, Ordering::Relaxed);
        }
    }
}
