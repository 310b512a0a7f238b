//! Processes, signals to other processes and the dynamic loader, as objects reach them.
//! The robot's C library had none of these (object-model 1.5: `fork execve kill … system`
//! are not functional), so an object's call fails as it would there — ENOSYS, `system`
//! and `popen` included, `posix_spawn` returning the error — and `dlopen` fails with a
//! `dlerror` text that says why. The first call of each is also a warning on stderr:
//! code that shells out or loads a library will not work on the robot either.
//!
//! The runtime's own calls (the crash reporter's `posix_spawn` of addr2line, the
//! loader's `dlopen`) pass untouched, as in `fs`. Out of reach of an interposer: raw
//! `syscall` instructions and lookups past the executable with `dlsym(RTLD_NEXT)`,
//! which recompiled robot code does not contain.
#![allow(clippy::too_many_arguments)]
#![allow(unused_unsafe)]

use std::cell::Cell;
use std::ffi::{c_char, c_int, c_long, c_void};
use std::ptr::null_mut;
use std::sync::Mutex;

use super::is_objects;
use super::real::fail;
use super::trampoline::{seven, trampolines};
use crate::runtime::Runtime;

type C = *const c_char;
type P = *mut c_void;

trampolines! {
    "fork" => fork, "_Fork" => fork_, "vfork" => vfork, "daemon" => daemon,
    "execve" => execve, "execv" => execv, "execvp" => execvp, "execvpe" => execvpe,
    "fexecve" => fexecve, "execveat" => execveat,
    "execl" => execl, "execlp" => execlp, "execle" => execle,
    "system" => system, "popen" => popen,
    "kill" => kill, "killpg" => killpg, "ptrace" => ptrace,
    "dlopen" => dlopen, "dlmopen" => dlmopen, "dlerror" => dlerror,
}

seven! {
    "posix_spawn" => posix_spawn, "posix_spawnp" => posix_spawnp,
}

/// Resolves libc's `dlerror` and `dlopen` before anything needs them: looking one up
/// later, between a failed `dlopen` and its `dlerror`, would clear the error text.
pub fn keep() -> usize {
    let _ = (libc_dlerror(), libc_dlopen());
    fork as *const () as usize
}

/// One lookup site each, so that `keep` resolves the very pointer the calls use.
fn libc_dlerror() -> Option<unsafe extern "C" fn() -> C> {
    real!("dlerror", unsafe extern "C" fn() -> C)
}
fn libc_dlopen() -> Option<unsafe extern "C" fn(C, c_int) -> P> {
    real!("dlopen", unsafe extern "C" fn(C, c_int) -> P)
}

/// For an object: warns once per function and fails with `errno`; else `call()`.
fn refuse<R>(name: &'static str, caller: usize, errno: i32, failed: R, call: impl FnOnce() -> R) -> R {
    if !is_objects(caller) {
        return call();
    }
    warn_once(name);
    fail(errno, failed)
}

fn warn_once(name: &'static str) {
    static TOLD: Mutex<Vec<&'static str>> = Mutex::new(Vec::new());
    let first = TOLD.lock().is_ok_and(|mut told| {
        let first = !told.contains(&name);
        if first {
            told.push(name);
        }
        first
    });
    if let (true, Some(rt)) = (first, Runtime::get()) {
        let who = crate::object::current().map_or("a thread of an object".to_string(), |o| format!("object `{}`", o.name()));
        rt.diag.warn(&format!("{who} called {name}(), which the robot does not have (object-model 1.5): refused"));
    }
}

// ---- processes ----

unsafe extern "C" fn fork(_: usize, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("fork", caller, libc::ENOSYS, -1, || call!("fork", -1, fn() -> c_int,))
}
unsafe extern "C" fn fork_(_: usize, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("_Fork", caller, libc::ENOSYS, -1, || call!("_Fork", -1, fn() -> c_int,))
}
/// vfork's child must not return from the function that called it, which a wrapper
/// would; the runtime never uses it, so its call is a fork.
unsafe extern "C" fn vfork(_: usize, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("vfork", caller, libc::ENOSYS, -1, || call!("fork", -1, fn() -> c_int,))
}
unsafe extern "C" fn daemon(nochdir: c_int, noclose: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("daemon", caller, libc::ENOSYS, -1, || call!("daemon", -1, fn(c_int, c_int) -> c_int, nochdir, noclose))
}

unsafe extern "C" fn execve(path: C, argv: P, envp: P, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execve", caller, libc::ENOSYS, -1, || call!("execve", -1, fn(C, P, P) -> c_int, path, argv, envp))
}
unsafe extern "C" fn execv(path: C, argv: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execv", caller, libc::ENOSYS, -1, || call!("execv", -1, fn(C, P) -> c_int, path, argv))
}
unsafe extern "C" fn execvp(file: C, argv: P, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execvp", caller, libc::ENOSYS, -1, || call!("execvp", -1, fn(C, P) -> c_int, file, argv))
}
unsafe extern "C" fn execvpe(file: C, argv: P, envp: P, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execvpe", caller, libc::ENOSYS, -1, || call!("execvpe", -1, fn(C, P, P) -> c_int, file, argv, envp))
}
unsafe extern "C" fn fexecve(fd: c_int, argv: P, envp: P, _: usize, _: usize, caller: usize) -> c_int {
    refuse("fexecve", caller, libc::ENOSYS, -1, || call!("fexecve", -1, fn(c_int, P, P) -> c_int, fd, argv, envp))
}
unsafe extern "C" fn execveat(fd: c_int, path: C, argv: P, envp: P, flags: c_int, caller: usize) -> c_int {
    refuse("execveat", caller, libc::ENOSYS, -1, || call!("execveat", -1, fn(c_int, C, P, P, c_int) -> c_int, fd, path, argv, envp, flags))
}
/// The list forms take their arguments variadically, which a wrapper cannot hand on;
/// the runtime never calls them, so they fail for every caller.
unsafe extern "C" fn execl(_: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execl", caller, libc::ENOSYS, -1, || fail(libc::ENOSYS, -1))
}
unsafe extern "C" fn execlp(_: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execlp", caller, libc::ENOSYS, -1, || fail(libc::ENOSYS, -1))
}
unsafe extern "C" fn execle(_: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("execle", caller, libc::ENOSYS, -1, || fail(libc::ENOSYS, -1))
}

unsafe extern "C" fn posix_spawn(pid: P, path: C, actions: P, attr: P, argv: P, envp: P, caller: usize) -> c_int {
    // posix_spawn reports its error as the result, not in errno.
    refuse("posix_spawn", caller, libc::ENOSYS, libc::ENOSYS, || {
        call!("posix_spawn", libc::ENOSYS, fn(P, C, P, P, P, P) -> c_int, pid, path, actions, attr, argv, envp)
    })
}
unsafe extern "C" fn posix_spawnp(pid: P, file: C, actions: P, attr: P, argv: P, envp: P, caller: usize) -> c_int {
    refuse("posix_spawnp", caller, libc::ENOSYS, libc::ENOSYS, || {
        call!("posix_spawnp", libc::ENOSYS, fn(P, C, P, P, P, P) -> c_int, pid, file, actions, attr, argv, envp)
    })
}

/// `system(NULL)` asks whether there is a shell: there is none (0). A command fails as
/// a shell that cannot be started does (-1).
unsafe extern "C" fn system(command: C, _: usize, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    if command.is_null() && is_objects(caller) {
        return 0;
    }
    refuse("system", caller, libc::ENOSYS, -1, || call!("system", -1, fn(C) -> c_int, command))
}
unsafe extern "C" fn popen(command: C, mode: C, _: usize, _: usize, _: usize, caller: usize) -> P {
    refuse("popen", caller, libc::ENOSYS, null_mut(), || call!("popen", null_mut(), fn(C, C) -> P, command, mode))
}

// ---- other processes ----

unsafe extern "C" fn kill(pid: c_int, sig: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("kill", caller, libc::ENOSYS, -1, || call!("kill", -1, fn(c_int, c_int) -> c_int, pid, sig))
}
unsafe extern "C" fn killpg(pgrp: c_int, sig: c_int, _: usize, _: usize, _: usize, caller: usize) -> c_int {
    refuse("killpg", caller, libc::ENOSYS, -1, || call!("killpg", -1, fn(c_int, c_int) -> c_int, pgrp, sig))
}
unsafe extern "C" fn ptrace(request: c_int, pid: c_int, addr: P, data: P, _: usize, caller: usize) -> c_long {
    refuse("ptrace", caller, libc::ENOSYS, -1, || call!("ptrace", -1, fn(c_int, c_int, P, P) -> c_long, request, pid, addr, data))
}

// ---- the dynamic loader ----

thread_local! {
    /// A refused `dlopen` on this thread whose text `dlerror` has not given yet.
    static REFUSED: Cell<bool> = const { Cell::new(false) };
}

const NO_LOADER: &std::ffi::CStr = c"dlopen: OPEN-R objects cannot load libraries (the robot has no dynamic loader; link the code into the object)";

/// `refuse` for the loader: a refusal also leaves its text for `dlerror`.
fn refuse_load(name: &'static str, caller: usize, call: impl FnOnce() -> P) -> P {
    if is_objects(caller) {
        REFUSED.with(|r| r.set(true));
    }
    refuse(name, caller, libc::ENOSYS, null_mut(), call)
}

unsafe extern "C" fn dlopen(file: C, flags: c_int, _: usize, _: usize, _: usize, caller: usize) -> P {
    refuse_load("dlopen", caller, || match libc_dlopen() {
        // SAFETY: the caller's arguments for glibc's `dlopen`.
        Some(f) => unsafe { f(file, flags) },
        None => fail(libc::ENOSYS, null_mut()),
    })
}
unsafe extern "C" fn dlmopen(ns: c_long, file: C, flags: c_int, _: usize, _: usize, caller: usize) -> P {
    refuse_load("dlmopen", caller, || call!("dlmopen", null_mut(), fn(c_long, C, c_int) -> P, ns, file, flags))
}
/// After a refused `dlopen`, its text once (as dlerror gives each error once); else libc's.
unsafe extern "C" fn dlerror(_: usize, _: usize, _: usize, _: usize, _: usize, caller: usize) -> *const c_char {
    if is_objects(caller) && REFUSED.with(|r| r.replace(false)) {
        return NO_LOADER.as_ptr();
    }
    // SAFETY: glibc's `dlerror` takes no arguments.
    libc_dlerror().map_or(std::ptr::null(), |f| unsafe { f() })
}
