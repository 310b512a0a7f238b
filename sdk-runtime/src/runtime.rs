//! The "system" side of OPEN-R: the process-wide state every object reaches through the
//! host API — objects by OID, the service registry, shared memory, the clock, design
//! data and power state — and the two message primitives, send and call.
use std::ffi::CString;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::{Arc, Mutex, OnceLock, RwLock};
use std::time::Duration;

use crate::clock::Clock;
use crate::ms::MsDir;
use crate::object::{Envelope, ObjectSlot, Spun};
use crate::power::Power;
use crate::shm::ShmTable;

/// OID of the first user object; the rest follow in OBJECT.CFG order.
pub const FIRST_OID: usize = 0x8000_0040;
/// OID of the first system object (loaded before the user objects).
pub const FIRST_SYSTEM_OID: usize = 0x8000_0010;

/// A registered service (`OObject::RegisterServiceEntry`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Service {
    pub name: String,
    pub oid: usize,
    pub selector: u32,
}

/// Where the runtime's messages go. The CLI passes its shell's (cargo's layout and
/// colours); without one, plain lines go to stderr.
pub trait Report: Send + Sync {
    fn warn(&self, msg: &str);
    fn error(&self, msg: &str);
    fn note(&self, msg: &str);
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
}

pub struct Runtime {
    pub ms: MsDir,
    pub design: CString,
    pub design_db: Vec<(String, String)>,
    pub objects: RwLock<Vec<Arc<ObjectSlot>>>,
    pub registry: Mutex<Vec<Service>>,
    pub shm: ShmTable,
    pub design_data: Mutex<Vec<u32>>,
    pub clock: Clock,
    pub power: Power,
    pub diag: Diag,
    pub timers: crate::timers::Timers,
    pub vr: crate::vr::VrService,
    /// Data vectors handed out by `new_vector` (freed by `delete_vector`).
    pub vectors: Mutex<Vec<u32>>,
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
}

/// `Runtime::fatal` before any `OPENR::Fatal` (ofatalUNDEF is u32::MAX, a real value).
pub const NO_FATAL: u32 = 0xFFFF_FFFE;

static RUNTIME: OnceLock<Runtime> = OnceLock::new();

/// Why a message could not be delivered or answered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CallError {
    UnknownDestination,
    SelfCall,
    Timeout,
}

fn enqueue(sched: &crate::sched::Sched, slot: &ObjectSlot, env: Envelope) -> Result<(), CallError> {
    if sched.push(slot.index, || slot.tx.send(env).is_ok()) {
        return Ok(());
    }
    Err(CallError::UnknownDestination)
}

impl Runtime {
    /// Installs the process's runtime; there is one per process (the host API is global).
    pub fn install(rt: Runtime) -> &'static Runtime {
        if RUNTIME.set(rt).is_err() {
            panic!("one OPEN-R runtime per process");
        }
        RUNTIME.get().expect("just set")
    }

    pub fn get() -> Option<&'static Runtime> {
        RUNTIME.get()
    }

    pub fn object(&self, oid: usize) -> Option<Arc<ObjectSlot>> {
        // A handful of objects: a scan beats hashing.
        self.objects.read().unwrap_or_else(|p| p.into_inner()).iter().find(|s| s.oid == oid).cloned()
    }

    pub fn all_objects(&self) -> Vec<Arc<ObjectSlot>> {
        self.objects.read().unwrap_or_else(|p| p.into_inner()).clone()
    }

    /// Queues a message (asynchronous `Send`).
    pub fn send(&self, dest: usize, selector: u32, data: Vec<u8>) -> Result<(), CallError> {
        let slot = self.object(dest).ok_or(CallError::UnknownDestination)?;
        enqueue(&self.sched, &slot, Envelope { selector, data, reply: None, caller: None })?;
        self.links.count(|| crate::object::current().map(|me| me.oid), dest, selector);
        Ok(())
    }

    /// Whether a frame may start while every object is idle: the boot sequence is not
    /// between two steps, or an object waits for virtual time to pass.
    pub fn frames_allowed(&self) -> bool {
        let objects = self.objects.read().unwrap_or_else(|p| p.into_inner());
        objects.iter().any(|s| s.sleeping.load(Ordering::Acquire)) || !self.booting.load(Ordering::Acquire)
    }

    /// Sends and waits for the answer (`Call`), at most `timeout` if given.
    pub fn call(&self, dest: usize, selector: u32, data: Vec<u8>, timeout: Option<Duration>) -> Result<Vec<u8>, CallError> {
        self.call_with(dest, selector, data, timeout, || {})
    }

    /// Queues a call from outside the objects (the boot sequence) and returns where its
    /// answer will arrive.
    pub fn call_start(&self, dest: usize, selector: u32, data: Vec<u8>) -> Result<mpsc::Receiver<Vec<u8>>, CallError> {
        let slot = self.object(dest).ok_or(CallError::UnknownDestination)?;
        let (tx, rx) = mpsc::sync_channel(1);
        enqueue(&self.sched, &slot, Envelope { selector, data, reply: Some(tx), caller: None })?;
        Ok(rx)
    }

    /// `call`, running `queued` once the message is queued (the boot sequence gives the
    /// turn back there).
    pub fn call_with(&self, dest: usize, selector: u32, data: Vec<u8>, timeout: Option<Duration>, queued: impl FnOnce()) -> Result<Vec<u8>, CallError> {
        let me = crate::object::current();
        if me.as_ref().is_some_and(|me| me.oid == dest) {
            return Err(CallError::SelfCall);
        }
        let slot = self.object(dest).ok_or(CallError::UnknownDestination)?;
        let (tx, rx) = mpsc::sync_channel(1);
        let caller = me.as_ref().map(|m| m.index);
        enqueue(&self.sched, &slot, Envelope { selector, data, reply: Some(tx), caller })?;
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

    pub fn register(&self, name: &str, oid: usize, selector: u32) -> bool {
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
