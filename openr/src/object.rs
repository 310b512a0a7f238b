//! The object side: the `Object` trait a program implements, the `Context` that holds
//! its subjects and observers, typed handles, and the entry functions the `object!`
//! macro puts in `ObjectEntryTable`.
use std::any::Any;
use std::cell::RefCell;
use std::ffi::c_void;
use std::marker::PhantomData;

use crate::abi::{self, OConnectMessage, OControlMessage, ONotifyMessage, OReadyMessage, OServiceEntry, OStatusMessage, Selector};
use crate::comm::{self, Entry, ObserverState, SubjectState};
use crate::console::{osyslog, Priority};
use crate::host;
use crate::payload::Payload;
use crate::shm::Region;

/// `OStatus` values the API reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Success,
    Fail,
    /// An observer's buffer was full; the oldest data was dropped.
    Overflow,
    /// As `Overflow`, and the observer had less than `d_min` units.
    Fatal,
    NoMemory,
}

/// A program's object. Each callback runs on the object's own thread, one at a time.
pub trait Object: 'static {
    /// `DoInit`: declare subjects and observers (`ctx.subject`, `ctx.observer`).
    fn init(ctx: &mut Context) -> Self
    where
        Self: Sized;
    /// `DoStart`. The default asserts ready to every connected subject
    /// (`ASSERT_READY_TO_ALL_OBSERVER`).
    fn start(&mut self, ctx: &mut Context) {
        ctx.assert_ready_all();
    }
    /// `DoStop`. The default deasserts ready (`DEASSERT_READY_TO_ALL_OBSERVER`).
    fn stop(&mut self, ctx: &mut Context) {
        ctx.deassert_ready_all();
    }
    /// `DoDestroy`; the services are unregistered afterwards.
    fn destroy(&mut self, _ctx: &mut Context) {}
    /// An observer of one of our subjects asserted or deasserted ready.
    fn ready(&mut self, _ctx: &mut Context, _event: ReadyEvent) {}
    /// Data arrived at one of our observers. Call `assert_ready` on it for more.
    fn notify(&mut self, _ctx: &mut Context, _event: NotifyEvent) {}
    /// A message at the event entry (`SEL_EVENT`): what the object's own threads, which
    /// may not touch its subjects and observers, post to it through the runtime.
    fn event(&mut self, _ctx: &mut Context, _data: &[u8]) {}
}

/// ASSERT/DEASSERT-READY from an observer (`OReadyEvent`).
#[derive(Debug)]
pub struct ReadyEvent {
    subject: usize,
    observer: OServiceEntry,
    assert: bool,
}

impl ReadyEvent {
    pub fn is_assert(&self) -> bool {
        self.assert
    }
    pub fn is_deassert(&self) -> bool {
        !self.assert
    }
    /// The observer's (OID address, Notify selector).
    pub fn observer(&self) -> (usize, Selector) {
        (self.observer.oid as usize, self.observer.selector)
    }
}

/// A notification (`ONotifyEvent`): the regions of whole units, oldest first.
#[derive(Debug)]
pub struct NotifyEvent {
    observer: usize,
    subject: OServiceEntry,
    regions: Vec<Region>,
    units: usize,
}

impl NotifyEvent {
    pub fn regions(&self) -> &[Region] {
        &self.regions
    }
    /// Number of units (`NumOfNotify`).
    pub fn units(&self) -> usize {
        self.units
    }
    /// The subject's (OID address, Ready selector).
    pub fn subject(&self) -> (usize, Selector) {
        (self.subject.oid as usize, self.subject.selector)
    }
}

/// A subject declared with `Context::subject`, sending values of type `T`.
pub struct Subject<T: ?Sized> {
    index: usize,
    _t: PhantomData<fn(&T)>,
}

impl<T: ?Sized> Clone for Subject<T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T: ?Sized> Copy for Subject<T> {}

impl<T: ?Sized + Payload> Subject<T> {
    /// Whether `event` concerns this subject.
    pub fn is(&self, event: &ReadyEvent) -> bool {
        event.subject == self.index
    }

    /// `SetData(buf, size)`: copies `value` into a new region and queues it for every
    /// observer.
    pub fn set_data(&self, ctx: &mut Context, value: &T) -> Status {
        let Some(mut r) = Region::alloc(value.size()) else { return Status::NoMemory };
        value.write(r.bytes_mut());
        self.set_region(ctx, &r)
    }

    /// `SetData(RCRegion*)`: queues a region (no copy; each observer's queue takes a
    /// reference).
    pub fn set_region(&self, ctx: &mut Context, region: &Region) -> Status {
        ctx.subjects[self.index].set_data(region)
    }

    /// `NotifyObservers`: ends the unit and notifies observers that asserted ready.
    pub fn notify_observers(&self, ctx: &mut Context) -> Status {
        ctx.subjects[self.index].notify_observers()
    }

    /// `set_data` then `notify_observers`.
    pub fn send(&self, ctx: &mut Context, value: &T) -> Status {
        match self.set_data(ctx, value) {
            Status::NoMemory => Status::NoMemory,
            _ => self.notify_observers(ctx),
        }
    }

    /// Connected observers.
    pub fn observers(&self, ctx: &Context) -> usize {
        ctx.subjects[self.index].num_observers()
    }

    /// Observers that asserted ready and wait (`IsReady`).
    pub fn ready_observers(&self, ctx: &Context) -> usize {
        ctx.subjects[self.index].ready_count()
    }
}

/// An observer declared with `Context::observer`, receiving values of type `T`.
pub struct Observer<T: ?Sized> {
    index: usize,
    _t: PhantomData<fn(&T)>,
}

impl<T: ?Sized> Clone for Observer<T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T: ?Sized> Copy for Observer<T> {}

impl<T: ?Sized + Payload> Observer<T> {
    /// Whether `event` arrived at this observer.
    pub fn is(&self, event: &NotifyEvent) -> bool {
        event.observer == self.index
    }

    /// The `i`th region of `event` read as `T` (`None` if it is missing or malformed).
    pub fn data<'e>(&self, event: &'e NotifyEvent, i: usize) -> Option<&'e T> {
        T::read(event.regions.get(i)?.bytes())
    }

    /// `AssertReady`: returns what came from every subject and asks for more.
    pub fn assert_ready(&self, ctx: &mut Context) -> Status {
        ctx.observers[self.index].ready_all(abi::CMD_ASSERT_READY)
    }

    /// `DeassertReady`.
    pub fn deassert_ready(&self, ctx: &mut Context) -> Status {
        ctx.observers[self.index].ready_all(abi::CMD_DEASSERT_READY)
    }

    /// `SetBufCtrlParam` (object-model 2.8): every `skip + 1`th notification, at least
    /// `min` and at most `max` per delivery; sent to the subjects as they connect, so
    /// call it before the connection (in `init`). `max < min` (or `min` 0) is refused
    /// (`Fail`) and the values stay as they were.
    pub fn set_buf_ctrl_param(&self, ctx: &mut Context, skip: usize, min: usize, max: usize) -> Status {
        if max < min || min == 0 {
            return Status::Fail;
        }
        ctx.observers[self.index].buf = (skip, min, max);
        Status::Success
    }

    /// Connected subjects.
    pub fn subjects(&self, ctx: &Context) -> usize {
        ctx.observers[self.index].num_subjects()
    }
}

/// The object's protocol state: its subjects and observers.
pub struct Context {
    oid: *mut c_void,
    subjects: Vec<SubjectState>,
    observers: Vec<ObserverState>,
}

impl Context {
    fn new() -> Context {
        Context { oid: host::self_oid(), subjects: Vec::new(), observers: Vec::new() }
    }

    /// The object's name from the runtime (its ocf name).
    pub fn name(&self) -> String {
        match host::api() {
            // SAFETY: the runtime returns a NUL-terminated string, never NULL.
            Some(a) => unsafe { std::ffi::CStr::from_ptr((a.self_name)()) }.to_string_lossy().into_owned(),
            None => String::new(),
        }
    }

    /// Declares a subject and registers `service` ("Object.Name.type.S") at its Control
    /// entry. Panics beyond `MAX_SUBJECTS` subjects (a program error).
    pub fn subject<T: ?Sized + Payload>(&mut self, service: &str) -> Subject<T> {
        let k = self.subjects.len();
        assert!(k < comm::MAX_SUBJECTS, "openr: at most {} subjects per object", comm::MAX_SUBJECTS);
        self.subjects.push(SubjectState::new(service, self.oid, k));
        register(service, comm::subject_selectors(k).0);
        Subject { index: k, _t: PhantomData }
    }

    /// Declares an observer and registers `service` ("Object.Name.type.O") at its
    /// Connect entry.
    pub fn observer<T: ?Sized + Payload>(&mut self, service: &str) -> Observer<T> {
        let k = self.observers.len();
        assert!(k < comm::MAX_OBSERVERS, "openr: at most {} observers per object", comm::MAX_OBSERVERS);
        self.observers.push(ObserverState::new(service, self.oid, k));
        register(service, comm::observer_selectors(k).0);
        Observer { index: k, _t: PhantomData }
    }

    /// ASSERT-READY from every observer to every subject it is connected to.
    pub fn assert_ready_all(&mut self) {
        for o in &mut self.observers {
            let _ = o.ready_all(abi::CMD_ASSERT_READY);
        }
    }

    /// DEASSERT-READY from every observer.
    pub fn deassert_ready_all(&mut self) {
        for o in &mut self.observers {
            let _ = o.ready_all(abi::CMD_DEASSERT_READY);
        }
    }

    /// The observer's Connect entry (2.8.1): connects to the subject and answers.
    fn connect(&mut self, k: usize, msg: &OConnectMessage) -> u32 {
        if msg.msg_type != abi::OMSG_CONNECT {
            return abi::O_WRONG_MESSAGE;
        }
        let add = match msg.command {
            abi::OCONNECTCMD_CONNECT => true,
            abi::OCONNECTCMD_DISCONNECT | abi::OCONNECTCMD_DISCONNECTALL => false,
            _ => return abi::O_UNKNOWN_COMMAND,
        };
        let command = if add { abi::CMD_ADDOBSERVER_V22 } else { abi::CMD_REMOVEOBSERVER_V22 };
        let ctl: OControlMessage = self.observers[k].control_message(command, &msg.sub_name);
        let reply = if msg.entry.oid == self.oid {
            // A subject of this object (2.8.1 step 6): handled here, no message.
            match comm::entry_of(msg.entry.selector) {
                Entry::Control(s) if s < self.subjects.len() => self.subjects[s].control(&ctl),
                _ => return abi::O_NOT_FOUND,
            }
        } else {
            match ObserverState::call_control(&ctl, msg.entry) {
                Ok(r) => r,
                Err(status) => return status,
            }
        };
        let status = self.observers[k].connected(add, &reply);
        if status != abi::O_SUCCESS {
            osyslog(Priority::Warning, &format!("Observer `{}`: connection to {} refused", self.observers[k].name, abi::get_name(&msg.sub_name)));
        }
        status
    }
}

fn register(service: &str, selector: Selector) {
    match host::register_service(service, selector) {
        0 => {}
        1 => osyslog(Priority::Error, &format!("service `{service}` is already registered")),
        _ => osyslog(Priority::Error, &format!("cannot register service `{service}`")),
    }
}

thread_local! {
    /// The object and its context. Entries run on the object's thread only.
    static STATE: RefCell<Option<(Context, Box<dyn Any>)>> = const { RefCell::new(None) };
}

fn reply_status(status: u32) {
    host::reply(&OStatusMessage { msg_type: abi::OMSG_OSTATUS, status });
}

/// Runs `f` on the object, if it was initialised.
fn with_object<T: Object>(f: impl FnOnce(&mut T, &mut Context)) -> bool {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        match s.as_mut() {
            Some((ctx, obj)) => match obj.downcast_mut::<T>() {
                Some(obj) => {
                    f(obj, ctx);
                    true
                }
                None => false,
            },
            None => false,
        }
    })
}

fn with_context<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    STATE.with(|s| s.borrow_mut().as_mut().map(|(ctx, _)| f(ctx)))
}

/// The body of every entry function. `msg` is the runtime's copy of the message.
///
/// # Safety
/// `msg` points to the message for selector `sel`, as the runtime delivers it.
pub unsafe fn dispatch<T: Object>(sel: Selector, msg: *mut c_void) {
    // SAFETY: `msg` is the message for `sel` (this function's contract, passed on).
    let run = std::panic::AssertUnwindSafe(|| unsafe { dispatch_inner::<T>(sel, msg) });
    if std::panic::catch_unwind(run).is_err() {
        // A panic is the Rust object's crash: the runtime's crash report names the
        // object and the entry, and the run fails (as for a C++ exception).
        osyslog(Priority::Error, &format!("panic in the entry for selector {sel}"));
        std::process::abort();
    }
}

unsafe fn dispatch_inner<T: Object>(sel: Selector, msg: *mut c_void) {
    match comm::entry_of(sel) {
        Entry::Init => {
            let mut ctx = Context::new();
            let obj = T::init(&mut ctx);
            STATE.with(|s| *s.borrow_mut() = Some((ctx, Box::new(obj))));
            reply_status(abi::O_SUCCESS);
        }
        Entry::Start => {
            with_object::<T>(|o, ctx| o.start(ctx));
            reply_status(abi::O_SUCCESS);
        }
        Entry::Stop => {
            with_object::<T>(|o, ctx| o.stop(ctx));
            reply_status(abi::O_SUCCESS);
        }
        Entry::Destroy => {
            with_object::<T>(|o, ctx| o.destroy(ctx));
            host::unregister_services();
            let state = STATE.with(|s| s.borrow_mut().take());
            drop(state);
            reply_status(abi::O_SUCCESS);
        }
        Entry::Control(k) => {
            // SAFETY: the Control entry receives an OControlMessage.
            let m: OControlMessage = unsafe { abi::read(msg) };
            let reply = with_context(|ctx| ctx.subjects.get_mut(k).map(|s| s.control(&m))).flatten();
            match reply {
                Some(r) => host::reply(&r),
                None => host::reply(&abi::OControlReplyMessage {
                    msg_type: abi::OMSG_CONTROL_REPLY,
                    status: abi::O_NOT_FOUND,
                    subject_id: OServiceEntry::INVALID,
                    mem_id: abi::OBJCOMM_VERSION22,
                }),
            }
        }
        Entry::Ready(k) => {
            // SAFETY: the Ready entry receives an OReadyMessage.
            let m: OReadyMessage = unsafe { abi::read(msg) };
            with_object::<T>(|o, ctx| {
                let Some(s) = ctx.subjects.get_mut(k) else { return };
                if let Some((observer, assert)) = s.ready(&m) {
                    o.ready(ctx, ReadyEvent { subject: k, observer, assert });
                }
            });
        }
        Entry::Connect(k) => {
            // SAFETY: the Connect entry receives an OConnectMessage.
            let m: OConnectMessage = unsafe { abi::read(msg) };
            let status = with_context(|ctx| if k < ctx.observers.len() { ctx.connect(k, &m) } else { abi::O_NOT_FOUND });
            reply_status(status.unwrap_or(abi::O_FAIL));
        }
        Entry::Event => {
            // SAFETY: the event entry receives `u32 len` and len bytes (SEL_EVENT's layout).
            let data = unsafe {
                let len = std::ptr::read_unaligned(msg.cast::<u32>()) as usize;
                std::slice::from_raw_parts(msg.cast::<u8>().add(4), len)
            };
            with_object::<T>(|o, ctx| o.event(ctx, data));
        }
        Entry::Notify(k) => {
            // SAFETY: the Notify entry receives an ONotifyMessage.
            let m: ONotifyMessage = unsafe { abi::read(msg) };
            with_object::<T>(|o, ctx| {
                let Some(obs) = ctx.observers.get_mut(k) else { return };
                if let Some((subject, regions, units)) = obs.notify(&m) {
                    o.notify(ctx, NotifyEvent { observer: k, subject, regions, units });
                }
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// SetBufCtrlParam refuses what the robot refuses and then keeps the old values.
    #[test]
    fn set_buf_ctrl_param_refuses_dmax_below_dmin_and_dmin_zero() {
        let mut ctx = Context::new(); // no runtime: registering is a no-op
        let o = ctx.observer::<[u8]>("Test.Data.char.O");
        let default = ctx.observers[0].buf;
        assert_eq!(o.set_buf_ctrl_param(&mut ctx, 0, 4, 3), Status::Fail, "dmax < dmin");
        assert_eq!(o.set_buf_ctrl_param(&mut ctx, 0, 0, 3), Status::Fail, "dmin 0");
        assert_eq!(ctx.observers[0].buf, default, "a refusal changes nothing");
        assert_eq!(o.set_buf_ctrl_param(&mut ctx, 1, 2, 2), Status::Success);
        assert_eq!(ctx.observers[0].buf, (1, 2, 2));
    }
}
