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
    unsafe { libc::fflush(stdout_file()) };
    let mut rest = bytes;
    while !rest.is_empty() {
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
