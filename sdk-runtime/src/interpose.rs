//! C++ file streams inside objects. `std::ifstream`/`ofstream` open files from inside
//! libstdc++ (its `fopen64`), which mkbin's `--wrap` cannot reach (legacy-code 3:
//! openSDK missed exactly this). The runtime executable therefore defines and exports
//! `fopen64`, which every shared library's call binds to first: on an object's thread
//! it applies the `/MS` mapping; anywhere else, and for paths an object's wrapped call
//! already mapped, it is plain libc.
#![deny(unsafe_op_in_unsafe_fn)]

use std::ffi::{c_char, CStr, CString};
use std::sync::OnceLock;

use crate::runtime::Runtime;

type FopenFn = unsafe extern "C" fn(*const c_char, *const c_char) -> *mut libc::FILE;

fn real_fopen64() -> Option<FopenFn> {
    static REAL: OnceLock<usize> = OnceLock::new();
    let p = *REAL.get_or_init(|| unsafe { libc::dlsym(libc::RTLD_NEXT, c"fopen64".as_ptr()) } as usize);
    // SAFETY: libc's fopen64 has this signature.
    (p != 0).then(|| unsafe { std::mem::transmute::<usize, FopenFn>(p) })
}

/// The path to hand to libc for `path` opened by the current thread, or an errno.
fn mapped(path: &CStr, mode: &CStr) -> Result<Option<CString>, i32> {
    let (Some(rt), Some(_)) = (Runtime::get(), crate::object::current()) else { return Ok(None) };
    let p = path.to_string_lossy();
    if std::path::Path::new(&*p).starts_with(rt.ms.root()) {
        return Ok(None);
    }
    let create = mode.to_bytes().first().is_some_and(|c| *c == b'w' || *c == b'a');
    let host = rt.ms.resolve(&p, create).map_err(|r| r.errno())?;
    Ok(Some(CString::new(host.into_os_string().into_encoded_bytes()).map_err(|_| libc::ENOENT)?))
}

/// # Safety
/// Same contract as libc's `fopen64`.
#[no_mangle]
pub unsafe extern "C" fn fopen64(path: *const c_char, mode: *const c_char) -> *mut libc::FILE {
    let Some(real) = real_fopen64() else { return std::ptr::null_mut() };
    if path.is_null() || mode.is_null() {
        // SAFETY: forwarded unchanged.
        return unsafe { real(path, mode) };
    }
    // SAFETY: NUL-terminated strings from the caller.
    let (p, m) = unsafe { (CStr::from_ptr(path), CStr::from_ptr(mode)) };
    match mapped(p, m) {
        // SAFETY: valid C strings.
        Ok(None) => unsafe { real(path, mode) },
        Ok(Some(host)) => unsafe { real(host.as_ptr(), mode) },
        Err(errno) => {
            // SAFETY: errno is thread-local.
            unsafe { *libc::__errno_location() = errno };
            std::ptr::null_mut()
        }
    }
}

/// Keeps the interposer in the final link (referenced from the boot code).
pub fn keep() -> usize {
    fopen64 as *const () as usize
}
