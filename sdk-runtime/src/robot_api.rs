//! The OPENR:: hardware calls of `openr_host.h` (primitives, gains, readings, sync keys,
//! data vectors) and the two calls system objects use (`vr_attach`, `vr_submit`).
//! Each returns an OStatus value, as the OPENR:: function that forwards it.
//!
//! Ids arrive typed ([`PrimitiveId`], [`MemId`], [`SyncKey`], [`Selector`]); the
//! robot model (`openr-robot`, no ABI dependency) numbers its primitives and sync keys
//! with plain `u32`s, so they are unwrapped only where it is called.
#![deny(unsafe_op_in_unsafe_fn)]

use openr_sys::{self as sys, MemId, PrimitiveId, Selector, SyncKey};
use std::ffi::{c_char, c_void, CStr};

use crate::gateway::proxy;
use crate::robot::status::*;
use crate::robot::{vectors, Gain, VirtualRobot};
use crate::runtime::Runtime;

const O_NO_MEMORY: u32 = 5;

fn with_robot<T>(f: impl FnOnce(&mut VirtualRobot) -> T) -> Option<T> {
    Runtime::get().map(|rt| f(&mut rt.vr.robot()))
}

pub unsafe fn open_primitive(locator: *const c_char, id: *mut PrimitiveId) -> u32 {
    if locator.is_null() || id.is_null() {
        return O_INVALID_ARG;
    }
    // SAFETY: NUL-terminated string from the object.
    let loc = unsafe { CStr::from_ptr(locator) }.to_string_lossy().into_owned();
    if let Some(reply) = proxy::call(proxy::OPEN_PRIMITIVE, loc.as_bytes()) {
        let (st, out) = proxy::split(&reply);
        if let Some(p) = out.get(..4) {
            // SAFETY: out-param.
            unsafe { *id = PrimitiveId(u32::from_le_bytes([p[0], p[1], p[2], p[3]])) };
        }
        return st;
    }
    match with_robot(|r| r.open_primitive(&loc)) {
        Some(Ok(p)) => {
            // SAFETY: out-param.
            unsafe { *id = PrimitiveId(p) };
            O_SUCCESS
        }
        Some(Err(st)) => st,
        None => O_FAIL,
    }
}

pub fn close_primitive(id: PrimitiveId) -> u32 {
    if let Some(reply) = proxy::call(proxy::CLOSE_PRIMITIVE, &id.0.to_le_bytes()) {
        return proxy::split(&reply).0;
    }
    with_robot(|r| r.close_primitive(id.0)).unwrap_or(O_FAIL)
}

/// Device requests (robot-api 5). The camera's white balance, gain and shutter change
/// the rendered image; the speaker and mic requests are accepted (the emulated
/// amplifier has no volume or mute of its own).
pub unsafe fn control_primitive(id: PrimitiveId, req: u32, p: *const c_void, ps: usize, _r: *mut c_void, _rs: usize) -> u32 {
    with_robot(|r| {
        if r.model().primitive(id.0).is_none() {
            return O_INVALID_PRIMITIVE_ID;
        }
        if (384..=386).contains(&req) {
            if p.is_null() || ps < 4 {
                return O_INVALID_ARG;
            }
            // SAFETY: OPrimitiveControl_CameraParam { longword camparam; }
            let camparam = unsafe { std::ptr::read_unaligned(p.cast::<u32>()) };
            return r.camera_control(id.0, req, camparam);
        }
        O_SUCCESS
    })
    .unwrap_or(O_FAIL)
}

pub unsafe fn joint_gain(op: i32, id: PrimitiveId, gains: *mut u16) -> u32 {
    let read = |g: *mut u16| -> Option<Gain> {
        if g.is_null() {
            return None;
        }
        // SAFETY: six words from the object.
        let w = unsafe { std::slice::from_raw_parts(g, 6) };
        Some(Gain { p: w[0], i: w[1], d: w[2], p_shift: w[3], i_shift: w[4], d_shift: w[5] })
    };
    let write = |g: *mut u16, v: Gain| {
        if !g.is_null() {
            // SAFETY: six words from the object.
            let w = unsafe { std::slice::from_raw_parts_mut(g, 6) };
            w.copy_from_slice(&[v.p, v.i, v.d, v.p_shift, v.i_shift, v.d_shift]);
        }
    };
    if let Some(st) = proxied_gain(op, id, gains) {
        return st;
    }
    let id = id.0;
    with_robot(|r| match op {
        sys::GAIN_ENABLE => r.enable_joint_gain(id),
        sys::GAIN_DISABLE => r.disable_joint_gain(id),
        sys::GAIN_SET => read(gains).map_or(O_INVALID_ARG, |g| r.set_joint_gain(id, g)),
        sys::GAIN_REGISTER_DEFAULT => read(gains).map_or(O_INVALID_ARG, |g| r.register_default_joint_gain(id, g)),
        sys::GAIN_SET_DEFAULT => r.set_default_joint_gain(id),
        sys::GAIN_GET => r.get_joint_gain(id).map_or_else(
            |e| e,
            |g| {
                write(gains, g);
                O_SUCCESS
            },
        ),
        sys::GAIN_GET_DEFAULT => r.get_default_joint_gain(id).map_or_else(
            |e| e,
            |g| {
                write(gains, g);
                O_SUCCESS
            },
        ),
        _ => O_INVALID_ARG,
    })
    .unwrap_or(O_FAIL)
}

/// `joint_gain` on the robot of an RP host program (`None`: no proxy, run it here).
fn proxied_gain(op: i32, id: PrimitiveId, gains: *mut u16) -> Option<u32> {
    let mut args = [op.to_le_bytes(), id.0.to_le_bytes()].concat();
    let mut words = [0u16; 6];
    if !gains.is_null() && matches!(op, sys::GAIN_SET | sys::GAIN_REGISTER_DEFAULT) {
        // SAFETY: six words from the object.
        words.copy_from_slice(unsafe { std::slice::from_raw_parts(gains, 6) });
    }
    words.iter().for_each(|w| args.extend_from_slice(&w.to_le_bytes()));
    let reply = proxy::call(proxy::JOINT_GAIN, &args)?;
    let (st, out) = proxy::split(&reply);
    if st == O_SUCCESS && !gains.is_null() && matches!(op, sys::GAIN_GET | sys::GAIN_GET_DEFAULT) && out.len() >= 12 {
        for k in 0..6 {
            // SAFETY: six words from the object.
            unsafe { *gains.add(k) = u16::from_le_bytes([out[2 * k], out[2 * k + 1]]) };
        }
    }
    Some(st)
}

/// A 16-byte value read on the robot of an RP host program (`None`: no proxy).
unsafe fn proxied_value(api: u8, id: PrimitiveId, out: *mut c_void) -> Option<u32> {
    let reply = proxy::call(api, &id.0.to_le_bytes())?;
    let (st, v) = proxy::split(&reply);
    if st == O_SUCCESS && v.len() >= 16 {
        let mut b = [0u8; 16];
        b.copy_from_slice(&v[..16]);
        // SAFETY: see put16 (the caller checked `out`).
        unsafe { put16(out, b) };
    }
    Some(st)
}

unsafe fn put16(out: *mut c_void, bytes: [u8; 16]) {
    // SAFETY: a 16-byte OJointValue/OSensorValue from the object.
    unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), out.cast::<u8>(), 16) };
}

pub unsafe fn joint_value(id: PrimitiveId, out: *mut c_void) -> u32 {
    if out.is_null() {
        return O_INVALID_ARG;
    }
    // SAFETY: `out` is the object's 16-byte value (checked non-null).
    if let Some(st) = unsafe { proxied_value(proxy::JOINT_VALUE, id, out) } {
        return st;
    }
    match with_robot(|r| r.joint_value(id.0)) {
        Some(Ok(v)) => {
            // SAFETY: see put16.
            unsafe { put16(out, v.to_bytes()) };
            O_SUCCESS
        }
        Some(Err(st)) => st,
        None => O_FAIL,
    }
}

pub unsafe fn sensor_value(id: PrimitiveId, out: *mut c_void) -> u32 {
    if out.is_null() {
        return O_INVALID_ARG;
    }
    // SAFETY: `out` is the object's 16-byte value (checked non-null).
    if let Some(st) = unsafe { proxied_value(proxy::SENSOR_VALUE, id, out) } {
        return st;
    }
    match with_robot(|r| r.sensor_value(id.0)) {
        Some(Ok(v)) => {
            // SAFETY: see put16.
            unsafe { put16(out, v.to_bytes()) };
            O_SUCCESS
        }
        Some(Err(st)) => st,
        None => O_FAIL,
    }
}

pub unsafe fn sync_key(op: i32, key: SyncKey, k1: *mut SyncKey, k2: *mut SyncKey) -> u32 {
    let put = |p: *mut SyncKey, v: u32| {
        if !p.is_null() {
            // SAFETY: out-param.
            unsafe { *p = SyncKey(v) };
        }
    };
    with_robot(|r| match op {
        sys::SYNC_NEW => r.new_sync_key().map_or_else(
            |e| e,
            |k| {
                put(k1, k);
                O_SUCCESS
            },
        ),
        sys::SYNC_CANCEL => r.cancel_sync_key(key.0),
        sys::SYNC_DIVIDE => r.divide_sync_key(key.0).map_or_else(
            |e| e,
            |(a, b)| {
                put(k1, a);
                put(k2, b);
                O_SUCCESS
            },
        ),
        _ => O_INVALID_ARG,
    })
    .unwrap_or(O_FAIL)
}

/// `OCdtVectorData` as `NewCdtVectorData` leaves it (robot-api 6.7).
fn cdt_vector_init(buf: &mut [u8]) {
    let put = |buf: &mut [u8], off: usize, v: u32| buf[off..off + 4].copy_from_slice(&v.to_le_bytes());
    put(buf, 16, 1028);
    put(buf, 20, 192);
    put(buf, 24, 144);
    put(buf, 28, 8);
    put(buf, 32, 0);
    put(buf, 36, 0xFFFF_FFFF);
    for i in 0..8 {
        let info = 192 + 144 * i;
        put(buf, info, 21);
        put(buf, info + 4, 0xFFFF_FFFF);
        put(buf, info + 8, 0);
        for e in 0..32 {
            put(buf, info + 12 + 4 * e, 0x8080_8080);
        }
    }
}

pub unsafe fn new_vector(kind: i32, n: usize, data_size: usize, mem_id: *mut MemId, base: *mut *mut c_void) -> u32 {
    let Some(rt) = Runtime::get() else { return O_FAIL };
    if mem_id.is_null() || base.is_null() || n == 0 || n > 4096 || data_size > 1 << 24 {
        return O_INVALID_ARG;
    }
    let design = rt.design.to_string_lossy().into_owned();
    let image = rt.vr.robot().image_layout();
    let size = match kind {
        sys::VECTOR_COMMAND => vectors::command_vector_size(n),
        sys::VECTOR_SOUND => vectors::sound_vector_size(n, data_size),
        sys::VECTOR_CDT => 192 + 144 * 8,
        sys::VECTOR_SENSOR => vectors::sensor_vector_size(n),
        sys::VECTOR_IMAGE => image.size(),
        _ => return O_INVALID_ARG,
    };
    let total = vectors::region_size(size);
    let Some((id, p)) = rt.shm.alloc(total) else { return O_NO_MEMORY };
    // SAFETY: a fresh zeroed region of `total` bytes.
    let buf = unsafe { std::slice::from_raw_parts_mut(p, total) };
    let init = match kind {
        sys::VECTOR_COMMAND => vectors::command_vector_init(buf, n).is_ok(),
        sys::VECTOR_SOUND => vectors::sound_vector_init(buf, n, data_size, &design).is_ok(),
        sys::VECTOR_CDT => {
            cdt_vector_init(buf);
            true
        }
        sys::VECTOR_SENSOR => vectors::sensor_vector_init(buf, n).is_ok(),
        _ => image.write_header(buf, u32::MAX, u32::MAX).is_ok(),
    };
    if !init || vectors::set_region_fields(buf, id.0, 0, total as u32).is_err() {
        rt.shm.unref(id);
        return O_FAIL;
    }
    rt.vectors.lock().unwrap_or_else(|p| p.into_inner()).push(id);
    // SAFETY: out-params.
    unsafe {
        *mem_id = id;
        *base = p.cast();
    }
    O_SUCCESS
}

pub fn delete_vector(mem_id: MemId) -> u32 {
    let Some(rt) = Runtime::get() else { return O_FAIL };
    let mut v = rt.vectors.lock().unwrap_or_else(|p| p.into_inner());
    match v.iter().position(|i| *i == mem_id) {
        Some(pos) => {
            v.swap_remove(pos);
            rt.shm.unref(mem_id);
            O_SUCCESS
        }
        None => O_INVALID_ARG,
    }
}

/// `SetCdtVectorData`: the camera detects colours with these tables from the next
/// image on (robot-api 6.7).
pub fn set_cdt(mem_id: MemId) -> u32 {
    let Some(rt) = Runtime::get() else { return O_FAIL };
    match rt.shm.base(mem_id) {
        Some((p, n)) => {
            // SAFETY: a live region of n bytes.
            let b = unsafe { std::slice::from_raw_parts(p, n) };
            rt.vr.robot().set_cdt(b)
        }
        None => O_INVALID_ARG,
    }
}

pub unsafe fn volume_switch(set: i32, value: *mut u8) -> u32 {
    let Some(rt) = Runtime::get() else { return O_FAIL };
    if value.is_null() {
        return O_INVALID_ARG;
    }
    if set != 0 {
        // SAFETY: in-param.
        let v = unsafe { *value };
        if v > 3 {
            return O_INVALID_ARG;
        }
        crate::boot::update_power(rt, |s| s.volume = v.into());
    } else {
        // SAFETY: out-param.
        unsafe { *value = rt.power.state().volume as u8 };
    }
    O_SUCCESS
}

pub fn vr_attach(service: i32, selector: Selector) -> u32 {
    let (Some(rt), Some(me)) = (Runtime::get(), crate::object::current()) else { return O_FAIL };
    if rt.vr.attach(service as usize, me.oid, selector) {
        O_SUCCESS
    } else {
        O_INVALID_ARG
    }
}

pub unsafe fn vr_submit(service: i32, oid: *mut c_void, selector: Selector, base: *mut c_void, size: usize, token: *mut u64) -> u32 {
    let Some(rt) = Runtime::get() else { return O_FAIL };
    if base.is_null() || token.is_null() {
        return O_INVALID_ARG;
    }
    if service as usize == crate::vr::SERVICE_SPEAKER {
        return match rt.vr.submit_sound(base as usize, size) {
            Ok(t) => {
                // SAFETY: out-param.
                unsafe { *token = t };
                O_SUCCESS
            }
            Err(e) => {
                rt.diag.warn(&format!("speaker: sound vector refused: {e}"));
                O_INVALID_ARG
            }
        };
    }
    if service as usize != crate::vr::SERVICE_EFFECTOR {
        return O_NOT_SUPPORTED;
    }
    match rt.vr.submit((oid as usize, selector), base as usize, size) {
        Ok(t) => {
            // SAFETY: out-param.
            unsafe { *token = t };
            O_SUCCESS
        }
        Err(e) => {
            rt.diag.warn(&format!("effector: malformed command vector refused: {e}"));
            O_INVALID_ARG
        }
    }
}
