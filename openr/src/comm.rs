//! The subject/observer protocol of object-model 2.8, message for message as the C++
//! `OSubject`/`OObserver` of `sdk-payload/cxx/ObjectComm` speak it, so either side may
//! be C++:
//!
//! * connection (2.8.1): the runtime sends `OConnectMessage` to the observer's Connect
//!   entry; the observer calls the subject's Control entry with `OControlMessage`
//!   (`ADDOBSERVER_V22`) and gets `OControlReplyMessage` naming the subject's Ready
//!   entry; the observer answers the runtime with `OStatusMessage`. A subject of the same
//!   object is handled in-object (the host refuses calls to self).
//! * data (2.8.2, 2.8.3): `SetData` queues a region per observer, `NotifyObservers` ends
//!   a unit and sends `ONotifyMessage` (whole units, at most 13 regions) to an observer
//!   that asserted ready; the observer's `OReadyMessage` (ASSERT/DEASSERT) returns the
//!   subject's region handles, whose references the subject then drops.
//!
//! A Rust subject's "region handle" in `TransferedData::srcRCR` is an opaque token (the
//! block's `MemoryRegionID`, never 0) standing for one host reference: C++ observers only
//! store and return it, exactly as they do a C++ subject's `RCRegion*`.
use std::ffi::c_void;

use crate::abi::{self, MemId, OControlMessage, OControlReplyMessage, ONotifyMessage, OReadyMessage, OServiceEntry, Selector, TransferedData};
use crate::console::{osyslog, Priority};
use crate::host;
use crate::shm::Region;
use crate::Status;

/// Subjects and observers an object may declare (selectors are fixed per slot).
pub const MAX_SUBJECTS: usize = 16;
pub const MAX_OBSERVERS: usize = 16;
/// Life-cycle selectors (Init, Start, Stop, Destroy).
pub const SEL_INIT: Selector = Selector(0);
pub const SEL_START: Selector = Selector(1);
pub const SEL_STOP: Selector = Selector(2);
pub const SEL_DESTROY: Selector = Selector(3);
/// The event entry after the observer slots: messages an object's own helper threads
/// (or the runtime) post to it, `u32` length then the bytes (`Object::event`).
pub const SEL_EVENT: Selector = Selector(4 + 2 * MAX_SUBJECTS as u32 + 2 * MAX_OBSERVERS as u32);

/// Entry selectors of subject slot `k`: (Control, Ready).
pub const fn subject_selectors(k: usize) -> (Selector, Selector) {
    (Selector(4 + 2 * k as u32), Selector(5 + 2 * k as u32))
}

/// Entry selectors of observer slot `k`: (Connect, Notify).
pub const fn observer_selectors(k: usize) -> (Selector, Selector) {
    let base = 4 + 2 * MAX_SUBJECTS as u32;
    (Selector(base + 2 * k as u32), Selector(base + 1 + 2 * k as u32))
}

/// What an entry selector means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Entry {
    Init,
    Start,
    Stop,
    Destroy,
    Control(usize),
    Ready(usize),
    Connect(usize),
    Notify(usize),
    Event,
}

pub(crate) const fn entry_of(sel: Selector) -> Entry {
    let s = sel.0 as usize;
    match sel {
        SEL_INIT => Entry::Init,
        SEL_START => Entry::Start,
        SEL_STOP => Entry::Stop,
        SEL_DESTROY => Entry::Destroy,
        SEL_EVENT => Entry::Event,
        _ if s < 4 + 2 * MAX_SUBJECTS => {
            if (s - 4) % 2 == 0 {
                Entry::Control((s - 4) / 2)
            } else {
                Entry::Ready((s - 4) / 2)
            }
        }
        _ => {
            let o = s - 4 - 2 * MAX_SUBJECTS;
            if o % 2 == 0 {
                Entry::Connect(o / 2)
            } else {
                Entry::Notify(o / 2)
            }
        }
    }
}

const MIN_QUEUE: usize = 14;
const CONTROL_TIMEOUT_MS: u32 = 15_000;
const CMD_ADDOBSERVER_SELF: u32 = 5;
const CMD_REMOVEOBSERVER_SELF: u32 = 6;

/// A subject's record of one observer (`_OObserverInfo`). Queue entries: `Some(region)`
/// holding one host reference, `None` the end of a unit.
struct ObserverRec {
    id: OServiceEntry,
    d_skip: usize,
    d_min: usize,
    d_max: usize,
    ready: i32,
    n_notify: usize,
    skip_counter: usize,
    q_size: usize,
    queue: Vec<Option<Region>>,
}

impl ObserverRec {
    fn drop_oldest(&mut self) {
        if let Some(k) = self.queue.iter().position(|e| e.is_none()) {
            self.queue.drain(..=k);
            self.n_notify -= 1;
        } else if !self.queue.is_empty() {
            self.queue.remove(0);
        }
    }

    fn clear(&mut self) {
        self.queue.clear();
        self.n_notify = 0;
        self.skip_counter = 0;
    }
}

pub(crate) struct SubjectState {
    pub(crate) name: String,
    id: OServiceEntry,
    observers: Vec<ObserverRec>,
}

pub(crate) struct ObserverState {
    pub(crate) name: String,
    id: OServiceEntry,
    subjects: Vec<OServiceEntry>,
    /// Received regions not yet given back: (subject, its handle).
    held: Vec<(OServiceEntry, *mut c_void)>,
    /// `SetBufCtrlParam`: (d_skip, d_min, d_max), sent to each subject as it connects.
    pub(crate) buf: (usize, usize, usize),
}

impl SubjectState {
    pub(crate) fn new(name: &str, oid: *mut c_void, k: usize) -> SubjectState {
        SubjectState { name: name.into(), id: OServiceEntry { oid, selector: subject_selectors(k).1 }, observers: Vec::new() }
    }

    pub(crate) fn num_observers(&self) -> usize {
        self.observers.len()
    }

    /// `OSubject::ControlHandler`: returns the reply (sent by the caller, or kept
    /// in-object for a self connection).
    pub(crate) fn control(&mut self, msg: &OControlMessage) -> OControlReplyMessage {
        let status = self.control_status(msg);
        OControlReplyMessage { msg_type: abi::OMSG_CONTROL_REPLY, status, subject_id: self.id, mem_id: abi::OBJCOMM_VERSION22 }
    }

    fn control_status(&mut self, msg: &OControlMessage) -> u32 {
        if msg.msg_type != abi::OMSG_CONTROL {
            return abi::O_WRONG_MESSAGE;
        }
        let add = match msg.command {
            abi::CMD_ADDOBSERVER | abi::CMD_ADDOBSERVER_V22 | CMD_ADDOBSERVER_SELF => true,
            abi::CMD_REMOVEOBSERVER | abi::CMD_REMOVEOBSERVER_V22 | CMD_REMOVEOBSERVER_SELF => false,
            _ => return abi::O_UNKNOWN_COMMAND,
        };
        let found = self.observers.iter().position(|o| o.id == msg.observer_id);
        if add {
            let q_size = (msg.d_max * 2).max(MIN_QUEUE);
            let rec = ObserverRec {
                id: msg.observer_id,
                d_skip: msg.d_skip,
                d_min: msg.d_min,
                d_max: msg.d_max,
                ready: 0,
                n_notify: 0,
                skip_counter: 0,
                q_size,
                queue: Vec::with_capacity(q_size),
            };
            match found {
                Some(i) => self.observers[i] = rec,
                None => self.observers.push(rec),
            }
            abi::O_SUCCESS
        } else if let Some(i) = found {
            self.observers.remove(i);
            abi::O_SUCCESS
        } else {
            abi::O_NOT_FOUND
        }
    }

    /// `OSubject::ReadyHandler`: `Some(assert?)` for an ASSERT/DEASSERT from a known
    /// observer. Returned handles are released in every case.
    pub(crate) fn ready(&mut self, msg: &OReadyMessage) -> Option<(OServiceEntry, bool)> {
        if msg.msg_type != abi::OMSG_READY_V22 {
            return None;
        }
        let n = (msg.num_of_data.max(0) as usize).min(abi::MAX_NUM_DATA);
        for &token in &msg.rc_region[..n] {
            if !token.is_null() {
                // A Rust subject's handle is its region's MemId, carried as a pointer.
                let mem_id = MemId(token as usize as u32);
                crate::shm::token_returned(mem_id);
                host::shm_unref(mem_id);
            }
        }
        let self_id = self.id;
        let o = self.observers.iter_mut().find(|o| o.id == msg.observer_id)?;
        match msg.command {
            abi::CMD_ASSERT_READY => {
                o.ready = 1;
                send_notify(self_id, o);
                Some((msg.observer_id, true))
            }
            abi::CMD_DEASSERT_READY => {
                o.ready = -1;
                o.clear();
                Some((msg.observer_id, false))
            }
            _ => None,
        }
    }

    /// `OSubject::SetData(RCRegion*)` for every observer.
    pub(crate) fn set_data(&mut self, region: &Region) -> Status {
        let mut result = Status::Success;
        for o in &mut self.observers {
            if o.ready < 0 || o.skip_counter != o.d_skip {
                continue;
            }
            let n_data = o.queue.len();
            let full = n_data + 1 >= o.q_size;
            if o.n_notify >= o.d_max || full {
                if full && o.n_notify < o.d_max {
                    result = if o.n_notify < o.d_min { Status::Fatal } else { Status::Overflow };
                    osyslog(Priority::Error, &format!("Subject `{}`: buffer of an observer is full, oldest data dropped", self.name));
                }
                o.drop_oldest();
            }
            o.queue.push(Some(region.clone()));
        }
        result
    }

    /// `OSubject::NotifyObservers`.
    pub(crate) fn notify_observers(&mut self) -> Status {
        let mut result = Status::Success;
        let self_id = self.id;
        for o in &mut self.observers {
            if o.skip_counter < o.d_skip {
                o.skip_counter += 1;
            } else {
                o.skip_counter = 0;
            }
            if matches!(o.queue.last(), None | Some(None)) {
                continue;
            }
            o.queue.push(None);
            o.n_notify += 1;
            if !send_notify(self_id, o) {
                result = Status::Fail;
            }
        }
        result
    }

    /// Number of observers that asserted ready and wait for data (`IsReady`).
    pub(crate) fn ready_count(&self) -> usize {
        self.observers.iter().filter(|o| o.ready > 0).count()
    }
}

/// Sends the whole pending units to `o` if it asserted ready (C++ `sendNotify`).
fn send_notify(self_id: OServiceEntry, o: &mut ObserverRec) -> bool {
    if o.ready <= 0 || o.n_notify < o.d_min || o.queue.is_empty() {
        return true;
    }
    let empty = TransferedData { src_rcr: std::ptr::null_mut(), mem_id: MemId(0), offset: 0, size: 0 };
    let mut m = ONotifyMessage { msg_type: abi::OMSG_NOTIFY_V22, subject_id: self_id, num_of_data: 0, num_of_notify: 0, data: [empty; abi::MAX_NUM_DATA] };
    let (mut pos, mut units, mut regions) = (0, 0, 0);
    while pos < o.queue.len() {
        let Some(end) = o.queue[pos..].iter().position(|e| e.is_none()).map(|e| pos + e) else { break };
        let count = end - pos;
        if regions + count > abi::MAX_NUM_DATA {
            break;
        }
        for r in o.queue[pos..end].iter().flatten() {
            m.data[regions] = TransferedData { src_rcr: r.mem_id().0 as usize as *mut c_void, mem_id: r.mem_id(), offset: r.offset() as u32, size: r.len() };
            regions += 1;
        }
        units += 1;
        pos = end + 1;
    }
    if units == 0 {
        return true;
    }
    m.num_of_data = regions as i16;
    m.num_of_notify = units as i16;
    if !host::send(o.id, &m) {
        osyslog(Priority::Error, "Subject: cannot send a notification to an observer");
        return false;
    }
    // The queued references now travel with the message; the observer's next READY
    // message returns them (see `ready`).
    for e in o.queue.drain(..pos) {
        std::mem::forget(e);
    }
    o.n_notify -= units;
    o.ready = 0;
    true
}

impl ObserverState {
    pub(crate) fn new(name: &str, oid: *mut c_void, k: usize) -> ObserverState {
        ObserverState {
            name: name.into(),
            id: OServiceEntry { oid, selector: observer_selectors(k).1 },
            subjects: Vec::new(),
            held: Vec::new(),
            buf: (0, 1, 1),
        }
    }

    pub(crate) fn num_subjects(&self) -> usize {
        self.subjects.len()
    }

    pub(crate) fn control_message(&self, command: u32, sub_name: &[u8; 128]) -> OControlMessage {
        let (d_skip, d_min, d_max) = self.buf;
        OControlMessage { msg_type: abi::OMSG_CONTROL, command, observer_id: self.id, d_skip, d_min, d_max, sub_name: *sub_name }
    }

    /// Calls a subject of another object.
    pub(crate) fn call_control(ctl: &OControlMessage, subject: OServiceEntry) -> Result<OControlReplyMessage, u32> {
        match host::call::<_, OControlReplyMessage>(subject, ctl, CONTROL_TIMEOUT_MS) {
            Ok(r) => Ok(r),
            Err(rc) => {
                let why = match rc {
                    -3 => "timeout",
                    -4 => "short reply",
                    _ => "unknown object",
                };
                osyslog(Priority::Error, &format!("Observer: no answer from subject {} ({why})", abi::get_name(&ctl.sub_name)));
                Err(if rc == -4 { abi::O_REFUSED } else { abi::O_FAIL })
            }
        }
    }

    /// Records the outcome of an ADD/REMOVE control exchange.
    pub(crate) fn connected(&mut self, add: bool, reply: &OControlReplyMessage) -> u32 {
        if reply.msg_type != abi::OMSG_CONTROL_REPLY || reply.status != abi::O_SUCCESS {
            return abi::O_REFUSED;
        }
        if add {
            if !self.subjects.contains(&reply.subject_id) {
                self.subjects.push(reply.subject_id);
            }
        } else {
            self.send_ready(reply.subject_id, abi::CMD_DEASSERT_READY);
            self.subjects.retain(|s| *s != reply.subject_id);
        }
        abi::O_SUCCESS
    }

    /// `OObserver::NotifyHandler`: the regions of the message, each with its own host
    /// reference; the subject's handles are kept for the next READY.
    pub(crate) fn notify(&mut self, msg: &ONotifyMessage) -> Option<(OServiceEntry, Vec<Region>, usize)> {
        if msg.msg_type != abi::OMSG_NOTIFY_V22 {
            return None;
        }
        let n = (msg.num_of_data.max(0) as usize).min(abi::MAX_NUM_DATA);
        let mut regions = Vec::with_capacity(n);
        for d in &msg.data[..n] {
            self.held.push((msg.subject_id, d.src_rcr));
            match Region::attach(d.mem_id, d.offset as usize, d.size) {
                Some(r) => regions.push(r),
                None => osyslog(Priority::Warning, &format!("Observer `{}`: region {} is not shared memory", self.name, d.mem_id)),
            }
        }
        Some((msg.subject_id, regions, msg.num_of_notify.max(0) as usize))
    }

    /// Sends ASSERT/DEASSERT-READY to one subject, returning what came from it.
    pub(crate) fn send_ready(&mut self, subject: OServiceEntry, command: u32) -> bool {
        let mut m = OReadyMessage {
            msg_type: abi::OMSG_READY_V22,
            command,
            observer_id: self.id,
            num_of_data: 0,
            rc_region: [std::ptr::null_mut(); abi::MAX_NUM_DATA],
        };
        let mut kept = Vec::new();
        for (s, token) in self.held.drain(..) {
            if s == subject && (m.num_of_data as usize) < abi::MAX_NUM_DATA {
                m.rc_region[m.num_of_data as usize] = token;
                m.num_of_data += 1;
            } else {
                kept.push((s, token));
            }
        }
        self.held = kept;
        let ok = host::send(subject, &m);
        if !ok {
            osyslog(Priority::Error, &format!("Observer `{}`: cannot send READY to a subject", self.name));
        }
        ok
    }

    /// ASSERT/DEASSERT-READY to every connected subject.
    pub(crate) fn ready_all(&mut self, command: u32) -> Status {
        if self.subjects.is_empty() {
            return Status::Fail;
        }
        for s in self.subjects.clone() {
            self.send_ready(s, command);
        }
        Status::Success
    }
}
