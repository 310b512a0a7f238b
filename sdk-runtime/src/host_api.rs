//! The `extern "C"` layer: `openr_runtime_api_v1`, the table declared in
//! `cxx/openr_host.h`, through which each object's OPEN-R library reaches the runtime.
//! Field order must match the header; every function tolerates being called with no
//! runtime installed or from a thread that is not an object's.
#![deny(unsafe_op_in_unsafe_fn)]

use std::ffi::{c_char, c_void, CStr};
use std::ptr;
use std::sync::atomic::Ordering;
use std::time::Duration;

use crate::object;
use crate::power::{Observer, PowerState, ORSB_MOTOR_POWER};
use crate::runtime::{CallError, Runtime};

pub const ABI_VERSION: u32 = 1;

#[repr(C)]
pub struct HostApi {
    pub abi_version: u32,
    pub size: u32,
    map_path: unsafe extern "C" fn(*const c_char, i32, *mut c_char, usize) -> i32,
    object_exit: extern "C" fn(i32),
    self_oid: extern "C" fn() -> *mut c_void,
    self_name: extern "C" fn() -> *const c_char,
    send: unsafe extern "C" fn(*mut c_void, u32, *const c_void, usize) -> i32,
    call: unsafe extern "C" fn(*mut c_void, u32, *const c_void, usize, *mut c_void, usize, *mut usize, u32) -> i32,
    reply: unsafe extern "C" fn(*const c_void, usize) -> i32,
    register_service: unsafe extern "C" fn(*const c_char, *mut c_void, u32) -> i32,
    unregister_services: extern "C" fn(),
    console_write: unsafe extern "C" fn(*const c_char, usize),
    shm_alloc: unsafe extern "C" fn(usize, *mut u32) -> *mut c_void,
    shm_base: unsafe extern "C" fn(u32, *mut usize) -> *mut c_void,
    shm_ref: extern "C" fn(u32),
    shm_unref: extern "C" fn(u32),
    system_time: unsafe extern "C" fn(*mut u32, *mut u32),
    get_clock: unsafe extern "C" fn(*mut i64, *mut i32),
    set_clock: extern "C" fn(i64, i32),
    sleep_ns: extern "C" fn(u64),
    robot_design: extern "C" fn() -> *const c_char,
    find_design_data: unsafe extern "C" fn(*const c_char, *mut u32, *mut *mut c_void, *mut usize) -> u32,
    delete_design_data: extern "C" fn(u32) -> u32,
    set_timer: unsafe extern "C" fn(*mut c_void, u32, *const c_void, usize, u32, u32) -> u32,
    cancel_timer: extern "C" fn(u32) -> i32,
    power_status: unsafe extern "C" fn(*mut PowerState),
    observe_power: unsafe extern "C" fn(*mut c_void, u32, *const PowerState) -> u32,
    set_motor_power: extern "C" fn(i32),
    shutdown: extern "C" fn(),
    open_primitive: unsafe extern "C" fn(*const c_char, *mut u32) -> u32,
    close_primitive: extern "C" fn(u32) -> u32,
    control_primitive: unsafe extern "C" fn(u32, u32, *const c_void, usize, *mut c_void, usize) -> u32,
    joint_gain: unsafe extern "C" fn(i32, u32, *mut u16) -> u32,
    joint_value: unsafe extern "C" fn(u32, *mut c_void) -> u32,
    sensor_value: unsafe extern "C" fn(u32, *mut c_void) -> u32,
    sync_key: unsafe extern "C" fn(i32, u32, *mut u32, *mut u32) -> u32,
    new_vector: unsafe extern "C" fn(i32, usize, usize, *mut u32, *mut *mut c_void) -> u32,
    delete_vector: extern "C" fn(u32) -> u32,
    set_cdt: extern "C" fn(u32) -> u32,
    volume_switch: unsafe extern "C" fn(i32, *mut u8) -> u32,
    vr_attach: extern "C" fn(i32, u32) -> u32,
    vr_submit: unsafe extern "C" fn(i32, *mut c_void, u32, *mut c_void, usize, *mut u64) -> u32,
}

/// The table objects find with `dlsym(RTLD_DEFAULT, "openr_runtime_api_v1")`; the
/// `cargo-openr` binary exports it (`--export-dynamic-symbol`, see its build.rs).
#[no_mangle]
#[used]
pub static openr_runtime_api_v1: HostApi = HostApi {
    abi_version: ABI_VERSION,
    size: std::mem::size_of::<HostApi>() as u32,
    map_path,
    object_exit,
    self_oid,
    self_name,
    send,
    call,
    reply,
    register_service,
    unregister_services,
    console_write,
    shm_alloc,
    shm_base,
    shm_ref,
    shm_unref,
    system_time,
    get_clock,
    set_clock,
    sleep_ns,
    robot_design,
    find_design_data,
    delete_design_data,
    set_timer,
    cancel_timer,
    power_status,
    observe_power,
    set_motor_power,
    shutdown,
    open_primitive: crate::robot_api::open_primitive,
    close_primitive: crate::robot_api::close_primitive,
    control_primitive: crate::robot_api::control_primitive,
    joint_gain: crate::robot_api::joint_gain,
    joint_value: crate::robot_api::joint_value,
    sensor_value: crate::robot_api::sensor_value,
    sync_key: crate::robot_api::sync_key,
    new_vector: crate::robot_api::new_vector,
    delete_vector: crate::robot_api::delete_vector,
    set_cdt: crate::robot_api::set_cdt,
    volume_switch: crate::robot_api::volume_switch,
    vr_attach: crate::robot_api::vr_attach,
    vr_submit: crate::robot_api::vr_submit,
};

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

unsafe extern "C" fn map_path(path: *const c_char, create: i32, out: *mut c_char, len: usize) -> i32 {
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

extern "C" fn object_exit(status: i32) {
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

extern "C" fn self_oid() -> *mut c_void {
    object::current().map_or(0xFFFF_FFFF, |s| s.oid) as *mut c_void
}

extern "C" fn self_name() -> *const c_char {
    thread_local! {
        static NAME: std::cell::OnceCell<std::ffi::CString> = const { std::cell::OnceCell::new() };
    }
    let name = object::current().map(|s| s.name().to_string()).unwrap_or_else(|| "runtime".into());
    NAME.with(|n| n.get_or_init(|| std::ffi::CString::new(name).unwrap_or_default()).as_ptr())
}

unsafe extern "C" fn send(dest: *mut c_void, selector: u32, msg: *const c_void, size: usize) -> i32 {
    let Some(rt) = rt() else { return -1 };
    let data = unsafe { bytes(msg, size) }.to_vec();
    match rt.send(dest as usize, selector, data) {
        Ok(()) => 0,
        Err(_) => -1,
    }
}

unsafe extern "C" fn call(dest: *mut c_void, selector: u32, msg: *const c_void, size: usize, reply: *mut c_void, cap: usize, got: *mut usize, timeout_ms: u32) -> i32 {
    let Some(rt) = rt() else { return -1 };
    let data = unsafe { bytes(msg, size) }.to_vec();
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

unsafe extern "C" fn reply(msg: *const c_void, size: usize) -> i32 {
    if object::reply_current(unsafe { bytes(msg, size) }) {
        0
    } else {
        1
    }
}

unsafe extern "C" fn register_service(name: *const c_char, oid: *mut c_void, selector: u32) -> i32 {
    let (Some(rt), Some(name)) = (rt(), unsafe { cstr(name) }) else { return 1 };
    if rt.register(name, oid as usize, selector) {
        0
    } else {
        1
    }
}

extern "C" fn unregister_services() {
    if let (Some(rt), Some(me)) = (rt(), object::current()) {
        rt.unregister_all_of(me.oid);
    }
}

unsafe extern "C" fn console_write(text: *const c_char, len: usize) {
    crate::console::write(unsafe { bytes(text.cast(), len) });
}

unsafe extern "C" fn shm_alloc(size: usize, mem_id: *mut u32) -> *mut c_void {
    let Some((id, base)) = rt().and_then(|rt| rt.shm.alloc(size)) else { return ptr::null_mut() };
    if !mem_id.is_null() {
        // SAFETY: out-param.
        unsafe { *mem_id = id };
    }
    base.cast()
}

unsafe extern "C" fn shm_base(mem_id: u32, size: *mut usize) -> *mut c_void {
    let Some((base, n)) = rt().and_then(|rt| rt.shm.base(mem_id)) else { return ptr::null_mut() };
    if !size.is_null() {
        // SAFETY: out-param.
        unsafe { *size = n };
    }
    base.cast()
}

extern "C" fn shm_ref(mem_id: u32) {
    if let Some(rt) = rt() {
        rt.shm.add_ref(mem_id);
    }
}

extern "C" fn shm_unref(mem_id: u32) {
    if let Some(rt) = rt() {
        rt.shm.unref(mem_id);
    }
}

unsafe extern "C" fn system_time(sec: *mut u32, usec: *mut u32) {
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

unsafe extern "C" fn get_clock(sec: *mut i64, dif: *mut i32) {
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

extern "C" fn set_clock(sec: i64, dif: i32) {
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
extern "C" fn sleep_ns(ns: u64) {
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

extern "C" fn robot_design() -> *const c_char {
    rt().map_or(c"ERS-7".as_ptr(), |rt| rt.design.as_ptr())
}

unsafe extern "C" fn find_design_data(keyword: *const c_char, id: *mut u32, data: *mut *mut c_void, size: *mut usize) -> u32 {
    let (Some(rt), Some(key)) = (rt(), unsafe { cstr(keyword) }) else { return crate::design::O_FAIL };
    match crate::design::find(rt, key) {
        Ok((mem_id, base, n)) => {
            // SAFETY: out-params.
            unsafe {
                if !id.is_null() {
                    *id = mem_id;
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

extern "C" fn delete_design_data(id: u32) -> u32 {
    rt().map_or(crate::design::O_INVALID_ARG, |rt| crate::design::delete(rt, id))
}

unsafe extern "C" fn set_timer(dest: *mut c_void, selector: u32, msg: *const c_void, size: usize, after_ms: u32, period_ms: u32) -> u32 {
    let Some(rt) = rt() else { return 0 };
    let data = unsafe { bytes(msg, size) }.to_vec();
    let period = (period_ms > 0).then(|| Duration::from_millis(period_ms.into()));
    rt.timers.add(rt.clock.since_boot(), dest as usize, selector, data, Duration::from_millis(after_ms.into()), period)
}

extern "C" fn cancel_timer(id: u32) -> i32 {
    match rt() {
        Some(rt) if rt.timers.cancel(id) => 0,
        _ => -1,
    }
}

unsafe extern "C" fn power_status(out: *mut PowerState) {
    if let (Some(rt), false) = (rt(), out.is_null()) {
        // SAFETY: out-param.
        unsafe { *out = rt.power.state() };
    }
}

unsafe extern "C" fn observe_power(oid: *mut c_void, selector: u32, filter: *const PowerState) -> u32 {
    let Some(rt) = rt() else { return crate::design::O_FAIL };
    if filter.is_null() {
        return if rt.power.unobserve(oid as usize, selector) { 0 } else { 6 };
    }
    // SAFETY: a valid openr_power_state from the object.
    let filter = unsafe { *filter };
    rt.power.observe(Observer { oid: oid as usize, selector, filter });
    0
}

extern "C" fn set_motor_power(on: i32) {
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

extern "C" fn shutdown() {
    if let Some(rt) = rt() {
        rt.request_shutdown();
    }
}
