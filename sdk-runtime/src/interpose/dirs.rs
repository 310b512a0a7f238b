//! Listings of the overlaid stick: a directory both the program's MS and the base tree
//! have lists the program's entries, then those only the base tree has (names compared
//! case-insensitively, as FAT does) — what `ls` showed on the robot's stick.
use std::ffi::{c_char, CStr, CString};
use std::sync::Mutex;

use crate::runtime::Runtime;

/// The base tree's entries still to list for one open `DIR*` of an object.
struct Extra {
    dir: usize,
    names: Vec<(CString, u8)>,
    next: usize,
    ent: Box<libc::dirent64>,
}

// SAFETY: `ent` is only touched with the lock held.
unsafe impl Send for Extra {}

static OPEN: Mutex<Vec<Extra>> = Mutex::new(Vec::new());

fn open_dirs() -> std::sync::MutexGuard<'static, Vec<Extra>> {
    OPEN.lock().unwrap_or_else(|p| p.into_inner())
}

/// An object opened `ms_path` (mapped to `host`) as `dir`: remember what the base tree
/// adds to it.
///
/// # Safety
/// `ms_path` and `host` are NUL-terminated strings.
pub(super) unsafe fn opened(dir: *mut libc::c_void, ms_path: *const c_char, host: *const c_char) {
    let Some(rt) = Runtime::get() else { return };
    // SAFETY: the caller's strings.
    let (ms_path, host) = unsafe { (CStr::from_ptr(ms_path), CStr::from_ptr(host)) };
    let (Ok(ms_path), Ok(host)) = (ms_path.to_str(), host.to_str()) else { return };
    let Some(lower) = rt.ms.lower_dir(&super::as_ms_path(rt, ms_path).unwrap_or_else(|| ms_path.to_string())) else { return };
    let own: Vec<String> = names_in(std::path::Path::new(host)).map(|(n, _)| n).collect();
    let names: Vec<(CString, u8)> =
        names_in(&lower).filter(|(n, _)| !own.iter().any(|o| o.eq_ignore_ascii_case(n))).filter_map(|(n, t)| Some((CString::new(n).ok()?, t))).collect();
    if !names.is_empty() {
        // SAFETY: a plain C struct; all zero is a valid value.
        let ent = Box::new(unsafe { std::mem::zeroed::<libc::dirent64>() });
        open_dirs().push(Extra { dir: dir as usize, names, next: 0, ent });
    }
}

fn names_in(dir: &std::path::Path) -> impl Iterator<Item = (String, u8)> {
    std::fs::read_dir(dir).into_iter().flatten().flatten().map(|e| {
        let kind = match e.file_type() {
            Ok(t) if t.is_dir() => libc::DT_DIR,
            Ok(t) if t.is_file() => libc::DT_REG,
            _ => libc::DT_UNKNOWN,
        };
        (e.file_name().to_string_lossy().into_owned(), kind)
    })
}

/// The next entry the base tree adds to `dir` once libc's listing has ended, or null.
pub(super) fn next_extra(dir: *mut libc::c_void) -> *mut libc::dirent64 {
    let mut open = open_dirs();
    let Some(x) = open.iter_mut().find(|x| x.dir == dir as usize) else { return std::ptr::null_mut() };
    let Some((name, kind)) = x.names.get(x.next) else { return std::ptr::null_mut() };
    x.next += 1;
    let ent = &mut *x.ent;
    let bytes = name.as_bytes_with_nul();
    let n = bytes.len().min(ent.d_name.len());
    for (d, s) in ent.d_name.iter_mut().zip(&bytes[..n]) {
        *d = *s as c_char;
    }
    ent.d_name[n - 1] = 0;
    ent.d_ino = 1;
    ent.d_type = *kind;
    ent.d_reclen = std::mem::size_of::<libc::dirent64>() as u16;
    // Stable while the DIR is open: the Box does not move.
    ent as *mut libc::dirent64
}

/// `rewinddir`: list the base tree's entries again.
pub(super) fn rewound(dir: *mut libc::c_void) {
    if let Some(x) = open_dirs().iter_mut().find(|x| x.dir == dir as usize) {
        x.next = 0;
    }
}

/// `closedir`: forget `dir`.
pub(super) fn closed(dir: *mut libc::c_void) {
    open_dirs().retain(|x| x.dir != dir as usize);
}
