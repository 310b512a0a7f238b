//! The "system" side of OPEN-R: the state of one robot that every object reaches through
//! the host API — objects by OID, the service registry, shared memory, the clock, design
//! data and power state — and the two message primitives, send and call.
//!
//! A [`Runtime`] is an instance: a process may run several sticks at once (the tests do).
//! Object code calls the host API with no context argument (the C ABI of the robot), so
//! each thread knows the runtime it works for ([`Runtime::enter`]): the object threads,
//! the runtime's own ([`spawn`]) and the threads objects start (`crash::exits`). A thread
//! that was given none (a library's helper thread) reaches the process's runtime while
//! there is exactly one.
use std::cell::Cell;
use std::ffi::CString;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use crate::clock::Clock;
use crate::ms::MsDir;
use crate::object::{Envelope, ObjectSlot, Spun};
use crate::power::Power;
use crate::shm::ShmTable;
use openr_sys::{DesignDataId, MemId, Selector};

/// OID of the first user object; the rest follow in OBJECT.CFG order.
pub const FIRST_OID: usize = 0x8000_0040;
/// OID of the first system object (loaded before the user objects).
pub const FIRST_SYSTEM_OID: usize = 0x8000_0010;

/// A registered service (`OObject::RegisterServiceEntry`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Service {
    pub name: String,
    pub oid: usize,
    pub selector: Selector,
}

/// Where the runtime's messages go. The CLI passes its shell's (cargo's layout and
/// colours); without one, plain lines go to stderr.
pub trait Report: Send + Sync {
    fn warn(&self, msg: &str);
    fn error(&self, msg: &str);
    fn note(&self, msg: &str);
    /// A plain line of its own (the IPStack's port remaps and `OPENR_NET_TRACE` lines).
    fn line(&self, text: &str);
}

/// `warning: …`, `error: …`, `       note: …` on stderr, no colour.
pub struct PlainStderr;

impl Report for PlainStderr {
    fn warn(&self, msg: &str) {
        eprintln!("warning: {msg}");
    }
    fn error(&self, msg: &str) {
        eprintln!("error: {msg}");
    }
    fn note(&self, msg: &str) {
        eprintln!("{:>12} {msg}", "note:");
    }
    fn line(&self, text: &str) {
        eprintln!("{text}");
    }
}

/// How runtime diagnostics are shown: what `--quiet` / `--verbose` let through, and
/// where they go.
#[derive(Clone)]
pub struct Diag {
    pub quiet: bool,
    pub verbose: bool,
    pub report: Arc<dyn Report>,
}

impl Default for Diag {
    fn default() -> Diag {
        Diag::new(false, false)
    }
}

impl std::fmt::Debug for Diag {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Diag").field("quiet", &self.quiet).field("verbose", &self.verbose).finish_non_exhaustive()
    }
}

impl Diag {
    pub fn new(quiet: bool, verbose: bool) -> Diag {
        Diag { quiet, verbose, report: Arc::new(PlainStderr) }
    }

    /// The same settings, reported through `report`.
    pub fn with_report(self, report: Arc<dyn Report>) -> Diag {
        Diag { report, ..self }
    }

    pub fn warn(&self, msg: &str) {
        if !self.quiet {
            self.report.warn(msg);
        }
    }
    /// Always shown (`--quiet` too).
    pub fn error(&self, msg: &str) {
        self.report.error(msg);
    }
    pub fn info(&self, msg: &str) {
        if self.verbose {
            self.report.note(msg);
        }
    }
    /// A plain line, unless `--quiet`.
    pub fn line(&self, text: &str) {
        if !self.quiet {
            self.report.line(text);
        }
    }
}

pub struct Runtime {
    pub ms: MsDir,
    pub design: CString,
    pub design_db: Vec<(String, String)>,
    pub objects: crate::objects::Objects,
    pub registry: Mutex<Vec<Service>>,
    pub shm: ShmTable,
    pub design_data: Mutex<Vec<(DesignDataId, MemId)>>,
    pub clock: Clock,
    pub power: Power,
    pub diag: Diag,
    pub timers: crate::timers::Timers,
    pub vr: crate::vr::VrService,
    /// Data vectors handed out by `new_vector` (freed by `delete_vector`).
    pub vectors: Mutex<Vec<MemId>>,
    pub shutdown_requested: AtomicBool,
    /// The OFatal of an `OPENR::Fatal` call (`NO_FATAL`: none).
    pub fatal: std::sync::atomic::AtomicU32,
    /// True until every Start has been sent: at `--speed max` virtual time waits for the
    /// boot sequence too (unless an object sleeps in it), so runs are reproducible.
    pub booting: AtomicBool,
    /// Whose turn it is to run a message (reproducible `--speed max`).
    pub sched: crate::sched::Sched,
    /// SIGINT/SIGTERM/SIGHUP received (0: none), seen by every phase of the run.
    pub signal: std::sync::atomic::AtomicI32,
    /// CONNECT.CFG's made connections and their message counts (the view shows them).
    pub links: crate::links::Links,
    /// This run's network settings and its IPStack, started on first use (net.rs).
    pub net: crate::net::NetState,
    /// The TCP gateway of Remote Processing, when the stick has one (gateway/).
    pub gateway: crate::gateway::State,
    /// Which objects wait for console input (console.rs).
    pub console: crate::console::input::Watch,
    /// Panics stopped at the host API's boundary (a non-zero count fails the run).
    pub internal_errors: std::sync::atomic::AtomicU32,
}

/// `Runtime::fatal` before any `OPENR::Fatal` (ofatalUNDEF is u32::MAX, a real value).
pub const NO_FATAL: u32 = 0xFFFF_FFFE;

thread_local! {
    /// The runtime this thread works for.
    static CURRENT: Cell<Option<&'static Runtime>> = const { Cell::new(None) };
}

/// The runtimes of this process whose run has not ended.
static LIVE: Mutex<Vec<&'static Runtime>> = Mutex::new(Vec::new());

/// Starts a thread that works for the calling thread's runtime (if it has one).
pub fn spawn<F, T>(name: impl Into<String>, f: F) -> std::io::Result<std::thread::JoinHandle<T>>
where
    F: FnOnce() -> T + Send + 'static,
    T: Send + 'static,
{
    let rt = Runtime::get();
    std::thread::Builder::new().name(name.into()).spawn(move || {
        if let Some(rt) = rt {
            rt.enter();
        }
        f()
    })
}

/// Why a message could not be delivered or answered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CallError {
    UnknownDestination,
    SelfCall,
    Timeout,
}

fn enqueue(sched: &crate::sched::Sched, slot: &Arc<ObjectSlot>, env: Envelope) -> Result<(), CallError> {
    if sched.push(slot.index, slot, || slot.mailbox.post(env).ok()) {
        return Ok(());
    }
    Err(CallError::UnknownDestination)
}

impl Runtime {
    /// Makes `rt` a live runtime of this process, the calling thread's. It is never
    /// freed: an object blocked for good (a Call after `OPENR::Fatal`, a read of the
    /// console) keeps its thread, and that thread its runtime, to the process's end.
    pub fn install(rt: Runtime) -> &'static Runtime {
        let rt: &'static Runtime = Box::leak(Box::new(rt));
        LIVE.lock().unwrap_or_else(|p| p.into_inner()).push(rt);
        rt.enter();
        rt
    }

    /// The run ended: the calling thread and threads that were given no runtime no
    /// longer reach this one.
    pub fn retire(&'static self) {
        LIVE.lock().unwrap_or_else(|p| p.into_inner()).retain(|r| !std::ptr::eq(*r, self));
        CURRENT.with(|c| {
            if c.get().is_some_and(|r| std::ptr::eq(r, self)) {
                c.set(None);
            }
        });
    }

    /// The calling thread works for this runtime from now on.
    pub fn enter(&'static self) {
        CURRENT.with(|c| c.set(Some(self)));
    }

    /// The runtime the calling thread works for; on a thread given none, the process's
    /// only live runtime.
    pub fn get() -> Option<&'static Runtime> {
        CURRENT.with(|c| c.get()).or_else(|| match LIVE.lock().unwrap_or_else(|p| p.into_inner()).as_slice() {
            [only] => Some(*only),
            _ => None,
        })
    }

    pub fn object(&self, oid: usize) -> Option<&Arc<ObjectSlot>> {
        self.objects.get(oid)
    }

    /// Every loaded object, in load order (`ObjectSlot::index`).
    pub fn all_objects(&self) -> &[Arc<ObjectSlot>] {
        self.objects.all()
    }

    /// Queues a message (asynchronous `Send`).
    pub fn send(&self, dest: usize, selector: Selector, data: Vec<u8>) -> Result<(), CallError> {
        let slot = self.object(dest).ok_or(CallError::UnknownDestination)?;
        enqueue(&self.sched, slot, Envelope { selector, data, reply: None, caller: None })?;
        self.links.count(crate::object::current_oid, dest, selector);
        Ok(())
    }

    /// Whether a frame may start while every object is idle: the boot sequence is not
    /// between two steps, or an object waits for virtual time to pass.
    pub fn frames_allowed(&self) -> bool {
        self.all_objects().iter().any(|s| s.sleeping.load(Ordering::Acquire)) || !self.booting.load(Ordering::Acquire)
    }

    /// Sends and waits for the answer (`Call`), at most `timeout` if given.
    pub fn call(&self, dest: usize, selector: Selector, data: Vec<u8>, timeout: Option<Duration>) -> Result<Vec<u8>, CallError> {
        self.call_with(dest, selector, data, timeout, || {})
    }

    /// Queues a call from outside the objects (the boot sequence) and returns where its
    /// answer will arrive.
    pub fn call_start(&self, dest: usize, selector: Selector, data: Vec<u8>) -> Result<mpsc::Receiver<Vec<u8>>, CallError> {
        let slot = self.object(dest).ok_or(CallError::UnknownDestination)?;
        let (tx, rx) = mpsc::sync_channel(1);
        enqueue(&self.sched, slot, Envelope { selector, data, reply: Some(tx), caller: None })?;
        Ok(rx)
    }

    /// `call`, running `queued` once the message is queued (the boot sequence gives the
    /// turn back there).
    pub fn call_with(&self, dest: usize, selector: Selector, data: Vec<u8>, timeout: Option<Duration>, queued: impl FnOnce()) -> Result<Vec<u8>, CallError> {
        let me = crate::object::current();
        if me.as_ref().is_some_and(|me| me.oid == dest) {
            return Err(CallError::SelfCall);
        }
        let slot = self.object(dest).ok_or(CallError::UnknownDestination)?;
        let (tx, rx) = mpsc::sync_channel(1);
        let caller = me.as_ref().map(|m| m.index);
        enqueue(&self.sched, slot, Envelope { selector, data, reply: Some(tx), caller })?;
        queued();
        let held = caller.is_some_and(|i| self.sched.calling(i));
        let answer = match (crate::object::spin_recv(&rx), timeout) {
            (Spun::Got(v), _) => Ok(v),
            (Spun::Gone, _) => Err(CallError::UnknownDestination),
            (Spun::Nothing, Some(t)) => rx.recv_timeout(t).map_err(|e| match e {
                RecvTimeoutError::Timeout => CallError::Timeout,
                RecvTimeoutError::Disconnected => CallError::UnknownDestination,
            }),
            (Spun::Nothing, None) => rx.recv().map_err(|_| CallError::UnknownDestination),
        };
        if let (true, Some(i)) = (held, caller) {
            self.sched.call_returned(i);
        }
        answer
    }

    pub fn register(&self, name: &str, oid: usize, selector: Selector) -> bool {
        let mut reg = self.registry.lock().unwrap_or_else(|p| p.into_inner());
        if reg.iter().any(|s| s.name == name) {
            return false;
        }
        reg.push(Service { name: name.to_string(), oid, selector });
        true
    }

    pub fn unregister_all_of(&self, oid: usize) {
        self.registry.lock().unwrap_or_else(|p| p.into_inner()).retain(|s| s.oid != oid);
    }

    pub fn service(&self, name: &str) -> Option<Service> {
        self.registry.lock().unwrap_or_else(|p| p.into_inner()).iter().find(|s| s.name == name).cloned()
    }

    pub fn service_names(&self) -> Vec<String> {
        self.registry.lock().unwrap_or_else(|p| p.into_inner()).iter().map(|s| s.name.clone()).collect()
    }

    pub fn request_shutdown(&self) {
        // No frame after this one: where the run ends depends on the program only.
        self.clock.freeze();
        self.shutdown_requested.store(true, Ordering::Release);
    }
}
