//! A crashing object (SIGSEGV, SIGBUS, SIGFPE, SIGILL, abort) gets a report naming the
//! object, the entry it was running and a symbolised backtrace; then the runtime exits
//! non-zero. The report is best effort — a crash inside malloc could deadlock it — so an
//! alarm ends the process if reporting itself hangs.
use std::ffi::{c_void, CStr};
use std::fmt::Write as _;

use crate::object::RUNNING;
use crate::runtime::Runtime;

const SIGNALS: [libc::c_int; 5] = [libc::SIGSEGV, libc::SIGBUS, libc::SIGFPE, libc::SIGILL, libc::SIGABRT];
const ALT_STACK: usize = 256 * 1024;

/// Installs the fault handlers for the whole process.
pub fn install() {
    unsafe {
        let mut sa: libc::sigaction = std::mem::zeroed();
        sa.sa_sigaction = on_fault as *const () as usize;
        sa.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK | libc::SA_RESETHAND;
        libc::sigemptyset(&mut sa.sa_mask);
        for s in SIGNALS {
            libc::sigaction(s, &sa, std::ptr::null_mut());
        }
    }
}

/// Gives the calling thread an alternate signal stack, so a stack overflow in an object
/// can still be reported. The stack is leaked: object threads live until exit.
pub fn alt_stack() {
    let mem = vec![0u8; ALT_STACK].leak();
    let st = libc::stack_t { ss_sp: mem.as_mut_ptr().cast(), ss_flags: 0, ss_size: ALT_STACK };
    unsafe { libc::sigaltstack(&st, std::ptr::null_mut()) };
}

fn signal_name(sig: libc::c_int) -> &'static str {
    match sig {
        libc::SIGSEGV => "SIGSEGV (invalid memory access)",
        libc::SIGBUS => "SIGBUS (misaligned or bad memory access)",
        libc::SIGFPE => "SIGFPE (arithmetic exception)",
        libc::SIGILL => "SIGILL (illegal instruction)",
        libc::SIGABRT => "SIGABRT (abort)",
        _ => "signal",
    }
}

/// Name of the symbol containing `addr`, from the dynamic symbol tables (what is left
/// after `strip`).
fn dl_name(addr: *mut c_void) -> Option<(String, String)> {
    let mut info: libc::Dl_info = unsafe { std::mem::zeroed() };
    if unsafe { libc::dladdr(addr, &mut info) } == 0 {
        return None;
    }
    let s = |p: *const libc::c_char| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() };
    Some((s(info.dli_sname), s(info.dli_fname)))
}

extern "C" fn on_fault(sig: libc::c_int, info: *mut libc::siginfo_t, _ctx: *mut c_void) {
    unsafe { libc::alarm(10) };
    let (index, selector) = RUNNING.with(|r| r.get());
    let mut report = String::new();
    let slot = Runtime::get().and_then(|rt| rt.all_objects().get(index).cloned());
    match &slot {
        Some(slot) => {
            let entry = slot
                .module
                .get()
                .and_then(|m| m.entry(selector))
                .and_then(|f| dl_name(f as *mut c_void))
                .map(|(n, _)| n)
                .filter(|n| !n.is_empty());
            let what = match (selector, entry) {
                (u32::MAX, _) => "outside any entry (loading or static constructors)".to_string(),
                (s, Some(n)) => format!("entry {n} (selector {s})"),
                (s, None) => format!("selector {s}"),
            };
            let _ = writeln!(report, "error: object `{}` ({}) crashed with {} in {what}", slot.name(), slot.bin, signal_name(sig));
        }
        None => {
            let _ = writeln!(report, "error: the cargo-openr runtime crashed with {} (not inside an object)", signal_name(sig));
        }
    }
    if matches!(sig, libc::SIGSEGV | libc::SIGBUS) && !info.is_null() {
        let _ = writeln!(report, "  fault address: {:p}", unsafe { (*info).si_addr() });
    }
    let _ = writeln!(report, "backtrace:");
    let mut n = 0;
    backtrace::trace(|frame| {
        let ip = frame.ip();
        let mut line = format!("  {n:2}: {ip:p}");
        let mut named = false;
        backtrace::resolve_frame(frame, |sym| {
            if named {
                return;
            }
            if let Some(name) = sym.name() {
                let _ = write!(line, " {name:#}");
                named = true;
            }
            if let (Some(f), Some(l)) = (sym.filename(), sym.lineno()) {
                let _ = write!(line, " at {}:{l}", f.display());
            }
        });
        if !named {
            if let Some((name, file)) = dl_name(ip) {
                let _ = write!(line, " {} ({})", if name.is_empty() { "??" } else { &name }, file);
            }
        }
        report.push_str(&line);
        report.push('\n');
        n += 1;
        n < 64
    });
    unsafe {
        libc::fflush(std::ptr::null_mut());
        libc::write(2, report.as_ptr().cast(), report.len());
        libc::_exit(128 + sig);
    }
}
