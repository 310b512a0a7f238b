//! The runtime's side of the host table (`openr_runtime_api_v1`, declared once in the
//! `openr-sys` crate and checked there against `cxx/openr_host.h`): one plain function
//! per entry, which `openr_sys::host_table!` wraps in an `extern "C"` trampoline that
//! stops panics. Every function tolerates being called with no runtime installed or
//! from a thread that is not an object's.
#![deny(unsafe_op_in_unsafe_fn)]

use std::ffi::{c_char, c_void, CStr};
use std::ptr;
use std::sync::atomic::Ordering;
use std::time::Duration;

use openr_sys::{DesignDataId, MemId, Selector, TimerId};

use crate::object;
use crate::power::{Observer, PowerState, ORSB_MOTOR_POWER};
use crate::runtime::{CallError, Runtime};

pub const ABI_VERSION: u32 = openr_sys::HOST_ABI_VERSION;

/// The table objects find with `dlsym(RTLD_DEFAULT, "openr_runtime_api_v1")`; the
/// `cargo-openr` binary exports it (`--export-dynamic-symbol`, see its build.rs).
/// Declared once in `openr-sys`: each entry calls the function of the same name here
/// (or in `robot_api`) and stops a panic at the boundary ([`panicked`]).
#[no_mangle]
#[used]
pub static openr_runtime_api_v1: HostApi = openr_sys::host_table!(crate::host_api, crate::host_api::panicked);

pub(crate) use crate::robot_api::{
    close_primitive, control_primitive, delete_vector, joint_gain, joint_value, new_vector, open_primitive, sensor_value, set_cdt, sync_key, volume_switch,
    vr_attach, vr_submit,
};
pub use openr_sys::openr_host_api as HostApi;

/// A panic inside the runtime's side of an OPEN-R call: said on stderr with the call
/// and the object, and the run ends with a non-zero status (it is a bug of cargo-openr,
/// never of the program). The call returns its failure value.
pub fn panicked(function: &str, payload: Box<dyn std::any::Any + Send>) {
    let what = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".into());
    let who = object::current().map_or_else(|| "a thread that is not an object's".to_string(), |o| format!("object `{}`", o.name()));
    let msg = format!("internal error in cargo-openr: the runtime's `{function}` (called by {who}) panicked: {what}");
    match rt() {
        Some(rt) => {
            rt.diag.error(&msg);
            rt.internal_errors.fetch_add(1, Ordering::AcqRel);
        }
        None => crate::runtime::Report::error(&crate::runtime::PlainStderr, &msg),
    }
}

/// Test hook for the boundary: `OPENR_INJECT_PANIC=robot_design` makes that call
/// panic (only cold calls check it), so a test can see the report and the exit status.
fn inject_panic(function: &str) {
    static WHICH: std::sync::OnceLock<Option<String>> = std::sync::OnceLock::new();
    if WHICH.get_or_init(|| std::env::var("OPENR_INJECT_PANIC").ok()).as_deref() == Some(function) {
        panic!("injected by OPENR_INJECT_PANIC={function}");
    }
}

/// Keeps the table alive in the final link (referenced from the boot code).
pub fn api_table() -> *const HostApi {
    &openr_runtime_api_v1
}

fn rt() -> Option<&'static Runtime> {
    Runtime::get()
}

unsafe fn bytes<'a>(p: *const c_void, n: usize) -> &'a [u8] {
    if p.is_null() || n == 0 {
        &[]
    } else {
        // SAFETY: the caller (object code) passes a buffer of `n` readable bytes.
        unsafe { std::slice::from_raw_parts(p.cast(), n) }
    }
}

unsafe fn cstr<'a>(p: *const c_char) -> Option<&'a str> {
    if p.is_null() {
        return None;
    }
    // SAFETY: a NUL-terminated string from the object.
    unsafe { CStr::from_ptr(p) }.to_str().ok()
}

fn set_errno(e: i32) {
    // SAFETY: errno is thread-local.
    unsafe { *libc::__errno_location() = e };
}

pub(crate) unsafe fn map_path(path: *const c_char, create: i32, out: *mut c_char, len: usize) -> i32 {
    // SAFETY: `path` is the object's C string or null (the host API's contract).
    let (Some(rt), Some(path)) = (rt(), unsafe { cstr(path) }) else {
        set_errno(libc::ENOENT);
        return -1;
    };
    match rt.ms.resolve(path, if create != 0 { crate::ms::Access::Write } else { crate::ms::Access::Read }) {
        Ok(host) => {
            let b = host.as_os_str().as_encoded_bytes();
            if b.len() + 1 > len {
                set_errno(libc::ENAMETOOLONG);
                return -1;
            }
            // SAFETY: `out` has room for `len` bytes.
            unsafe {
                ptr::copy_nonoverlapping(b.as_ptr(), out.cast::<u8>(), b.len());
                *out.add(b.len()) = 0;
            }
            0
        }
        Err(refusal) => {
            set_errno(refusal.errno());
            -1
        }
    }
}

pub(crate) fn object_exit(status: i32) {
    if let (Some(rt), Some(me)) = (rt(), object::current()) {
        rt.diag.warn(&format!("object `{}` called exit({status}): it stops running, as on the robot", me.name()));
        me.stopped.store(true, Ordering::Release);
        rt.sched.retire(me.index);
        // Answer a pending call so the caller (e.g. the boot sequence) is not left waiting.
        object::reply_current(&[]);
        loop {
            std::thread::park();
        }
    }
    // Not an object thread: behave like exit().
    std::process::exit(status)
}

pub(crate) fn self_oid() -> *mut c_void {
    object::current_oid().unwrap_or(0xFFFF_FFFF) as *mut c_void
}

pub(crate) fn self_name() -> *const c_char {
    thread_local! {
        static NAME: std::cell::OnceCell<std::ffi::CString> = const { std::cell::OnceCell::new() };
    }
    let name = object::current().map(|s| s.name().to_string()).unwrap_or_else(|| "runtime".into());
    NAME.with(|n| n.get_or_init(|| std::ffi::CString::new(name).unwrap_or_default()).as_ptr())
}

pub(crate) unsafe fn send(dest: *mut c_void, selector: Selector, msg: *const c_void, size: usize) -> i32 {
    let Some(rt) = rt() else { return -1 };
    // SAFETY: `msg` holds `size` readable bytes or is null (the host API's contract); copied at once.
    let data = object::message(unsafe { bytes(msg, size) });
    match rt.send(dest as usize, selector, data) {
        Ok(()) => 0,
        Err(_) => -1,
    }
}

pub(crate) unsafe fn call(
    dest: *mut c_void,
    selector: Selector,
    msg: *const c_void,
    size: usize,
    reply: *mut c_void,
    cap: usize,
    got: *mut usize,
    timeout_ms: u32,
) -> i32 {
    let Some(rt) = rt() else { return -1 };
    // SAFETY: `msg` holds `size` readable bytes or is null (the host API's contract); copied at once.
    let data = object::message(unsafe { bytes(msg, size) });
    let timeout = (timeout_ms > 0).then(|| Duration::from_millis(timeout_ms.into()));
    match rt.call(dest as usize, selector, data, timeout) {
        Ok(answer) => {
            let n = answer.len().min(cap);
            if !reply.is_null() {
                // SAFETY: `reply` has room for `cap` bytes.
                unsafe { ptr::copy_nonoverlapping(answer.as_ptr(), reply.cast::<u8>(), n) };
            }
            if !got.is_null() {
                // SAFETY: out-param from the caller.
                unsafe { *got = answer.len() };
            }
            0
        }
        Err(CallError::UnknownDestination) => -1,
        Err(CallError::SelfCall) => -2,
        Err(CallError::Timeout) => -3,
    }
}

pub(crate) unsafe fn reply(msg: *const c_void, size: usize) -> i32 {
    // SAFETY: `msg` holds `size` readable bytes or is null (the host API's contract), read before return.
    if object::reply_current(unsafe { bytes(msg, size) }) {
        0
    } else {
        1
    }
}

pub(crate) unsafe fn register_service(name: *const c_char, oid: *mut c_void, selector: Selector) -> i32 {
    // SAFETY: `name` is the object's C string or null (the host API's contract).
    let (Some(rt), Some(name)) = (rt(), unsafe { cstr(name) }) else { return 1 };
    if rt.register(name, oid as usize, selector) {
        0
    } else {
        1
    }
}

pub(crate) fn unregister_services() {
    if let (Some(rt), Some(me)) = (rt(), object::current()) {
        rt.unregister_all_of(me.oid);
    }
}

pub(crate) unsafe fn console_write(text: *const c_char, len: usize) {
    // SAFETY: `text` holds `len` readable bytes or is null (the host API's contract), read before return.
    crate::console::write(unsafe { bytes(text.cast(), len) });
}

pub(crate) unsafe fn shm_alloc(size: usize, mem_id: *mut MemId) -> *mut c_void {
    let Some((id, base)) = rt().and_then(|rt| rt.shm.alloc(size)) else { return ptr::null_mut() };
    if !mem_id.is_null() {
        // SAFETY: out-param.
        unsafe { *mem_id = id };
    }
    base.cast()
}

pub(crate) unsafe fn shm_base(mem_id: MemId, size: *mut usize) -> *mut c_void {
    let Some((base, n)) = rt().and_then(|rt| rt.shm.base(mem_id)) else { return ptr::null_mut() };
    if !size.is_null() {
        // SAFETY: out-param.
        unsafe { *size = n };
    }
    base.cast()
}

pub(crate) fn shm_ref(mem_id: MemId) {
    if let Some(rt) = rt() {
        rt.shm.add_ref(mem_id);
    }
}

pub(crate) fn shm_unref(mem_id: MemId) {
    if let Some(rt) = rt() {
        rt.shm.unref(mem_id);
    }
}

pub(crate) unsafe fn system_time(sec: *mut u32, usec: *mut u32) {
    let t = rt().map(|rt| rt.clock.since_boot()).unwrap_or_default();
    // SAFETY: out-params.
    unsafe {
        if !sec.is_null() {
            *sec = t.as_secs() as u32;
        }
        if !usec.is_null() {
            *usec = t.subsec_micros();
        }
    }
}

pub(crate) unsafe fn get_clock(sec: *mut i64, dif: *mut i32) {
    let (s, d) = rt().map(|rt| rt.clock.calendar()).unwrap_or((0, 0));
    // SAFETY: out-params.
    unsafe {
        if !sec.is_null() {
            *sec = s;
        }
        if !dif.is_null() {
            *dif = d;
        }
    }
}

pub(crate) fn set_clock(sec: i64, dif: i32) {
    if let Some(rt) = rt() {
        let old = rt.clock.calendar().1;
        rt.clock.set_calendar(sec, dif);
        if old != dif {
            // OPowerStatus.timeDif is the same setting: GetPowerStatus and observers see it.
            crate::boot::update_power(rt, |s| s.time_dif = dif);
        }
    }
}

/// Sleeps on virtual time; the object counts as idle meanwhile (so `--speed max`
/// advances the clock it waits for).
pub(crate) fn sleep_ns(ns: u64) {
    let Some(rt) = rt() else {
        std::thread::sleep(Duration::from_nanos(ns));
        return;
    };
    let me = object::current();
    let until = rt.clock.since_boot() + Duration::from_nanos(ns);
    let mut turn = false;
    if let Some(s) = &me {
        s.sleeping.store(true, Ordering::Release);
        turn = rt.sched.sleeping(s.index, until);
    }
    rt.clock.wait_until(until);
    if let Some(s) = &me {
        if turn {
            rt.sched.woke(s.index);
        }
        s.sleeping.store(false, Ordering::Release);
    }
}

/// OPENR::Fatal (robot-api 4.4): the battery micro plays the warning and powers the
/// robot off, so no object gets Stop or Destroy; the caller never returns.
pub(crate) fn fatal(kind: u32) {
    let Some(rt) = rt() else { return };
    let warning = match kind {
        0 => "ofatalMEMORY_STICK: the memory-stick error sound",
        1 => "ofatalPAUSE_SW: no sound",
        2 => "ofatalORB",
        u32::MAX => "ofatalUNDEF: \"Toccata and Fugue\"",
        _ => "an undefined OFatal value",
    };
    let who = object::current().map_or_else(|| "?".to_string(), |o| o.name().to_string());
    rt.diag.error(&format!("object `{who}` called OPENR::Fatal({warning}); the robot powers off (no DoStop, no DoDestroy)"));
    rt.fatal.store(kind, Ordering::Release);
    rt.request_shutdown();
    loop {
        std::thread::park();
    }
}

pub(crate) fn robot_design() -> *const c_char {
    inject_panic("robot_design");
    // A Remote Processing host object asks the robot (through the API proxy).
    if let Some(robot) = crate::gateway::proxy::robot_design() {
        return robot.map_or(std::ptr::null(), |d| d.as_ptr());
    }
    rt().map_or(c"ERS-7".as_ptr(), |rt| rt.design.as_ptr())
}

pub(crate) unsafe fn find_design_data(keyword: *const c_char, id: *mut DesignDataId, data: *mut *mut c_void, size: *mut usize) -> u32 {
    // SAFETY: `keyword` is the object's C string or null (the host API's contract).
    let (Some(rt), Some(key)) = (rt(), unsafe { cstr(keyword) }) else { return crate::design::O_FAIL };
    match crate::design::find(rt, key) {
        Ok((data_id, base, n)) => {
            // SAFETY: out-params.
            unsafe {
                if !id.is_null() {
                    *id = data_id;
                }
                if !data.is_null() {
                    *data = base.cast();
                }
                if !size.is_null() {
                    *size = n;
                }
            }
            0
        }
        Err(status) => status,
    }
}

pub(crate) fn delete_design_data(id: DesignDataId) -> u32 {
    rt().map_or(crate::design::O_INVALID_ARG, |rt| crate::design::delete(rt, id))
}

pub(crate) unsafe fn set_timer(dest: *mut c_void, selector: Selector, msg: *const c_void, size: usize, after_ms: u32, period_ms: u32) -> TimerId {
    let Some(rt) = rt() else { return TimerId::NONE };
    // SAFETY: `msg` holds `size` readable bytes or is null (the host API's contract); copied at once.
    let data = object::message(unsafe { bytes(msg, size) });
    let period = (period_ms > 0).then(|| Duration::from_millis(period_ms.into()));
    rt.timers.add(rt.clock.since_boot(), dest as usize, selector, data, Duration::from_millis(after_ms.into()), period)
}

pub(crate) fn cancel_timer(id: TimerId) -> i32 {
    match rt() {
        Some(rt) if rt.timers.cancel(id) => 0,
        _ => -1,
    }
}

pub(crate) unsafe fn power_status(out: *mut PowerState) {
    if out.is_null() {
        return;
    }
    if let Some(reply) = crate::gateway::proxy::call(crate::gateway::proxy::POWER_STATUS, &[]) {
        let (_, b) = crate::gateway::proxy::split(&reply);
        if b.len() >= std::mem::size_of::<PowerState>() {
            // SAFETY: out-param; `b` holds a whole PowerState of 32-bit integers.
            unsafe { *out = std::ptr::read_unaligned(b.as_ptr().cast::<PowerState>()) };
        }
        return;
    }
    if let Some(rt) = rt() {
        // SAFETY: out-param.
        unsafe { *out = rt.power.state() };
    }
}

pub(crate) unsafe fn observe_power(oid: *mut c_void, selector: Selector, filter: *const PowerState) -> u32 {
    let Some(rt) = rt() else { return crate::design::O_FAIL };
    if filter.is_null() {
        return if rt.power.unobserve(oid as usize, selector) { 0 } else { 6 };
    }
    // SAFETY: a valid openr_power_state from the object.
    let filter = unsafe { *filter };
    rt.power.observe(Observer { oid: oid as usize, selector, filter });
    0
}

pub(crate) fn set_motor_power(on: i32) {
    if crate::gateway::proxy::call(crate::gateway::proxy::SET_MOTOR_POWER, &on.to_le_bytes()).is_some() {
        return;
    }
    if let Some(rt) = rt() {
        rt.vr.robot().set_motor_power(on != 0);
        crate::boot::update_power(rt, |s| {
            if on != 0 {
                s.robot_status |= ORSB_MOTOR_POWER;
            } else {
                s.robot_status &= !ORSB_MOTOR_POWER;
            }
        });
    }
}

pub(crate) fn shutdown() {
    if let Some(rt) = rt() {
        rt.request_shutdown();
    }
}
