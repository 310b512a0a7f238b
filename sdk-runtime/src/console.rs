//! The robot's console (telnet port 59000 on the robot): stdout of the runtime. Each
//! message is written with one `write(2)` under a lock, so messages of concurrently
//! running objects never interleave (object-model 4.2).
use std::sync::Mutex;

static LOCK: Mutex<()> = Mutex::new(());

/// Writes `bytes` to fd 1 in one piece (retrying on short writes while holding the lock).
pub fn write(bytes: &[u8]) {
    let _guard = LOCK.lock().unwrap_or_else(|p| p.into_inner());
    // Flush what C stdio (printf/cout of objects) buffered for the console first, so
    // order is kept; other streams (objects' open files) are not the console's business.
    // SAFETY: `stdout_file` is glibc's live `stdout` stream.
    unsafe { libc::fflush(stdout_file()) };
    let mut rest = bytes;
    while !rest.is_empty() {
        // SAFETY: `rest` is a live slice: write reads at most its length.
        let n = unsafe { libc::write(1, rest.as_ptr().cast(), rest.len()) };
        if n <= 0 {
            if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                continue;
            }
            return;
        }
        rest = &rest[n as usize..];
    }
}

/// C stdio's `stdout` (objects' printf/cout write there).
pub fn stdout_file() -> *mut libc::FILE {
    extern "C" {
        static mut stdout: *mut libc::FILE;
    }
    // SAFETY: glibc's `stdout` is initialised before main and never reassigned here.
    unsafe { stdout }
}

/// The robot's console input never ends: a read with no input blocks the object, at the
/// end of a file or with stdin closed too (a PC's EOF made `while (gets(line))`-style
/// readers spin, printing their prompt millions of times). fd 0 becomes a pipe that a
/// pump thread fills from the real stdin and never closes. A terminal stays fd 0 (a
/// pump reading it would stop a background run with SIGTTIN).
pub mod input {
    use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
    use std::sync::Mutex;
    use std::time::{Duration, Instant};

    /// fd 0 is the pump's pipe (the process has one stdin, whatever runs in it).
    static TAKEN: AtomicBool = AtomicBool::new(false);
    const MAX_OBJECTS: usize = 128;

    /// What one run knows of its objects and the console, by object index.
    pub struct Watch {
        /// Each object thread's kernel tid (its first thread: the one that runs its
        /// messages).
        tids: Mutex<Vec<(usize, libc::pid_t)>>,
        /// Objects found blocked on the console, with the message count at that moment:
        /// still blocked while they have not finished that message.
        blocked: Mutex<Vec<(usize, u64)>>,
        /// Messages each object has finished (`run_loop`).
        handled: [crate::padded::Line<AtomicU64>; MAX_OBJECTS],
        /// Busy objects with their message count and since when they were seen busy in it.
        busy: Mutex<Vec<(usize, u64, Instant)>>,
    }

    impl Default for Watch {
        fn default() -> Watch {
            Watch {
                tids: Mutex::new(Vec::new()),
                blocked: Mutex::new(Vec::new()),
                handled: std::array::from_fn(|_| crate::padded::Line(AtomicU64::new(0))),
                busy: Mutex::new(Vec::new()),
            }
        }
    }

    /// Puts the never-ending pipe on fd 0 (once per process; not for a terminal).
    pub fn take_over_stdin() {
        // SAFETY: isatty takes any fd.
        if unsafe { libc::isatty(0) } == 1 || TAKEN.swap(true, Ordering::AcqRel) {
            return;
        }
        // SAFETY: fcntl(F_DUPFD_CLOEXEC) on fd 0 touches no memory.
        let real = unsafe { libc::fcntl(0, libc::F_DUPFD_CLOEXEC, 3) };
        let mut p = [0; 2];
        // SAFETY: `p` is a writable array of two fds; dup2 takes any fds.
        if unsafe { libc::pipe2(p.as_mut_ptr(), libc::O_CLOEXEC) } != 0 || unsafe { libc::dup2(p[0], 0) } < 0 {
            TAKEN.store(false, Ordering::Release);
            return;
        }
        // SAFETY: `p[0]` is the pipe's read end, now also fd 0: closing this copy only.
        unsafe { libc::close(p[0]) };
        let write_end = p[1];
        if real < 0 {
            return; // stdin was closed: nothing will ever come, and nothing ends either
        }
        let _ = std::thread::Builder::new().name("openr-console-in".into()).spawn(move || pump(real, write_end));
    }

    /// Copies the real stdin into the pipe; at its end, closes only the real one.
    fn pump(real: i32, pipe: i32) {
        let mut buf = [0u8; 4096];
        loop {
            // SAFETY: the read is bounded by `buf`'s length.
            let n = unsafe { libc::read(real, buf.as_mut_ptr().cast(), buf.len()) };
            if n < 0 && std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                continue;
            }
            if n <= 0 {
                break;
            }
            let mut rest = &buf[..n as usize];
            while !rest.is_empty() {
                // SAFETY: `rest` is a live slice: write reads at most its length.
                let w = unsafe { libc::write(pipe, rest.as_ptr().cast(), rest.len()) };
                if w <= 0 {
                    if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                        continue;
                    }
                    return;
                }
                rest = &rest[w as usize..];
            }
        }
        // SAFETY: `real` is the pump's own dup of stdin, closed once, here.
        unsafe { libc::close(real) };
    }

    impl Watch {
        /// Called on each object's thread before it runs object code.
        pub fn register_thread(&self, index: usize) {
            // SAFETY: gettid has no preconditions.
            let tid = unsafe { libc::gettid() };
            let mut t = self.tids.lock().unwrap_or_else(|p| p.into_inner());
            if !t.iter().any(|(i, _)| *i == index) {
                t.push((index, tid));
            }
        }

        /// An object finished a message.
        pub fn handled(&self, index: usize) {
            if let Some(c) = self.handled.get(index) {
                c.fetch_add(1, Ordering::Relaxed);
            }
        }

        fn handled_count(&self, index: usize) -> Option<u64> {
            self.handled.get(index).map(|c| c.load(Ordering::Relaxed))
        }
    }

    /// Bytes waiting in the console pipe.
    fn pending_input() -> i32 {
        let mut n: libc::c_int = 0;
        // SAFETY: FIONREAD writes one c_int, into the live `n`.
        if unsafe { libc::ioctl(0, libc::FIONREAD, &mut n) } != 0 {
            return 0;
        }
        n
    }

    /// How long an object runs one message before its thread is looked at.
    const PROBE_AFTER: Duration = Duration::from_millis(1);

    impl Watch {
        /// Whether the busy object `index` waits for console input that has not come (for
        /// the frame thread: such an object is idle, as one sleeping on virtual time is).
        /// Cheap once known, until it finishes that message or input arrives; otherwise the
        /// thread's current system call is looked at (`/proc/self/task/TID/syscall`: read
        /// on fd 0) once the object has been in one message for `PROBE_AFTER`.
        pub fn blocked_reading(&self, index: usize) -> bool {
            self.check(index, false)
        }

        /// The same, looking at the thread at once (the shutdown sequence: a blocked
        /// object gets no Stop, and no timeout is waited out).
        pub fn waits_for_input(&self, index: usize) -> bool {
            self.check(index, true)
        }

        fn check(&self, index: usize, at_once: bool) -> bool {
            if !TAKEN.load(Ordering::Acquire) {
                return false;
            }
            let Some(now) = self.handled_count(index) else { return false };
            let known = self.blocked.lock().unwrap_or_else(|p| p.into_inner()).iter().any(|&(i, h)| i == index && h == now);
            if known {
                return pending_input() == 0;
            }
            if !at_once {
                let mut busy = self.busy.lock().unwrap_or_else(|p| p.into_inner());
                match busy.iter_mut().find(|(i, _, _)| *i == index) {
                    Some(b) if b.1 == now => {
                        if b.2.elapsed() < PROBE_AFTER {
                            return false;
                        }
                    }
                    Some(b) => {
                        *b = (index, now, Instant::now());
                        return false;
                    }
                    None => {
                        busy.push((index, now, Instant::now()));
                        return false;
                    }
                }
            }
            if pending_input() != 0 {
                return false;
            }
            let tid = self.tids.lock().unwrap_or_else(|p| p.into_inner()).iter().find(|(i, _)| *i == index).map(|(_, t)| *t);
            let Some(tid) = tid else { return false };
            let Ok(text) = std::fs::read_to_string(format!("/proc/self/task/{tid}/syscall")) else { return false };
            let mut f = text.split_whitespace();
            // read(2) is system call 0 on x86-64; its first argument the descriptor.
            let blocked = f.next() == Some("0") && f.next() == Some("0x0");
            if blocked {
                let mut b = self.blocked.lock().unwrap_or_else(|p| p.into_inner());
                b.retain(|(i, _)| *i != index);
                b.push((index, now));
            }
            blocked
        }
    }
}
