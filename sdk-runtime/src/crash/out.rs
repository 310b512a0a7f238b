//! Text of a crash report, built without allocating: a fixed buffer that `core::fmt`
//! writes into (truncating when full) and hands to `write(2)` in pieces.
use std::cell::UnsafeCell;
use std::sync::atomic::{AtomicBool, Ordering};

const SIZE: usize = 16 * 1024;

/// The one report buffer of the process: only the thread that won `claim` touches it.
pub struct ReportBuffer {
    claimed: AtomicBool,
    bytes: UnsafeCell<[u8; SIZE]>,
}

// SAFETY: access is serialised by `claimed` (one reporting thread, which never returns).
unsafe impl Sync for ReportBuffer {}

pub static BUFFER: ReportBuffer = ReportBuffer { claimed: AtomicBool::new(false), bytes: UnsafeCell::new([0; SIZE]) };

impl ReportBuffer {
    /// The buffer, for the first caller only (the process ends after its report).
    pub fn claim(&'static self) -> Option<Out> {
        if self.claimed.swap(true, Ordering::AcqRel) {
            return None;
        }
        // SAFETY: claimed exactly once.
        Some(Out { buf: unsafe { &mut *self.bytes.get() }, len: 0 })
    }
}

pub struct Out {
    buf: &'static mut [u8; SIZE],
    len: usize,
}

impl Out {
    /// Writes what was formatted so far to fd 2 and empties the buffer.
    pub fn flush(&mut self) {
        write_all(2, &self.buf[..self.len]);
        self.len = 0;
    }
}

impl core::fmt::Write for Out {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        let n = s.len().min(SIZE - self.len);
        self.buf[self.len..self.len + n].copy_from_slice(&s.as_bytes()[..n]);
        self.len += n;
        Ok(())
    }
}

/// `write(2)` until done (async-signal-safe).
pub fn write_all(fd: i32, mut bytes: &[u8]) {
    while !bytes.is_empty() {
        // SAFETY: `bytes` is a live slice: write reads at most its length.
        let n = unsafe { libc::write(fd, bytes.as_ptr().cast(), bytes.len()) };
        if n <= 0 {
            // SAFETY: __errno_location returns this thread's errno, always valid.
            if n < 0 && unsafe { *libc::__errno_location() } == libc::EINTR {
                continue;
            }
            return;
        }
        bytes = &bytes[n as usize..];
    }
}

/// A NUL-terminated C string as text (lossy: invalid UTF-8 becomes `?`), no allocation.
pub struct CText(pub *const libc::c_char);

impl core::fmt::Display for CText {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.0.is_null() {
            return f.write_str("??");
        }
        // SAFETY: `self.0` is non-null: a NUL-terminated C string (`CText`'s contract).
        let bytes = unsafe { std::ffi::CStr::from_ptr(self.0) }.to_bytes();
        for chunk in bytes.utf8_chunks() {
            f.write_str(chunk.valid())?;
            if !chunk.invalid().is_empty() {
                f.write_str("?")?;
            }
        }
        Ok(())
    }
}

// si_code values (Linux <asm-generic/siginfo.h>; not all are in the libc crate).
const FPE_INTDIV: i32 = 1;
const FPE_INTOVF: i32 = 2;
const FPE_FLTDIV: i32 = 3;
const FPE_FLTOVF: i32 = 4;
const FPE_FLTUND: i32 = 5;
const FPE_FLTRES: i32 = 6;
const FPE_FLTINV: i32 = 7;
const SEGV_ACCERR: i32 = 2;
const BUS_ADRALN: i32 = 1;

/// What the fault was, in the robot's terms (its CPU faults the object for each).
pub fn fault_kind(sig: i32, code: i32, mxcsr: Option<u32>) -> &'static str {
    match (sig, code) {
        (libc::SIGFPE, FPE_INTDIV) => "integer divide by zero",
        (libc::SIGFPE, FPE_INTOVF) => "integer overflow",
        (libc::SIGFPE, FPE_FLTDIV) => "FP exception: division by zero",
        (libc::SIGFPE, FPE_FLTOVF) => "FP exception: overflow",
        (libc::SIGFPE, FPE_FLTINV) => {
            "FP exception: invalid operation (0/0, sqrt of a negative number, a NaN compared, or a float→int conversion out of range)"
        }
        // Linux reports the denormal-operand exception as underflow; MXCSR tells them apart.
        (libc::SIGFPE, FPE_FLTUND) if mxcsr.is_some_and(|m| m & 0x2 != 0) => "FP exception: denormal operand",
        (libc::SIGFPE, FPE_FLTUND) => "FP exception: underflow",
        (libc::SIGFPE, FPE_FLTRES) => "FP exception: inexact result",
        (libc::SIGFPE, _) => "arithmetic exception",
        (libc::SIGSEGV, SEGV_ACCERR) => "invalid memory access (no permission: a read-only page, e.g. a read-only shared region)",
        // A general protection fault: the kernel has no address to give (a jump or a
        // return to a non-canonical address, e.g. through a smashed stack frame).
        (libc::SIGSEGV, libc::SI_KERNEL) => "invalid memory access (a general protection fault: a bad address, e.g. a return through a smashed stack frame)",
        (libc::SIGSEGV, _) => "invalid memory access (unmapped address)",
        (libc::SIGBUS, BUS_ADRALN) => "misaligned access",
        (libc::SIGBUS, _) => "bad memory access",
        (libc::SIGILL, _) => "illegal instruction",
        (libc::SIGABRT, _) => "abort",
        _ => "fault",
    }
}

pub fn signal_name(sig: i32) -> &'static str {
    match sig {
        libc::SIGSEGV => "SIGSEGV",
        libc::SIGBUS => "SIGBUS",
        libc::SIGFPE => "SIGFPE",
        libc::SIGILL => "SIGILL",
        libc::SIGABRT => "SIGABRT",
        _ => "signal",
    }
}
