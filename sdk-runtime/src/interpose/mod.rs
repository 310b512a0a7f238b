//! The file system as objects reach it (object-model 1.5). Every libc entry point that
//! takes a path is defined by the runtime executable and exported (cargo-openr's
//! build.rs), so it is what every shared library binds to first: objects, the
//! libstdc++ behind their `std::ifstream`, the wrappers mkbin links with `--wrap`.
//!
//! Whose call is it? A call whose return address lies outside the executable comes
//! from an object or a library working for one: its paths are `/MS/...` paths, mapped
//! and confined by [`MsDir`](crate::ms::MsDir) (anything else is ENOENT, as on the
//! robot; a way out is EACCES). A call from inside the executable is the runtime's own
//! (configuration, design data, the crash reporter, Rust's `std::fs`) and reaches libc
//! untouched, whatever thread makes it. The thread does not matter, so a thread an
//! object creates is covered like the object's own. Calls that address files relative
//! to a directory descriptor, make links or special files, or leave a file outside
//! (`tmpfile`, `mkstemp`) are refused from objects: the robot's C library had none.
//!
//! Each entry point is a two-instruction trampoline (`global_asm!`) that passes its
//! return address as an extra argument to the Rust function behind it.
#![deny(unsafe_op_in_unsafe_fn)]

use std::ffi::{c_char, CStr, CString};
use std::sync::OnceLock;

use crate::ms::Access;
use crate::runtime::Runtime;

#[macro_use]
mod real;
mod dirs;
mod fs;
mod process;
mod trampoline;

pub use fs::SYMBOLS;
pub use process::{SYMBOLS as PROCESS_SYMBOLS, SYMBOLS7 as PROCESS_SYMBOLS7};

/// The executable's address range: calls from there are the runtime's.
fn exe_range() -> (usize, usize) {
    static RANGE: OnceLock<(usize, usize)> = OnceLock::new();
    *RANGE.get_or_init(|| {
        unsafe extern "C" fn first(info: *mut libc::dl_phdr_info, _: usize, out: *mut libc::c_void) -> libc::c_int {
            // SAFETY: the loader passes a valid entry; `out` is the range below.
            let (info, out) = unsafe { (&*info, &mut *out.cast::<(usize, usize)>()) };
            let mut range = (usize::MAX, 0);
            for i in 0..info.dlpi_phnum as usize {
                // SAFETY: dlpi_phnum headers follow dlpi_phdr.
                let ph = unsafe { &*info.dlpi_phdr.add(i) };
                if ph.p_type == libc::PT_LOAD {
                    let start = info.dlpi_addr as usize + ph.p_vaddr as usize;
                    range = (range.0.min(start), range.1.max(start + ph.p_memsz as usize));
                }
            }
            *out = range;
            1 // the first entry is the executable
        }
        let mut range = (0usize, 0usize);
        // SAFETY: the callback writes only `range`.
        unsafe { libc::dl_iterate_phdr(Some(first), (&mut range as *mut (usize, usize)).cast()) };
        range
    })
}

/// The address ranges of a sanitizer runtime preloaded into the process (`cargo openr
/// run` preloads libasan/libtsan for objects built with `--sanitize`): its own file
/// accesses (libbacktrace reading the modules to symbolize a report, `/proc/self/maps`)
/// are the tool's, not an object's, and must not be confined to `/MS`.
fn sanitizer_ranges() -> &'static [(usize, usize)] {
    static RANGES: OnceLock<Vec<(usize, usize)>> = OnceLock::new();
    RANGES.get_or_init(|| {
        unsafe extern "C" fn each(info: *mut libc::dl_phdr_info, _: usize, out: *mut libc::c_void) -> libc::c_int {
            // SAFETY: the loader passes a valid entry; `out` is the vector below.
            let (info, out) = unsafe { (&*info, &mut *out.cast::<Vec<(usize, usize)>>()) };
            if info.dlpi_name.is_null() {
                return 0;
            }
            // SAFETY: a NUL-terminated module name.
            let name = unsafe { CStr::from_ptr(info.dlpi_name) }.to_string_lossy();
            let file = name.rsplit('/').next().unwrap_or("");
            if !["libasan.so", "libtsan.so", "liblsan.so", "libubsan.so"].iter().any(|l| file.starts_with(l)) {
                return 0;
            }
            for i in 0..info.dlpi_phnum as usize {
                // SAFETY: dlpi_phnum headers follow dlpi_phdr.
                let ph = unsafe { &*info.dlpi_phdr.add(i) };
                if ph.p_type == libc::PT_LOAD {
                    let start = info.dlpi_addr as usize + ph.p_vaddr as usize;
                    out.push((start, start + ph.p_memsz as usize));
                }
            }
            0
        }
        let mut ranges: Vec<(usize, usize)> = Vec::new();
        // SAFETY: the callback only pushes onto `ranges`.
        unsafe { libc::dl_iterate_phdr(Some(each), (&mut ranges as *mut Vec<(usize, usize)>).cast()) };
        ranges
    })
}

fn from_runtime(caller: usize) -> bool {
    let (lo, hi) = exe_range();
    (lo..hi).contains(&caller) || sanitizer_ranges().iter().any(|(lo, hi)| (*lo..*hi).contains(&caller))
}

/// What to hand to libc for one path argument.
pub(crate) enum Mapped {
    /// The runtime's own call (or no runtime): the path unchanged.
    Pass,
    Host(CString),
    Refused(i32),
}

impl Mapped {
    /// The pointer to pass on, or the errno to fail with.
    pub(crate) fn ptr(&self, original: *const c_char) -> Result<*const c_char, i32> {
        match self {
            Mapped::Pass => Ok(original),
            Mapped::Host(h) => Ok(h.as_ptr()),
            Mapped::Refused(e) => Err(*e),
        }
    }
}

/// Whether the caller at `caller` gets its paths mapped (an object's call, a runtime
/// installed).
pub(crate) fn is_objects(caller: usize) -> bool {
    !from_runtime(caller) && Runtime::get().is_some()
}

/// Maps `path` for a call made from `caller`.
///
/// # Safety
/// `path` is null or a NUL-terminated string.
pub(crate) unsafe fn map(caller: usize, path: *const c_char, access: Access) -> Mapped {
    let Some(rt) = Runtime::get().filter(|_| !from_runtime(caller)) else { return Mapped::Pass };
    if path.is_null() {
        return Mapped::Pass; // libc reports EFAULT/EINVAL itself
    }
    // SAFETY: the caller's C string.
    let Ok(p) = unsafe { CStr::from_ptr(path) }.to_str() else { return Mapped::Refused(libc::ENOENT) };
    let ms_path = as_ms_path(rt, p);
    match rt.ms.resolve(ms_path.as_deref().unwrap_or(p), access) {
        Ok(host) => match CString::new(host.into_os_string().into_encoded_bytes()) {
            Ok(c) => Mapped::Host(c),
            Err(_) => Mapped::Refused(libc::ENOENT),
        },
        Err(refusal) => Mapped::Refused(refusal.errno()),
    }
}

/// A host path inside the program's MS directory or the base tree — what objects built
/// with an older SDK root pass after mapping `/MS` themselves — as the `/MS` path it
/// stands for, so that it is normalised and confined like one (`<stick>/../x` escapes).
pub(crate) fn as_ms_path(rt: &Runtime, p: &str) -> Option<String> {
    [Some(rt.ms.root()), rt.ms.base()].into_iter().flatten().find_map(|layer| {
        let rest = p.strip_prefix(layer.to_str()?)?;
        (rest.is_empty() || rest.starts_with('/')).then(|| format!("/MS{rest}"))
    })
}

/// The `/MS` path a host path of the program's directory or the base tree stands for.
pub(crate) fn host_to_ms(host: &str) -> Option<String> {
    as_ms_path(Runtime::get()?, host)
}

pub(crate) fn set_errno(e: i32) {
    // SAFETY: errno is thread-local.
    unsafe { *libc::__errno_location() = e };
}

/// Keeps the interposers in the final link (referenced from the boot code) and
/// measures the executable before any object runs.
pub fn keep() -> usize {
    exe_range();
    sanitizer_ranges();
    fs::keep() ^ process::keep()
}
