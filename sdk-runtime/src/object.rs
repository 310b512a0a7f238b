//! One OPEN-R object: a thread named after it, a message queue, and a single-threaded
//! loop that dispatches each message by selector through the object's entry table
//! (object-model 2.1).
use std::cell::{Cell, RefCell};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, SyncSender};
use std::sync::{Arc, OnceLock};

use crate::loader::Module;
use openr_sys::Selector;

/// A message on its way to an object.
pub struct Envelope {
    pub selector: Selector,
    pub data: Vec<u8>,
    /// Present when the sender waits for `Reply`/`Return` (a `Call`).
    pub reply: Option<SyncSender<Vec<u8>>>,
    /// The calling object's index, when an object made the call.
    pub caller: Option<usize>,
}

/// Zero bytes after a message's own as its entry gets it (`run_loop`).
const SLACK: usize = 64;

/// A message's bytes, with room for the slack its receiver adds (no second allocation).
pub(crate) fn message(bytes: &[u8]) -> Vec<u8> {
    let mut v = Vec::with_capacity(bytes.len() + SLACK);
    v.extend_from_slice(bytes);
    v
}

/// Everything the runtime knows about one loaded object.
pub struct ObjectSlot {
    pub index: usize,
    /// The OID address, e.g. 0x80000040; printed by OSYSLOG as 8 hex digits.
    pub oid: usize,
    /// The `.BIN` path as OBJECT.CFG wrote it.
    pub bin: String,
    pub module: OnceLock<Module>,
    /// Its message queue (`mailbox`).
    pub mailbox: crate::mailbox::Mailbox<Envelope>,
    /// Set when the object called `exit()`: it no longer runs (object-model 1.5).
    pub stopped: AtomicBool,
    /// Inside a sleep on virtual time (frames may run during the boot then).
    pub sleeping: AtomicBool,
}

impl crate::sched::Wake for ObjectSlot {
    fn wake(&self) {
        self.mailbox.wake();
    }
}

impl ObjectSlot {
    /// A slot for the object loaded `index`th, before its module is.
    pub fn new(index: usize, oid: usize, bin: String) -> ObjectSlot {
        ObjectSlot { index, oid, bin, module: OnceLock::new(), mailbox: Default::default(), stopped: AtomicBool::new(false), sleeping: AtomicBool::new(false) }
    }

    /// The object's name: its ocf NAME, else the `.BIN` file name.
    pub fn name(&self) -> &str {
        self.module.get().and_then(|m| m.ocf_name.as_deref()).unwrap_or_else(|| self.bin.rsplit('/').next().unwrap_or(&self.bin))
    }

    pub fn is_stopped(&self) -> bool {
        self.stopped.load(Ordering::Acquire)
    }
}

thread_local! {
    /// The object whose thread this is.
    static CURRENT: RefCell<Option<Arc<ObjectSlot>>> = const { RefCell::new(None) };
    /// The reply channel of the message being processed, until answered.
    static PENDING_REPLY: RefCell<Option<(SyncSender<Vec<u8>>, Option<usize>)>> = const { RefCell::new(None) };
    /// Object index and selector being run, read by the crash handler.
    pub(crate) static RUNNING: Cell<(usize, Selector)> = const { Cell::new((usize::MAX, Selector::UNDEF)) };
    /// `CURRENT` as a plain pointer: the crash handler reads it without touching the
    /// `RefCell` or the `Arc` (the slot outlives the thread).
    pub(crate) static CURRENT_SLOT: Cell<*const ObjectSlot> = const { Cell::new(std::ptr::null()) };
}

pub fn current() -> Option<Arc<ObjectSlot>> {
    CURRENT.with(|c| c.borrow().clone())
}

/// The calling object's OID (no reference count taken, unlike `current`).
pub fn current_oid() -> Option<usize> {
    CURRENT.with(|c| c.borrow().as_ref().map(|s| s.oid))
}

pub(crate) fn set_current(slot: Arc<ObjectSlot>) {
    RUNNING.with(|r| r.set((slot.index, Selector::UNDEF)));
    if let Some(rt) = crate::runtime::Runtime::get() {
        rt.console.register_thread(slot.index);
    }
    CURRENT_SLOT.with(|c| c.set(Arc::as_ptr(&slot)));
    CURRENT.with(|c| *c.borrow_mut() = Some(slot));
}

/// Answers the current call, if any is pending. Returns whether a reply was sent.
pub fn reply_current(bytes: &[u8]) -> bool {
    match PENDING_REPLY.with(|p| p.borrow_mut().take()) {
        Some((tx, caller)) => {
            if let (Some(c), Some(rt)) = (caller, crate::runtime::Runtime::get()) {
                rt.sched.answered(c);
            }
            let _ = tx.send(bytes.to_vec());
            true
        }
        None => false,
    }
}

/// What a brief spin (`spin`) found on a channel.
pub(crate) enum Spun<T> {
    Got(T),
    /// The sender is gone.
    Gone,
    /// Nothing yet: the caller parks.
    Nothing,
}

pub(crate) fn spin_recv<T>(rx: &Receiver<T>) -> Spun<T> {
    use std::sync::mpsc::TryRecvError;
    match crate::spin::poll(|| match rx.try_recv() {
        Ok(v) => Some(Spun::Got(v)),
        Err(TryRecvError::Disconnected) => Some(Spun::Gone),
        Err(TryRecvError::Empty) => None,
    }) {
        Some(spun) => spun,
        None => Spun::Nothing,
    }
}

/// The object's message loop; it runs as long as the process (objects are never
/// unloaded).
pub(crate) fn run_loop(slot: &ObjectSlot, warn: impl Fn(String)) -> ! {
    let module = slot.module.get().expect("loaded before the loop starts");
    let rt = crate::runtime::Runtime::get().expect("objects run in a runtime");
    let sched = &rt.sched;
    loop {
        let mut env = slot.mailbox.recv();
        sched.begin(slot.index, env.selector);
        let Some(entry) = module.entry(env.selector) else {
            warn(format!("object `{}` has no entry for selector {}: message dropped", slot.name(), env.selector));
            PENDING_REPLY.with(|p| *p.borrow_mut() = env.reply.take().map(|tx| (tx, env.caller)));
            reply_current(&[]);
            sched.end(slot.index);
            continue;
        };
        PENDING_REPLY.with(|p| *p.borrow_mut() = env.reply.take().map(|tx| (tx, env.caller)));
        RUNNING.with(|r| r.set((slot.index, env.selector)));
        // Keep a little slack after the message: C++ code may read a struct slightly
        // larger than what a short sender wrote.
        env.data.resize(env.data.len() + SLACK, 0);
        // SAFETY: `entry` is a function of the object's ObjectEntryTable (`void (*)(void*)`), given the
        // message bytes plus 64 bytes of slack, live for the call.
        unsafe { entry(env.data.as_mut_ptr().cast()) };
        RUNNING.with(|r| r.set((slot.index, Selector::UNDEF)));
        rt.console.handled(slot.index);
        // A call whose entry returned without Reply/Return gets an empty answer, so the
        // caller is never left waiting forever.
        reply_current(&[]);
        sched.end(slot.index);
    }
}
