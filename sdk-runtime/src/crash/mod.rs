//! A crashing object (SIGSEGV, SIGBUS, SIGFPE, SIGILL, abort) gets a report naming the
//! object, the entry it was running, what the robot's CPU would have done and a
//! backtrace; then the runtime exits with 128 + the signal number.
//!
//! The handler cannot fail: it allocates nothing (a crash inside malloc — a double free
//! — must not deadlock it), writes the header line before anything else, runs on a
//! per-thread alternate stack (a stack overflow is reported too) and an alarm ends the
//! process should the backtrace hang anyway. Object threads also trap on floating-point
//! errors like the robot's R4000 under Aperios (`fp_traps`).
use std::cell::Cell;
use std::ffi::c_void;
use std::fmt::Write as _;
use std::sync::atomic::{AtomicBool, Ordering};

use crate::object::{ObjectSlot, CURRENT_SLOT, RUNNING};
use openr_sys::Selector;

mod exits;
mod frames;
mod out;

pub use exits::{exit_now, fault_note_from};
use out::{fault_kind, signal_name, CText, Out, BUFFER};

const SIGNALS: [libc::c_int; 5] = [libc::SIGSEGV, libc::SIGBUS, libc::SIGFPE, libc::SIGILL, libc::SIGABRT];
const ALT_STACK: usize = 256 * 1024;
/// `RUNNING` selector of a thread an object started itself (pthread_create).
pub const OWN_THREAD: Selector = Selector(u32::MAX - 1);

static FP_TRAPS: AtomicBool = AtomicBool::new(true);
/// `OPENR_CORE_DUMP=1`: after the report, die of the signal itself so the kernel writes a
/// core file (the core size limit is raised for the run).
static CORE_DUMP: AtomicBool = AtomicBool::new(false);
static FIRST_SIGNAL: std::sync::atomic::AtomicI32 = std::sync::atomic::AtomicI32::new(0);

thread_local! {
    /// This thread's stack (low, high), to tell a stack overflow from other faults.
    static STACK: Cell<(usize, usize)> = const { Cell::new((0, 0)) };
    static IN_HANDLER: Cell<bool> = const { Cell::new(false) };
}

/// Whether object threads trap on FP errors (`--no-fp-traps` turns it off). Set before
/// the objects load.
pub fn set_fp_traps(on: bool) {
    FP_TRAPS.store(on, Ordering::Release);
}

/// Installs the fault handlers for the whole process.
pub fn install() {
    if std::env::var_os("OPENR_CORE_DUMP").is_some_and(|v| v == "1") {
        CORE_DUMP.store(true, Ordering::Release);
        let unlimited = libc::rlimit { rlim_cur: libc::RLIM_INFINITY, rlim_max: libc::RLIM_INFINITY };
        // SAFETY: plain syscalls on this process; a hard limit below infinity is kept.
        unsafe {
            if libc::setrlimit(libc::RLIMIT_CORE, &unlimited) != 0 {
                let mut cur = std::mem::zeroed::<libc::rlimit>();
                libc::getrlimit(libc::RLIMIT_CORE, &mut cur);
                cur.rlim_cur = cur.rlim_max;
                libc::setrlimit(libc::RLIMIT_CORE, &cur);
            }
        }
    }
    frames::warm_up();
    exits::remember_pid();
    std::hint::black_box(exits::keep());
    // SAFETY: sigaction is plain C data (all-zero: no flags, empty mask); `on_fault` has the
    // SA_SIGINFO handler signature, and only writes what allocates nothing.
    unsafe {
        let mut sa: libc::sigaction = std::mem::zeroed();
        sa.sa_sigaction = on_fault as *const () as usize;
        // SA_NODEFER: a fault while reporting (unwinding a smashed stack) re-enters the
        // handler, which then ends the process, instead of the kernel killing it.
        sa.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK | libc::SA_NODEFER;
        libc::sigemptyset(&mut sa.sa_mask);
        for s in SIGNALS {
            libc::sigaction(s, &sa, std::ptr::null_mut());
        }
    }
}

/// Prepares the calling thread to run object code: an alternate signal stack (leaked:
/// object threads live until exit), its stack bounds, and the robot's FP traps.
pub fn arm_thread() {
    let mem = vec![0u8; ALT_STACK].leak();
    let st = libc::stack_t { ss_sp: mem.as_mut_ptr().cast(), ss_flags: 0, ss_size: ALT_STACK };
    // SAFETY: `st` describes a leaked (never freed) buffer of ALT_STACK bytes.
    unsafe { libc::sigaltstack(&st, std::ptr::null_mut()) };
    STACK.with(|s| s.set(stack_bounds()));
    if FP_TRAPS.load(Ordering::Acquire) {
        enable_fp_traps();
    }
}

fn stack_bounds() -> (usize, usize) {
    // SAFETY: pthread_attr_t is filled by pthread_getattr_np before it is read, and destroyed once;
    // the out-pointers are live locals.
    unsafe {
        let mut attr: libc::pthread_attr_t = std::mem::zeroed();
        if libc::pthread_getattr_np(libc::pthread_self(), &mut attr) != 0 {
            return (0, 0);
        }
        let (mut base, mut size) = (std::ptr::null_mut(), 0);
        libc::pthread_attr_getstack(&attr, &mut base, &mut size);
        libc::pthread_attr_destroy(&mut attr);
        (base as usize, base as usize + size)
    }
}

extern "C" {
    fn feenableexcept(excepts: libc::c_int) -> libc::c_int;
}

/// The R4000 faults the object on an invalid operation (0/0, sqrt(-1), NaN compares,
/// float→int out of range: SSE's cvttsd2si raises invalid there), division by zero,
/// overflow and a denormal operand (x86's DM, masked by feenableexcept's interface, is
/// unmasked in MXCSR directly).
fn enable_fp_traps() {
    const FE_INVALID: libc::c_int = 0x01;
    const FE_DIVBYZERO: libc::c_int = 0x04;
    const FE_OVERFLOW: libc::c_int = 0x08;
    const MXCSR_DM: u32 = 1 << 8;
    // SAFETY: FP exception masks only change how this thread's FP faults; stmxcsr/ldmxcsr
    // read/write the 4-byte `csr` local and no stack.
    unsafe {
        feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
        let mut csr: u32 = 0;
        std::arch::asm!("stmxcsr [{}]", in(reg) &mut csr, options(nostack));
        csr &= !MXCSR_DM;
        std::arch::asm!("ldmxcsr [{}]", in(reg) &csr, options(nostack));
    }
}

/// The object whose code this thread runs, if any (no allocation, no lock).
fn current_slot() -> Option<&'static ObjectSlot> {
    let p = CURRENT_SLOT.with(|c| c.get());
    // SAFETY: slots live until the process exits (the runtime holds them).
    (!p.is_null()).then(|| unsafe { &*p })
}

extern "C" fn on_fault(sig: libc::c_int, info: *mut libc::siginfo_t, ctx: *mut c_void) {
    if IN_HANDLER.with(|h| h.replace(true)) {
        out::write_all(2, b"  (the backtrace ends here: walking the stack faulted)\n");
        exits::flush_console();
        exit_now(128 + FIRST_SIGNAL.load(Ordering::Acquire));
    }
    FIRST_SIGNAL.store(sig, Ordering::Release);
    let Some(mut out) = BUFFER.claim() else {
        // Another thread is reporting; it ends the process.
        loop {
            // SAFETY: pause has no preconditions.
            unsafe { libc::pause() };
        }
    };
    // SAFETY: alarm has no preconditions.
    unsafe { libc::alarm(10) };
    let uc = ctx as *const libc::ucontext_t;
    // SAFETY: `uc` is non-null: the kernel's ucontext for this SA_SIGINFO handler.
    let pc = if uc.is_null() { 0 } else { unsafe { (*uc).uc_mcontext.gregs[libc::REG_RIP as usize] as usize } };
    // SAFETY: `uc` and its `fpregs` are null or the kernel's valid signal context.
    let mxcsr = unsafe { uc.as_ref().and_then(|u| u.uc_mcontext.fpregs.as_ref()).map(|f| f.mxcsr) };
    // SAFETY: `info` is non-null: the kernel's siginfo for this handler.
    let (code, addr) = if info.is_null() { (0, 0) } else { unsafe { ((*info).si_code, (*info).si_addr() as usize) } };
    // SAFETY: `info` is this handler's siginfo (or null), `fault_note_from`'s contract.
    let note = unsafe { fault_note_from(sig, info) };
    let stack = STACK.with(|s| s.get());
    let overflow = sig == libc::SIGSEGV && stack.0 != 0 && addr < stack.0 + 4096 && addr + (1 << 20) > stack.0;
    let kind = match () {
        _ if overflow => "stack overflow (endless recursion or a huge local array)",
        _ if note.is_some() && sig == libc::SIGILL => "unreachable code reached",
        _ if note.is_some() => "misaligned access",
        _ => fault_kind(sig, code, mxcsr),
    };
    header(&mut out, sig, kind);
    out.flush();
    if let Some(n) = note {
        let _ = writeln!(out, "  {}", CText(n));
    }
    if matches!(sig, libc::SIGSEGV | libc::SIGBUS) && note.is_none() {
        let _ = writeln!(out, "  fault address: {addr:#x}");
    }
    if code == libc::SI_TKILL || code == libc::SI_USER {
        let _ = writeln!(out, "  (raised by the program: kill/raise/abort)");
    }
    let _ = writeln!(out, "backtrace:");
    out.flush();
    let (ips, n) = frames::collect(pc);
    for (i, ip) in ips[..n].iter().enumerate() {
        frames::write_frame(&mut out, i, *ip, true);
        out.flush();
    }
    exits::flush_console();
    if CORE_DUMP.load(Ordering::Acquire) {
        dump_core(sig);
    }
    exit_now(128 + sig);
}

/// Dies of `sig` with its default action (a core file); returns only if that failed.
fn dump_core(sig: i32) {
    // SAFETY: async-signal-safe calls; SIG_DFL for the signal, then it is raised again
    // (unblocked: SA_NODEFER left it deliverable).
    unsafe {
        let mut sa: libc::sigaction = std::mem::zeroed();
        sa.sa_sigaction = libc::SIG_DFL;
        libc::sigemptyset(&mut sa.sa_mask);
        libc::sigaction(sig, &sa, std::ptr::null_mut());
        libc::raise(sig);
    }
}

/// `error: object `X` (BIN) crashed with SIGFPE: <kind> in entry E (selector S)`.
fn header(out: &mut Out, sig: i32, kind: &str) {
    let (_, selector) = RUNNING.with(|r| r.get());
    let Some(slot) = current_slot() else {
        let _ = writeln!(out, "error: the cargo-openr runtime crashed with {}: {kind} (not inside an object)", signal_name(sig));
        return;
    };
    let _ = write!(out, "error: object `{}` ({}) crashed with {}: {kind} ", slot.name(), slot.bin, signal_name(sig));
    let entry = slot.module.get().and_then(|m| m.entry(selector)).and_then(|f| frames::place(f as usize));
    let _ = match (selector, entry) {
        (Selector::UNDEF, _) => writeln!(out, "outside any entry (loading or static constructors)"),
        (OWN_THREAD, _) => writeln!(out, "in a thread the object started (pthread_create)"),
        (s, Some(p)) if !p.info.dli_sname.is_null() => writeln!(out, "in entry {} (selector {s})", CText(p.info.dli_sname)),
        (s, _) => writeln!(out, "in selector {s}"),
    };
}
