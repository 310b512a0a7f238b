//! The path-taking entry points of glibc, each behind a trampoline: an object's call is
//! mapped (or refused) and handed to the real function, the runtime's is handed on as
//! it is. Every function takes the caller's return address last (see `trampoline`).
#![allow(clippy::too_many_arguments)]
// `real!`/`call!` carry their own `unsafe`, and are used inside `unsafe` blocks too.
#![allow(unused_unsafe)]

use std::ffi::{c_char, c_int, c_uint, c_void};
use std::ptr::null_mut;

use super::real::fail;
use super::trampoline::trampolines;
use super::{host_to_ms, is_objects, map, set_errno, Mapped};
use crate::ms::Access;

type C = *const c_char;
type P = *mut c_void;

/// `call(path)` with `path` mapped for an object's call, or `fail` with its errno.
unsafe fn with<R>(caller: usize, path: C, access: Access, failed: R, call: impl FnOnce(C) -> R) -> R {
    // SAFETY: `path` is the caller's C string (or null).
    let mapped = unsafe { map(caller, path, access) };
    match mapped.ptr(path) {
        Ok(p) => call(p),
        Err(e) => fail(e, failed),
    }
}

/// Same for the `*at` calls: an object's absolute path is mapped; a relative one is
/// refused (no working directory on the robot: ENOENT; relative to a directory
/// descriptor, which could lead anywhere: EACCES); an empty one with AT_EMPTY_PATH
/// means the descriptor itself.
unsafe fn with_at<R>(caller: usize, dirfd: c_int, path: C, access: Access, empty_ok: bool, failed: R, call: impl FnOnce(C) -> R) -> R {
    if path.is_null() || !is_objects(caller) {
        return call(path);
    }
    // SAFETY: a non-null C string has a first byte.
    match unsafe { *path } as u8 {
        // SAFETY: `path` is the caller's non-null C string.
        b'/' => unsafe { with(caller, path, access, failed, call) },
        0 if empty_ok => call(path),
        _ if dirfd == libc::AT_FDCWD => fail(libc::ENOENT, failed),
        _ => fail(libc::EACCES, failed),
    }
}

/// Two paths (rename, link): both mapped, or the first refusal.
unsafe fn with2<R>(caller: usize, a: (C, Access), b: (C, Access), failed: R, call: impl FnOnce(C, C) -> R) -> R {
    // SAFETY: the caller's C strings.
    let (ma, mb) = unsafe { (map(caller, a.0, a.1), map(caller, b.0, b.1)) };
    match (ma.ptr(a.0), mb.ptr(b.0)) {
        (Ok(pa), Ok(pb)) => call(pa, pb),
        (Err(e), _) | (_, Err(e)) => fail(e, failed),
    }
}

/// What the robot's FAT stick cannot hold (links, devices, FIFOs): for an object, the
/// path's own refusal if it has one (ENOENT off the stick, EACCES out of it), else
/// EPERM — what Linux's vfat answers.
unsafe fn fat_has_none<R>(caller: usize, paths: &[C], failed: R, call: impl FnOnce() -> R) -> R {
    if !is_objects(caller) {
        return call();
    }
    for &path in paths {
        // SAFETY: the caller's C string. Read access: checking makes no directory.
        if let Mapped::Refused(e) = unsafe { map(caller, path, Access::Read) } {
            return fail(e, failed);
        }
    }
    fail(libc::EPERM, failed)
}

/// For an object: not functional on the robot (ENOSYS); else `call()`.
fn not_on_robot<R>(caller: usize, failed: R, call: impl FnOnce() -> R) -> R {
    if is_objects(caller) {
        fail(libc::ENOSYS, failed)
    } else {
        call()
    }
}

fn open_access(flags: c_int) -> Access {
    let writes = flags & libc::O_ACCMODE != libc::O_RDONLY || flags & (libc::O_CREAT | libc::O_TRUNC) != 0;
    if writes {
        Access::Write
    } else {
        Access::Read
    }
}

/// `fopen` modes: only "r" (with "b", "e", "m", "c" qualifiers) reads without writing.
unsafe fn mode_access(mode: C) -> Access {
    if mode.is_null() {
        return Access::Read;
    }
    // SAFETY: the caller's C string.
    let m = unsafe { std::ffi::CStr::from_ptr(mode) }.to_bytes();
    if m.first() == Some(&b'r') && !m.contains(&b'+') {
        Access::Read
    } else {
        Access::Write
    }
}

trampolines! {
    "open" => open, "open64" => open64, "__open_2" => open_2, "__open64_2" => open64_2,
    "openat" => openat, "openat64" => openat64, "__openat_2" => openat_2, "__openat64_2" => openat64_2,
    "creat" => creat, "creat64" => creat64,
    "fopen" => fopen, "fopen64" => fopen64, "freopen" => freopen, "freopen64" => freopen64,
    "stat" => stat, "stat64" => stat64, "lstat" => lstat, "lstat64" => lstat64,
    "fstatat" => fstatat, "fstatat64" => fstatat64, "statx" => statx,
    "statfs" => statfs, "statfs64" => statfs64, "statvfs" => statvfs, "statvfs64" => statvfs64,
    "access" => access, "euidaccess" => euidaccess, "eaccess" => eaccess, "faccessat" => faccessat,
    "opendir" => opendir, "readdir" => readdir, "readdir64" => readdir64, "rewinddir" => rewinddir,
    "closedir" => closedir, "scandir" => scandir, "scandir64" => scandir64, "scandirat" => scandirat,
    "mkdir" => mkdir, "mkdirat" => mkdirat, "rmdir" => rmdir,
    "unlink" => unlink, "unlinkat" => unlinkat, "remove" => remove,
    "rename" => rename, "renameat" => renameat, "renameat2" => renameat2,
    "truncate" => truncate, "truncate64" => truncate64,
    "chmod" => chmod, "fchmodat" => fchmodat, "chown" => chown, "lchown" => lchown, "fchownat" => fchownat,
    "utime" => utime, "utimes" => utimes, "lutimes" => lutimes, "futimesat" => futimesat, "utimensat" => utimensat,
    "readlink" => readlink, "readlinkat" => readlinkat, "realpath" => realpath,
    "getxattr" => getxattr, "lgetxattr" => lgetxattr, "listxattr" => listxattr, "llistxattr" => llistxattr,
    "setxattr" => setxattr, "lsetxattr" => lsetxattr, "removexattr" => removexattr, "lremovexattr" => lremovexattr,
    "link" => link, "linkat" => linkat, "symlink" => symlink, "symlinkat" => symlinkat,
    "mknod" => mknod, "mknodat" => mknodat, "mkfifo" => mkfifo, "mkfifoat" => mkfifoat,
    "chdir" => chdir, "fchdir" => fchdir, "chroot" => chroot,
    "tmpfile" => tmpfile, "tmpfile64" => tmpfile64, "mkstemp" => mkstemp, "mkstemp64" => mkstemp64,
    "mkostemp" => mkostemp, "mkstemps" => mkstemps, "mkostemps" => mkostemps, "mkdtemp" => mkdtemp,
    "ftw" => ftw, "nftw" => nftw,
}

/// A Rust function of this module, so the module's code (trampolines included) stays
/// in the link.
pub fn keep() -> usize {
    open as *const () as usize
}

// ---- opening ----

unsafe extern "C" fn open(path: C, flags: c_int, mode: c_uint, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `open`, passed on with the path mapped.
    unsafe { with(caller, path, open_access(flags), -1, |p| call!("open", -1, fn(C, c_int, c_uint) -> c_int, p, flags, mode)) }
}
unsafe extern "C" fn open64(path: C, flags: c_int, mode: c_uint, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `open64`, passed on with the path mapped.
    unsafe { with(caller, path, open_access(flags), -1, |p| call!("open64", -1, fn(C, c_int, c_uint) -> c_int, p, flags, mode)) }
}
unsafe extern "C" fn open_2(path: C, flags: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `__open_2`, passed on with the path mapped.
    unsafe { with(caller, path, open_access(flags), -1, |p| call!("__open_2", -1, fn(C, c_int) -> c_int, p, flags)) }
}
unsafe extern "C" fn open64_2(path: C, flags: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `__open64_2`, passed on with the path mapped.
    unsafe { with(caller, path, open_access(flags), -1, |p| call!("__open64_2", -1, fn(C, c_int) -> c_int, p, flags)) }
}
unsafe extern "C" fn openat(fd: c_int, path: C, flags: c_int, mode: c_uint, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `openat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, open_access(flags), false, -1, |p| call!("openat", -1, fn(c_int, C, c_int, c_uint) -> c_int, fd, p, flags, mode)) }
}
unsafe extern "C" fn openat64(fd: c_int, path: C, flags: c_int, mode: c_uint, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `openat64`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, open_access(flags), false, -1, |p| call!("openat64", -1, fn(c_int, C, c_int, c_uint) -> c_int, fd, p, flags, mode)) }
}
unsafe extern "C" fn openat_2(fd: c_int, path: C, flags: c_int, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `__openat_2`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, open_access(flags), false, -1, |p| call!("__openat_2", -1, fn(c_int, C, c_int) -> c_int, fd, p, flags)) }
}
unsafe extern "C" fn openat64_2(fd: c_int, path: C, flags: c_int, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `__openat64_2`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, open_access(flags), false, -1, |p| call!("__openat64_2", -1, fn(c_int, C, c_int) -> c_int, fd, p, flags)) }
}
unsafe extern "C" fn creat(path: C, mode: c_uint, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `creat`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("creat", -1, fn(C, c_uint) -> c_int, p, mode)) }
}
unsafe extern "C" fn creat64(path: C, mode: c_uint, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `creat64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("creat64", -1, fn(C, c_uint) -> c_int, p, mode)) }
}
unsafe extern "C" fn fopen(path: C, mode: C, _: usize, _: usize, _: usize, caller: usize) -> P {
    // SAFETY: the caller's arguments for glibc's `fopen`, passed on with the path mapped.
    unsafe { with(caller, path, mode_access(mode), null_mut(), |p| call!("fopen", null_mut(), fn(C, C) -> P, p, mode)) }
}
unsafe extern "C" fn fopen64(path: C, mode: C, _: usize, _: usize, _: usize, caller: usize) -> P {
    // SAFETY: the caller's arguments for glibc's `fopen64`, passed on with the path mapped.
    unsafe { with(caller, path, mode_access(mode), null_mut(), |p| call!("fopen64", null_mut(), fn(C, C) -> P, p, mode)) }
}
unsafe extern "C" fn freopen(path: C, mode: C, f: P, _: usize, _: usize, caller: usize) -> P {
    // SAFETY: the caller's arguments for glibc's `freopen`, passed on with the path mapped.
    unsafe { with(caller, path, mode_access(mode), null_mut(), |p| call!("freopen", null_mut(), fn(C, C, P) -> P, p, mode, f)) }
}
unsafe extern "C" fn freopen64(path: C, mode: C, f: P, _: usize, _: usize, caller: usize) -> P {
    // SAFETY: the caller's arguments for glibc's `freopen64`, passed on with the path mapped.
    unsafe { with(caller, path, mode_access(mode), null_mut(), |p| call!("freopen64", null_mut(), fn(C, C, P) -> P, p, mode, f)) }
}

// ---- inspecting ----

unsafe extern "C" fn stat(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `stat`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("stat", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn stat64(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `stat64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("stat64", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn lstat(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `lstat`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("lstat", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn lstat64(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `lstat64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("lstat64", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn fstatat(fd: c_int, path: C, buf: P, flags: c_int, _: usize, caller: usize) -> c_int {
    let empty = flags & libc::AT_EMPTY_PATH != 0;
    // SAFETY: the caller's arguments for glibc's `fstatat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Read, empty, -1, |p| call!("fstatat", -1, fn(c_int, C, P, c_int) -> c_int, fd, p, buf, flags)) }
}
unsafe extern "C" fn fstatat64(fd: c_int, path: C, buf: P, flags: c_int, _: usize, caller: usize) -> c_int {
    let empty = flags & libc::AT_EMPTY_PATH != 0;
    // SAFETY: the caller's arguments for glibc's `fstatat64`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Read, empty, -1, |p| call!("fstatat64", -1, fn(c_int, C, P, c_int) -> c_int, fd, p, buf, flags)) }
}
unsafe extern "C" fn statx(fd: c_int, path: C, flags: c_int, mask: c_uint, buf: P, caller: usize) -> c_int {
    let empty = flags & libc::AT_EMPTY_PATH != 0;
    // SAFETY: the caller's arguments for glibc's `statx`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Read, empty, -1, |p| call!("statx", -1, fn(c_int, C, c_int, c_uint, P) -> c_int, fd, p, flags, mask, buf)) }
}
unsafe extern "C" fn statfs(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `statfs`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("statfs", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn statfs64(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `statfs64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("statfs64", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn statvfs(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `statvfs`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("statvfs", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn statvfs64(path: C, buf: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `statvfs64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("statvfs64", -1, fn(C, P) -> c_int, p, buf)) }
}
unsafe extern "C" fn access(path: C, how: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `access`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("access", -1, fn(C, c_int) -> c_int, p, how)) }
}
unsafe extern "C" fn euidaccess(path: C, how: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `euidaccess`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("euidaccess", -1, fn(C, c_int) -> c_int, p, how)) }
}
unsafe extern "C" fn eaccess(path: C, how: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `eaccess`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("eaccess", -1, fn(C, c_int) -> c_int, p, how)) }
}
unsafe extern "C" fn faccessat(fd: c_int, path: C, how: c_int, flags: c_int, _: usize, caller: usize) -> c_int {
    let empty = flags & libc::AT_EMPTY_PATH != 0;
    // SAFETY: the caller's arguments for glibc's `faccessat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Read, empty, -1, |p| call!("faccessat", -1, fn(c_int, C, c_int, c_int) -> c_int, fd, p, how, flags)) }
}
unsafe extern "C" fn readlink(path: C, buf: P, len: usize, _: usize, _: usize, caller: usize) -> isize {
    // SAFETY: the caller's arguments for glibc's `readlink`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("readlink", -1, fn(C, P, usize) -> isize, p, buf, len)) }
}
unsafe extern "C" fn readlinkat(fd: c_int, path: C, buf: P, len: usize, _: usize, caller: usize) -> isize {
    // SAFETY: the caller's arguments for glibc's `readlinkat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Read, true, -1, |p| call!("readlinkat", -1, fn(c_int, C, P, usize) -> isize, fd, p, buf, len)) }
}

/// For an object, the canonical `/MS` path (`/MS/OPEN-R/../OPEN-R/MW` → `/MS/OPEN-R/MW`,
/// names as stored), never the host path behind it.
unsafe extern "C" fn realpath(path: C, resolved: *mut c_char, _: usize, _: usize, _: usize, caller: usize) -> *mut c_char {
    if !is_objects(caller) {
        return call!("realpath", null_mut(), fn(C, *mut c_char) -> *mut c_char, path, resolved);
    }
    // SAFETY: the caller's C string.
    let mapped = unsafe { map(caller, path, Access::Read) };
    let host = match mapped.ptr(path) {
        Ok(p) => p,
        Err(e) => return fail(e, null_mut()),
    };
    let real = call!("realpath", null_mut(), fn(C, *mut c_char) -> *mut c_char, host, null_mut());
    if real.is_null() {
        return null_mut(); // errno from realpath (ENOENT, ENOTDIR)
    }
    // SAFETY: realpath's malloc'd string, freed once read.
    let text = unsafe { std::ffi::CStr::from_ptr(real) }.to_string_lossy().into_owned();
    // SAFETY: `real` is realpath's malloc'd string, no longer used.
    unsafe { libc::free(real.cast()) };
    let Some(ms) = host_to_ms(&text) else { return fail(libc::EACCES, null_mut()) };
    let bytes = ms.as_bytes();
    if bytes.len() >= libc::PATH_MAX as usize {
        return fail(libc::ENAMETOOLONG, null_mut());
    }
    // SAFETY: `resolved` holds PATH_MAX bytes (realpath's contract), or we allocate.
    unsafe {
        let out = if resolved.is_null() { libc::malloc(bytes.len() + 1).cast::<c_char>() } else { resolved };
        if out.is_null() {
            return fail(libc::ENOMEM, null_mut());
        }
        std::ptr::copy_nonoverlapping(bytes.as_ptr().cast(), out, bytes.len());
        *out.add(bytes.len()) = 0;
        out
    }
}

// ---- directories ----

unsafe extern "C" fn opendir(path: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> P {
    // SAFETY: the caller's C string for glibc's `opendir`; `dir` is the stream it opened.
    unsafe {
        with(caller, path, Access::Read, null_mut(), |p| {
            let dir = call!("opendir", null_mut(), fn(C) -> P, p);
            if !dir.is_null() && p != path {
                super::dirs::opened(dir, path, p); // an object's listing of the overlay
            }
            dir
        })
    }
}
unsafe extern "C" fn readdir(dir: P, _: usize, _: usize, _: usize, _: usize, caller: usize) -> P {
    // SAFETY: the same contract: `dir` is the caller's open stream.
    unsafe { readdir64(dir, 0, 0, 0, 0, caller) }
}
unsafe extern "C" fn readdir64(dir: P, _: usize, _: usize, _: usize, _: usize, caller: usize) -> P {
    // dirent and dirent64 are one layout on LP64 Linux.
    let e = call!("readdir64", null_mut(), fn(P) -> P, dir);
    if !e.is_null() || !is_objects(caller) {
        return e;
    }
    let errno = std::io::Error::last_os_error().raw_os_error().unwrap_or(0);
    let extra = super::dirs::next_extra(dir);
    if extra.is_null() {
        set_errno(errno); // the end of the listing, or libc's error, as libc said
    }
    extra.cast()
}
unsafe extern "C" fn rewinddir(dir: P, _: usize, _: usize, _: usize, _: usize, _caller: usize) {
    super::dirs::rewound(dir);
    call!("rewinddir", (), fn(P) -> (), dir)
}
unsafe extern "C" fn closedir(dir: P, _: usize, _: usize, _: usize, _: usize, _caller: usize) -> c_int {
    super::dirs::closed(dir);
    call!("closedir", -1, fn(P) -> c_int, dir)
}
unsafe extern "C" fn scandir(path: C, list: P, filter: usize, compar: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `scandir`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("scandir", -1, fn(C, P, usize, usize) -> c_int, p, list, filter, compar)) }
}
unsafe extern "C" fn scandir64(path: C, list: P, filter: usize, compar: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `scandir64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("scandir64", -1, fn(C, P, usize, usize) -> c_int, p, list, filter, compar)) }
}
unsafe extern "C" fn scandirat(fd: c_int, path: C, list: P, filter: usize, compar: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `scandirat`, passed on with the path mapped.
    unsafe {
        with_at(caller, fd, path, Access::Read, false, -1, |p| call!("scandirat", -1, fn(c_int, C, P, usize, usize) -> c_int, fd, p, list, filter, compar))
    }
}
unsafe extern "C" fn mkdir(path: C, mode: c_uint, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `mkdir`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("mkdir", -1, fn(C, c_uint) -> c_int, p, mode)) }
}
unsafe extern "C" fn mkdirat(fd: c_int, path: C, mode: c_uint, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `mkdirat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Write, false, -1, |p| call!("mkdirat", -1, fn(c_int, C, c_uint) -> c_int, fd, p, mode)) }
}
unsafe extern "C" fn rmdir(path: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `rmdir`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Remove, -1, |p| call!("rmdir", -1, fn(C) -> c_int, p)) }
}
unsafe extern "C" fn ftw(path: C, f: usize, fds: c_int, _: usize, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("ftw", -1, fn(C, usize, c_int) -> c_int, path, f, fds))
}
unsafe extern "C" fn nftw(path: C, f: usize, fds: c_int, flags: c_int, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("nftw", -1, fn(C, usize, c_int, c_int) -> c_int, path, f, fds, flags))
}
unsafe extern "C" fn chdir(path: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // The working directory is the whole process's (the runtime's): objects have none.
    if !is_objects(caller) {
        return call!("chdir", -1, fn(C) -> c_int, path);
    }
    // SAFETY: the caller's C string, only mapped (to choose the errno), never used.
    unsafe { with(caller, path, Access::Read, -1, |_| fail(libc::EACCES, -1)) }
}
unsafe extern "C" fn fchdir(fd: c_int, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    if is_objects(caller) {
        return fail(libc::EACCES, -1);
    }
    call!("fchdir", -1, fn(c_int) -> c_int, fd)
}
unsafe extern "C" fn chroot(path: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    if is_objects(caller) {
        return fail(libc::EPERM, -1);
    }
    call!("chroot", -1, fn(C) -> c_int, path)
}

// ---- names ----

unsafe extern "C" fn unlink(path: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `unlink`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Remove, -1, |p| call!("unlink", -1, fn(C) -> c_int, p)) }
}
unsafe extern "C" fn unlinkat(fd: c_int, path: C, flags: c_int, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `unlinkat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Remove, false, -1, |p| call!("unlinkat", -1, fn(c_int, C, c_int) -> c_int, fd, p, flags)) }
}
unsafe extern "C" fn remove(path: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `remove`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Remove, -1, |p| call!("remove", -1, fn(C) -> c_int, p)) }
}
unsafe extern "C" fn rename(from: C, to: C, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `rename`, passed on mapped.
    unsafe { with2(caller, (from, Access::Remove), (to, Access::Write), -1, |a, b| call!("rename", -1, fn(C, C) -> c_int, a, b)) }
}
unsafe extern "C" fn renameat(fa: c_int, from: C, fb: c_int, to: C, _: usize, caller: usize) -> c_int {
    // SAFETY: the same contract as `renameat2` with no flags.
    unsafe { renameat2(fa, from, fb, to, 0, caller) }
}
unsafe extern "C" fn renameat2(fa: c_int, from: C, fb: c_int, to: C, flags: c_uint, caller: usize) -> c_int {
    // SAFETY: the caller's C strings and descriptors for glibc's `renameat`/`renameat2`.
    unsafe {
        with_at(caller, fa, from, Access::Remove, false, -1, |a| {
            with_at(caller, fb, to, Access::Write, false, -1, |b| match flags {
                0 => call!("renameat", -1, fn(c_int, C, c_int, C) -> c_int, fa, a, fb, b),
                _ => call!("renameat2", -1, fn(c_int, C, c_int, C, c_uint) -> c_int, fa, a, fb, b, flags),
            })
        })
    }
}
unsafe extern "C" fn link(from: C, to: C, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `link`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[from, to], -1, || call!("link", -1, fn(C, C) -> c_int, from, to)) }
}
unsafe extern "C" fn linkat(fa: c_int, from: C, fb: c_int, to: C, flags: c_int, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `linkat`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[from, to], -1, || call!("linkat", -1, fn(c_int, C, c_int, C, c_int) -> c_int, fa, from, fb, to, flags)) }
}
unsafe extern "C" fn symlink(target: C, path: C, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `symlink`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[path], -1, || call!("symlink", -1, fn(C, C) -> c_int, target, path)) }
}
unsafe extern "C" fn symlinkat(target: C, fd: c_int, path: C, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `symlinkat`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[path], -1, || call!("symlinkat", -1, fn(C, c_int, C) -> c_int, target, fd, path)) }
}
unsafe extern "C" fn mknod(path: C, mode: c_uint, dev: u64, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `mknod`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[path], -1, || call!("mknod", -1, fn(C, c_uint, u64) -> c_int, path, mode, dev)) }
}
unsafe extern "C" fn mknodat(fd: c_int, path: C, mode: c_uint, dev: u64, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `mknodat`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[path], -1, || call!("mknodat", -1, fn(c_int, C, c_uint, u64) -> c_int, fd, path, mode, dev)) }
}
unsafe extern "C" fn mkfifo(path: C, mode: c_uint, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `mkfifo`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[path], -1, || call!("mkfifo", -1, fn(C, c_uint) -> c_int, path, mode)) }
}
unsafe extern "C" fn mkfifoat(fd: c_int, path: C, mode: c_uint, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's C strings for glibc's `mkfifoat`, checked, then passed on or refused.
    unsafe { fat_has_none(caller, &[path], -1, || call!("mkfifoat", -1, fn(c_int, C, c_uint) -> c_int, fd, path, mode)) }
}

// ---- attributes ----

unsafe extern "C" fn truncate(path: C, len: i64, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `truncate`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("truncate", -1, fn(C, i64) -> c_int, p, len)) }
}
unsafe extern "C" fn truncate64(path: C, len: i64, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `truncate64`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("truncate64", -1, fn(C, i64) -> c_int, p, len)) }
}
unsafe extern "C" fn chmod(path: C, mode: c_uint, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `chmod`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("chmod", -1, fn(C, c_uint) -> c_int, p, mode)) }
}
unsafe extern "C" fn fchmodat(fd: c_int, path: C, mode: c_uint, flags: c_int, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `fchmodat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Write, false, -1, |p| call!("fchmodat", -1, fn(c_int, C, c_uint, c_int) -> c_int, fd, p, mode, flags)) }
}
unsafe extern "C" fn chown(path: C, uid: c_uint, gid: c_uint, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `chown`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("chown", -1, fn(C, c_uint, c_uint) -> c_int, p, uid, gid)) }
}
unsafe extern "C" fn lchown(path: C, uid: c_uint, gid: c_uint, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `lchown`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("lchown", -1, fn(C, c_uint, c_uint) -> c_int, p, uid, gid)) }
}
unsafe extern "C" fn fchownat(fd: c_int, path: C, uid: c_uint, gid: c_uint, flags: c_int, caller: usize) -> c_int {
    let empty = flags & libc::AT_EMPTY_PATH != 0;
    // SAFETY: the caller's arguments for glibc's `fchownat`, passed on with the path mapped.
    unsafe {
        with_at(caller, fd, path, Access::Write, empty, -1, |p| call!("fchownat", -1, fn(c_int, C, c_uint, c_uint, c_int) -> c_int, fd, p, uid, gid, flags))
    }
}
unsafe extern "C" fn utime(path: C, times: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `utime`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("utime", -1, fn(C, P) -> c_int, p, times)) }
}
unsafe extern "C" fn utimes(path: C, times: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `utimes`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("utimes", -1, fn(C, P) -> c_int, p, times)) }
}
unsafe extern "C" fn lutimes(path: C, times: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `lutimes`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("lutimes", -1, fn(C, P) -> c_int, p, times)) }
}
unsafe extern "C" fn futimesat(fd: c_int, path: C, times: P, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `futimesat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Write, false, -1, |p| call!("futimesat", -1, fn(c_int, C, P) -> c_int, fd, p, times)) }
}
unsafe extern "C" fn utimensat(fd: c_int, path: C, times: P, flags: c_int, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `utimensat`, passed on with the path mapped.
    unsafe { with_at(caller, fd, path, Access::Write, false, -1, |p| call!("utimensat", -1, fn(c_int, C, P, c_int) -> c_int, fd, p, times, flags)) }
}
unsafe extern "C" fn getxattr(path: C, name: C, v: P, n: usize, _: usize, caller: usize) -> isize {
    // SAFETY: the caller's arguments for glibc's `getxattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("getxattr", -1, fn(C, C, P, usize) -> isize, p, name, v, n)) }
}
unsafe extern "C" fn lgetxattr(path: C, name: C, v: P, n: usize, _: usize, caller: usize) -> isize {
    // SAFETY: the caller's arguments for glibc's `lgetxattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("lgetxattr", -1, fn(C, C, P, usize) -> isize, p, name, v, n)) }
}
unsafe extern "C" fn listxattr(path: C, list: P, n: usize, _: usize, _: usize, caller: usize) -> isize {
    // SAFETY: the caller's arguments for glibc's `listxattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("listxattr", -1, fn(C, P, usize) -> isize, p, list, n)) }
}
unsafe extern "C" fn llistxattr(path: C, list: P, n: usize, _: usize, _: usize, caller: usize) -> isize {
    // SAFETY: the caller's arguments for glibc's `llistxattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Read, -1, |p| call!("llistxattr", -1, fn(C, P, usize) -> isize, p, list, n)) }
}
unsafe extern "C" fn setxattr(path: C, name: C, v: P, n: usize, flags: c_int, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `setxattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("setxattr", -1, fn(C, C, P, usize, c_int) -> c_int, p, name, v, n, flags)) }
}
unsafe extern "C" fn lsetxattr(path: C, name: C, v: P, n: usize, flags: c_int, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `lsetxattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("lsetxattr", -1, fn(C, C, P, usize, c_int) -> c_int, p, name, v, n, flags)) }
}
unsafe extern "C" fn removexattr(path: C, name: C, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `removexattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("removexattr", -1, fn(C, C) -> c_int, p, name)) }
}
unsafe extern "C" fn lremovexattr(path: C, name: C, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    // SAFETY: the caller's arguments for glibc's `lremovexattr`, passed on with the path mapped.
    unsafe { with(caller, path, Access::Write, -1, |p| call!("lremovexattr", -1, fn(C, C) -> c_int, p, name)) }
}

// ---- files outside any directory (not functional on the robot) ----

unsafe extern "C" fn tmpfile(_: usize, _: usize, _: usize, _: usize, _: usize, caller: usize) -> P {
    not_on_robot(caller, null_mut(), || call!("tmpfile", null_mut(), fn() -> P,))
}
unsafe extern "C" fn tmpfile64(_: usize, _: usize, _: usize, _: usize, _: usize, caller: usize) -> P {
    not_on_robot(caller, null_mut(), || call!("tmpfile64", null_mut(), fn() -> P,))
}
unsafe extern "C" fn mkstemp(t: *mut c_char, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("mkstemp", -1, fn(*mut c_char) -> c_int, t))
}
unsafe extern "C" fn mkstemp64(t: *mut c_char, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("mkstemp64", -1, fn(*mut c_char) -> c_int, t))
}
unsafe extern "C" fn mkostemp(t: *mut c_char, flags: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("mkostemp", -1, fn(*mut c_char, c_int) -> c_int, t, flags))
}
unsafe extern "C" fn mkstemps(t: *mut c_char, n: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("mkstemps", -1, fn(*mut c_char, c_int) -> c_int, t, n))
}
unsafe extern "C" fn mkostemps(t: *mut c_char, n: c_int, flags: c_int, _: usize, _: usize, caller: usize) -> c_int {
    not_on_robot(caller, -1, || call!("mkostemps", -1, fn(*mut c_char, c_int, c_int) -> c_int, t, n, flags))
}
unsafe extern "C" fn mkdtemp(t: *mut c_char, _: usize, _: usize, _: usize, _: usize, caller: usize) -> *mut c_char {
    not_on_robot(caller, null_mut(), || call!("mkdtemp", null_mut(), fn(*mut c_char) -> *mut c_char, t))
}
