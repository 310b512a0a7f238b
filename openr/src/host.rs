//! The runtime's table (`openr_runtime_api_v1`, found with `dlsym(RTLD_DEFAULT)` as the
//! C++ archives do) and thin safe wrappers over the calls this crate makes.
use std::ffi::{c_void, CStr};
use std::sync::OnceLock;

use crate::abi::{self, openr_host_api, MemId, OServiceEntry, Selector};

struct Api(&'static openr_host_api);
// SAFETY: the table is immutable and lives as long as the process.
unsafe impl Send for Api {}
// SAFETY: as for Send: the table is never written after the runtime built it.
unsafe impl Sync for Api {}

/// The runtime's table, `None` when the object runs outside cargo-openr.
pub(crate) fn api() -> Option<&'static openr_host_api> {
    static API: OnceLock<Option<Api>> = OnceLock::new();
    API.get_or_init(|| {
        // SAFETY: dlsym with a NUL-terminated name; the symbol, if present, is the
        // runtime's `struct openr_host_api`, valid for the life of the process.
        let p = unsafe { libc_dlsym(c"openr_runtime_api_v1") };
        if p.is_null() {
            return None;
        }
        let table = p as *const openr_host_api;
        // SAFETY: every version of the table starts with these two u32s; only they are read
        // before the size is known (a reference to the whole struct could overrun an older one).
        let (version, size) = unsafe { ((*table).abi_version, (*table).size) };
        if version != abi::HOST_ABI_VERSION || (size as usize) < std::mem::size_of::<openr_host_api>() {
            return None;
        }
        // SAFETY: the table holds at least a whole `openr_host_api`, never written again.
        Some(Api(unsafe { &*table }))
    })
    .as_ref()
    .map(|a| a.0)
}

extern "C" {
    fn dlsym(handle: *mut c_void, symbol: *const std::ffi::c_char) -> *mut c_void;
}

unsafe fn libc_dlsym(name: &CStr) -> *mut c_void {
    // RTLD_DEFAULT is ((void*)0) on glibc.
    // SAFETY: `name` is a C string; a null handle is RTLD_DEFAULT.
    unsafe { dlsym(std::ptr::null_mut(), name.as_ptr()) }
}

/// The calling object's OID address.
pub(crate) fn self_oid() -> *mut c_void {
    match api() {
        // SAFETY: the runtime's `self_oid` takes no arguments (a checked, live table).
        Some(a) => unsafe { (a.self_oid)() },
        None => std::ptr::null_mut(),
    }
}

/// Sends `msg` (a whole protocol struct) to `dest`. False if the runtime refused.
pub(crate) fn send<T: Copy>(dest: OServiceEntry, msg: &T) -> bool {
    let Some(a) = api() else { return false };
    // SAFETY: `msg` is a live repr(C) struct of size_of::<T>() bytes; the runtime copies it.
    unsafe { (a.send)(dest.oid, dest.selector, (msg as *const T).cast(), std::mem::size_of::<T>()) == 0 }
}

/// Replies to the call being processed.
pub(crate) fn reply<T: Copy>(msg: &T) {
    if let Some(a) = api() {
        // SAFETY: as in `send`.
        unsafe { (a.reply)((msg as *const T).cast(), std::mem::size_of::<T>()) };
    }
}

/// A reply type `call` may fill from the bytes another object sent.
///
/// # Safety
/// Every bit pattern of `size_of::<Self>()` bytes is a valid value: a `repr(C)` struct of
/// integers and raw pointers only (no `bool`, enum, reference or padding-sensitive field).
pub(crate) unsafe trait Plain: Copy {}

// SAFETY: u32 fields and an OServiceEntry (a raw pointer and a u32): any bits are valid.
unsafe impl Plain for crate::abi::OControlReplyMessage {}

/// Calls `dest` and reads a reply of type `R`; `Err(code)` with the host's code
/// (-1 unknown, -2 self, -3 timeout), or -4 for a short reply.
pub(crate) fn call<T: Copy, R: Plain>(dest: OServiceEntry, msg: &T, timeout_ms: u32) -> Result<R, i32> {
    let Some(a) = api() else { return Err(-1) };
    let mut out = std::mem::MaybeUninit::<R>::zeroed();
    let mut got = 0usize;
    // SAFETY: `out` has room for size_of::<R>() bytes; the runtime writes at most that.
    let rc = unsafe {
        (a.call)(
            dest.oid,
            dest.selector,
            (msg as *const T).cast(),
            std::mem::size_of::<T>(),
            out.as_mut_ptr().cast(),
            std::mem::size_of::<R>(),
            &mut got,
            timeout_ms,
        )
    };
    if rc != 0 {
        return Err(rc);
    }
    if got < std::mem::size_of::<R>() {
        return Err(-4);
    }
    // SAFETY: zeroed, then filled with size_of::<R>() bytes; R: Plain takes any bits.
    Ok(unsafe { out.assume_init() })
}

/// Registers `name` at (self, selector): 0 ok, 1 already registered, -1 no runtime.
pub(crate) fn register_service(name: &str, selector: Selector) -> i32 {
    let Some(a) = api() else { return -1 };
    let Ok(c) = std::ffi::CString::new(name) else { return -1 };
    // SAFETY: `c` is a C string that outlives the call; the runtime copies the name.
    unsafe { (a.register_service)(c.as_ptr(), self_oid(), selector) }
}

pub(crate) fn unregister_services() {
    if let Some(a) = api() {
        // SAFETY: the runtime's `unregister_services` takes no arguments.
        unsafe { (a.unregister_services)() };
    }
}

/// Writes to the console in one piece (stdout without a runtime).
pub(crate) fn console_write(text: &[u8]) {
    match api() {
        // SAFETY: `text` is a live slice of `len` bytes; the runtime writes it out before returning.
        Some(a) => unsafe { (a.console_write)(text.as_ptr().cast(), text.len()) },
        None => {
            use std::io::Write;
            let mut out = std::io::stdout().lock();
            let _ = out.write_all(text);
            let _ = out.flush();
        }
    }
}

pub(crate) fn shm_alloc(size: usize) -> Option<(MemId, *mut u8)> {
    let a = api()?;
    let mut id = MemId::default();
    // SAFETY: `id` is a live MemId (a u32 in the ABI) the runtime writes.
    let p = unsafe { (a.shm_alloc)(size, &mut id) };
    (!p.is_null()).then_some((id, p.cast()))
}

pub(crate) fn shm_base(id: MemId) -> Option<(*mut u8, usize)> {
    let a = api()?;
    let mut size = 0;
    // SAFETY: `size` is a live usize the runtime writes.
    let p = unsafe { (a.shm_base)(id, &mut size) };
    (!p.is_null()).then_some((p.cast(), size))
}

pub(crate) fn shm_ref(id: MemId) {
    if let Some(a) = api() {
        // SAFETY: any id is accepted (an unknown one is ignored by the runtime).
        unsafe { (a.shm_ref)(id) };
    }
}

pub(crate) fn shm_unref(id: MemId) {
    if let Some(a) = api() {
        // SAFETY: any id is accepted (an unknown one is ignored by the runtime).
        unsafe { (a.shm_unref)(id) };
    }
}
