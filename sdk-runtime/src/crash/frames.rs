//! The backtrace of a crash, inside the signal handler: no allocation anywhere.
//!
//! * Frames: `_Unwind_Backtrace` (through `backtrace::trace_unsynchronized`), warmed up at
//!   install so its first use (FDE cache, `dl_iterate_phdr`) is not in the handler.
//! * Names: `dladdr` — not async-signal-safe by POSIX, but it only reads the loaded
//!   modules' symbol tables (it takes the loader lock: a fault inside `dlopen` could
//!   block it; the alarm then ends the process). Rust names are demangled in place;
//!   C++ names stay mangled on that line.
//! * Source lines and C++ names: `addr2line -f -C -i -p` run with `posix_spawn`
//!   (glibc's: a vfork-style clone, no malloc) on each frame of an object module with debug info, its
//!   output read through a pipe into a stack buffer.
use std::ffi::{c_void, CString};
use std::fmt::Write as _;
use std::sync::OnceLock;

use super::out::{CText, Out};

pub const MAX_FRAMES: usize = 48;

/// `addr2line`, ready to be spawned from the handler: its path, a pipe for its answer
/// and the file actions putting the pipe on its stdout (stderr to /dev/null).
struct Symboliser {
    path: CString,
    pipe: [libc::c_int; 2],
    actions: Actions,
}

struct Actions(libc::posix_spawn_file_actions_t);
// SAFETY: built once, then only read (by posix_spawn).
unsafe impl Send for Actions {}
// SAFETY: as for Send: posix_spawn only reads the actions, never changes them.
unsafe impl Sync for Actions {}

static ADDR2LINE: OnceLock<Option<Symboliser>> = OnceLock::new();

fn symboliser() -> Option<Symboliser> {
    let explicit = std::env::var_os("OPENR_ADDR2LINE").map(std::path::PathBuf::from);
    let found = explicit.or_else(|| std::env::split_paths(&std::env::var_os("PATH")?).map(|d| d.join("addr2line")).find(|p| p.is_file()))?;
    let path = CString::new(found.into_os_string().into_encoded_bytes()).ok()?;
    let mut pipe = [0; 2];
    // SAFETY: `pipe` is a writable array of two fds.
    if unsafe { libc::pipe2(pipe.as_mut_ptr(), libc::O_CLOEXEC | libc::O_NONBLOCK) } != 0 {
        return None;
    }
    // SAFETY: posix_spawn_file_actions_t is plain C data, all-zero before its init.
    let mut actions: libc::posix_spawn_file_actions_t = unsafe { std::mem::zeroed() };
    // SAFETY: `actions` is a live local, initialised before it is added to; the path is a C string.
    unsafe {
        libc::posix_spawn_file_actions_init(&mut actions);
        libc::posix_spawn_file_actions_adddup2(&mut actions, pipe[1], 1);
        libc::posix_spawn_file_actions_addopen(&mut actions, 2, c"/dev/null".as_ptr(), libc::O_WRONLY, 0);
    }
    Some(Symboliser { path, pipe, actions: Actions(actions) })
}

/// Finds `addr2line` (on `PATH`, or `OPENR_ADDR2LINE`) and walks a stack once.
pub fn warm_up() {
    ADDR2LINE.get_or_init(symboliser);
    let mut n = 0;
    // SAFETY: the crate's lock is skipped (a handler must not block on it); the walk itself is
    // libgcc's `_Unwind_Backtrace`, safe to run on several threads at once.
    unsafe {
        backtrace::trace_unsynchronized(|_| {
            n += 1;
            n < 4
        })
    };
}

/// The return addresses of the current stack, from the faulting instruction `pc` on
/// (the handler's own frames are dropped when `pc` is found among them).
pub fn collect(pc: usize) -> ([usize; MAX_FRAMES], usize) {
    let mut ips = [0usize; MAX_FRAMES];
    let mut n = 0;
    // SAFETY: as in `warm_up`; the callback stays within `ips` (it stops at MAX_FRAMES).
    unsafe {
        backtrace::trace_unsynchronized(|f| {
            ips[n] = f.ip() as usize;
            n += 1;
            n < MAX_FRAMES
        })
    };
    if let Some(at) = ips[..n].iter().position(|&ip| ip == pc) {
        ips.copy_within(at..n, 0);
        n -= at;
    }
    while n > 0 && ips[n - 1] == 0 {
        n -= 1;
    }
    (ips, n)
}

/// One module and symbol of an address.
pub struct Place {
    pub info: libc::Dl_info,
}

pub fn place(addr: usize) -> Option<Place> {
    // SAFETY: Dl_info is plain C data (pointers and null pointers).
    let mut info: libc::Dl_info = unsafe { std::mem::zeroed() };
    // SAFETY: `info` is a writable Dl_info; dladdr accepts any address.
    (unsafe { libc::dladdr(addr as *const c_void, &mut info) } != 0).then_some(Place { info })
}

impl Place {
    pub fn is_main_program(&self) -> bool {
        let exe = place(warm_up as *const () as usize);
        exe.is_some_and(|e| e.info.dli_fbase == self.info.dli_fbase)
    }

    /// A module of the system (glibc, libstdc++…): no debug info to look up.
    fn is_system_library(&self) -> bool {
        // SAFETY: a `Place` comes from a successful dladdr, whose `dli_fname` is the module's C string
        // (modules are never unloaded).
        let name = unsafe { std::ffi::CStr::from_ptr(self.info.dli_fname) }.to_bytes();
        name.starts_with(b"/lib") || name.starts_with(b"/usr/lib")
    }
}

/// `  N: 0xADDR symbol+0xOFF (module)`, then the source line when it can be found.
pub fn write_frame(out: &mut Out, i: usize, ip: usize, lookup_lines: bool) {
    let _ = write!(out, "  {i:2}: {ip:#014x}");
    match place(ip) {
        Some(p) => {
            if !p.info.dli_sname.is_null() {
                // SAFETY: `dli_sname` is non-null: the symbol's C string in the loaded module.
                let bytes = unsafe { std::ffi::CStr::from_ptr(p.info.dli_sname) }.to_bytes();
                let _ = write!(out, " {:#}+{:#x}", backtrace::SymbolName::new(bytes), ip - p.info.dli_saddr as usize);
            }
            let _ = writeln!(out, " ({})", CText(p.info.dli_fname));
            if lookup_lines && !p.is_main_program() && !p.is_system_library() {
                // Return addresses point after the call: look up the call itself.
                let at = if i == 0 { ip } else { ip - 1 };
                source_line(out, &p, at - p.info.dli_fbase as usize, !p.info.dli_sname.is_null());
            }
        }
        None => {
            let _ = writeln!(out, " ??");
        }
    }
}

/// Runs `addr2line` on one offset of a module and appends its answer, unless it knows
/// nothing (a stripped module: `?? ??:0`).
/// Without line information (a stripped module) only the demangled name is kept, and
/// only when `named` (addr2line's nearest-symbol guess for a static function would be a
/// wrong name).
fn source_line(out: &mut Out, p: &Place, offset: usize, named: bool) {
    let Some(Some(tool)) = ADDR2LINE.get() else { return };
    let mut addr = [0u8; 24];
    let text = hex(offset, &mut addr);
    let argv: [*const libc::c_char; 9] = [
        tool.path.as_ptr(),
        c"-f".as_ptr(),
        c"-C".as_ptr(),
        c"-i".as_ptr(),
        c"-p".as_ptr(),
        c"-e".as_ptr(),
        p.info.dli_fname,
        text.as_ptr().cast(),
        std::ptr::null(),
    ];
    let envp: [*const libc::c_char; 1] = [std::ptr::null()];
    let mut pid = 0;
    // glibc's posix_spawn: clone(CLONE_VM|CLONE_VFORK) on an mmap'ed stack, no malloc
    // and no fork handlers; the file actions were built at install.
    // SAFETY: argv and envp are null-terminated arrays of C strings that outlive the call;
    // `actions` was initialised at install.
    let spawned = unsafe { libc::posix_spawn(&mut pid, argv[0], &tool.actions.0, std::ptr::null(), argv.as_ptr().cast(), envp.as_ptr().cast()) };
    if spawned != 0 {
        return;
    }
    // SAFETY: waitpid on our own child, no status buffer.
    unsafe { libc::waitpid(pid, std::ptr::null_mut(), 0) };
    // The answer waits in the pipe (far less than its 64 KiB); the read end is non-blocking.
    let mut answer = [0u8; 2048];
    let mut len = 0;
    while len < answer.len() {
        // SAFETY: the read is bounded to the unused tail of `answer`.
        let n = unsafe { libc::read(tool.pipe[0], answer[len..].as_mut_ptr().cast(), answer.len() - len) };
        if n <= 0 {
            break;
        }
        len += n as usize;
    }
    let answer = std::str::from_utf8(&answer[..len]).unwrap_or("");
    for line in answer.lines().filter(|l| !l.starts_with("??")) {
        let line = line.trim();
        match line.strip_suffix(" at ??:?").or_else(|| line.strip_suffix(" at ??:0")) {
            Some(name) if named => {
                let _ = writeln!(out, "        {name}");
            }
            Some(_) => {}
            None => {
                let _ = writeln!(out, "        {line}");
            }
        }
    }
}

/// `0x…` of `v`, NUL-terminated, in `buf`.
fn hex(mut v: usize, buf: &mut [u8; 24]) -> &[u8] {
    let mut digits = [0u8; 16];
    let mut n = 0;
    loop {
        digits[n] = b"0123456789abcdef"[v & 0xf];
        n += 1;
        v >>= 4;
        if v == 0 {
            break;
        }
    }
    buf[0] = b'0';
    buf[1] = b'x';
    for i in 0..n {
        buf[2 + i] = digits[n - 1 - i];
    }
    buf[2 + n] = 0;
    &buf[..3 + n]
}
