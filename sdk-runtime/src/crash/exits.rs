//! How an object can end the process without a signal, and threads it starts itself.
//! The runtime executable exports these (see cargo-openr's build.rs), so the objects'
//! calls bind here first:
//! * `_exit` / `_Exit`: on the robot an object cannot end the system. Here it ends the
//!   run, but never silently: the object is named, the console's pending output is
//!   flushed, and the exit status is non-zero (the object's, or 1 for `_exit(0)`).
//! * `pthread_create`: a thread started by object code runs as that object (its faults
//!   are reported with the object's name, it gets an alternate stack and FP traps).
use std::ffi::c_void;
use std::fmt::Write as _;
use std::sync::OnceLock;

use super::out::BUFFER;

/// The runtime's pid: a forked child calling `_exit` is not an object.
static PID: OnceLock<libc::pid_t> = OnceLock::new();

pub(super) fn remember_pid() {
    // SAFETY: getpid has no preconditions.
    PID.get_or_init(|| unsafe { libc::getpid() });
}

fn in_runtime_process() -> bool {
    // SAFETY: getpid has no preconditions.
    PID.get().is_some_and(|p| *p == unsafe { libc::getpid() })
}

/// Ends the process now (no atexit handlers, no C++ destructors of running objects).
pub fn exit_now(code: i32) -> ! {
    // SAFETY: exit_group has no memory preconditions; it does not return.
    unsafe { libc::syscall(libc::SYS_exit_group, code as libc::c_long) };
    unreachable!("exit_group returned")
}

extern "C" {
    fn ftrylockfile(f: *mut libc::FILE) -> libc::c_int;
    fn funlockfile(f: *mut libc::FILE);
    fn fflush_unlocked(f: *mut libc::FILE) -> libc::c_int;
}

/// Writes out what objects' printf/cout left in stdout's buffer, unless another thread
/// holds stdout's lock for longer than a moment (then that output is lost, not the run).
pub fn flush_console() {
    let stdout = crate::console::stdout_file();
    for _ in 0..100 {
        // SAFETY: `stdout` is libc's own `stdout` FILE, valid for the whole process.
        if unsafe { ftrylockfile(stdout) } == 0 {
            // SAFETY: this thread holds `stdout`'s lock (ftrylockfile returned 0), which funlockfile releases.
            unsafe {
                fflush_unlocked(stdout);
                funlockfile(stdout);
            }
            return;
        }
        // SAFETY: usleep has no memory preconditions.
        unsafe { libc::usleep(1000) };
    }
}

/// The note libmcoopstub's check handlers sent with their signal (`sigqueue`: `si_value`
/// points at the text): SIGBUS from the alignment check, SIGILL from a reached
/// `__builtin_unreachable()`.
///
/// # Safety
/// `info` is the handler's siginfo.
pub unsafe fn fault_note_from(sig: i32, info: *const libc::siginfo_t) -> Option<*const libc::c_char> {
    // SAFETY: `info` is non-null and is the handler's siginfo (this function's contract).
    if !matches!(sig, libc::SIGBUS | libc::SIGILL) || info.is_null() || unsafe { (*info).si_code } != libc::SI_QUEUE {
        return None;
    }
    // SAFETY: `info` is the handler's siginfo (checked non-null above); getpid has no preconditions.
    if unsafe { (*info).si_pid() } != unsafe { libc::getpid() } {
        return None;
    }
    // SAFETY: a SI_QUEUE siginfo carries `si_value` (the sender's `sigqueue` argument).
    let p = unsafe { (*info).si_value().sival_ptr } as *const libc::c_char;
    (!p.is_null()).then_some(p)
}

fn object_exit(status: i32) -> ! {
    if in_runtime_process() {
        if let Some(slot) = super::current_slot() {
            flush_console();
            if let Some(mut out) = BUFFER.claim() {
                let _ = writeln!(
                    out,
                    "error: object `{}` ({}) called _exit({status}): the robot has no process to end; the run stops here",
                    slot.name(),
                    slot.bin,
                );
                out.flush();
            }
            exit_now(if status != 0 { status } else { 1 });
        }
    }
    exit_now(status)
}

#[no_mangle]
pub extern "C" fn _exit(status: libc::c_int) -> ! {
    object_exit(status)
}

#[no_mangle]
pub extern "C" fn _Exit(status: libc::c_int) -> ! {
    object_exit(status)
}

type StartFn = extern "C" fn(*mut c_void) -> *mut c_void;
type CreateFn = unsafe extern "C" fn(*mut libc::pthread_t, *const libc::pthread_attr_t, StartFn, *mut c_void) -> libc::c_int;

fn real_pthread_create() -> CreateFn {
    static REAL: OnceLock<usize> = OnceLock::new();
    // SAFETY: a NUL-terminated name.
    let p = *REAL.get_or_init(|| unsafe { libc::dlsym(libc::RTLD_NEXT, c"pthread_create".as_ptr()) } as usize);
    assert!(p != 0, "libc's pthread_create not found");
    // SAFETY: libc's pthread_create has this signature.
    unsafe { std::mem::transmute::<usize, CreateFn>(p) }
}

struct Adopted {
    rt: Option<&'static crate::runtime::Runtime>,
    slot: std::sync::Arc<crate::object::ObjectSlot>,
    start: StartFn,
    arg: *mut c_void,
}

extern "C" fn adopted_start(p: *mut c_void) -> *mut c_void {
    // SAFETY: boxed by pthread_create below, for this thread only.
    let a = unsafe { Box::from_raw(p as *mut Adopted) };
    let index = a.slot.index;
    if let Some(rt) = a.rt {
        rt.enter();
    }
    crate::object::set_current(a.slot);
    crate::object::RUNNING.with(|r| r.set((index, super::OWN_THREAD)));
    super::arm_thread();
    (a.start)(a.arg)
}

/// # Safety
/// Same contract as libc's `pthread_create`.
#[no_mangle]
pub unsafe extern "C" fn pthread_create(thread: *mut libc::pthread_t, attr: *const libc::pthread_attr_t, start: StartFn, arg: *mut c_void) -> libc::c_int {
    let real = real_pthread_create();
    // Threads the runtime starts (Rust std's start routine lives in this executable)
    // stay the runtime's, even when started from an object's thread.
    let from_object = crate::object::current().filter(|_| super::frames::place(start as usize).is_some_and(|p| !p.is_main_program()));
    match from_object {
        Some(slot) => {
            let boxed = Box::into_raw(Box::new(Adopted { rt: crate::runtime::Runtime::get(), slot, start, arg }));
            // SAFETY: the caller's arguments (pthread_create's contract); `boxed` is a live Box that
            // `adopted_start` takes ownership of on the new thread.
            let r = unsafe { real(thread, attr, adopted_start, boxed.cast()) };
            if r != 0 {
                // SAFETY: the thread was not created, so `boxed` was never taken: it is freed once, here.
                drop(unsafe { Box::from_raw(boxed) });
            }
            r
        }
        // SAFETY: the caller's arguments, passed on unchanged (pthread_create's contract).
        None => unsafe { real(thread, attr, start, arg) },
    }
}

/// Keeps the interposers in the final link (referenced from the boot code).
pub fn keep() -> usize {
    _exit as *const () as usize ^ _Exit as *const () as usize ^ pthread_create as *const () as usize
}
