//! Where a `.BIN`'s ELF image is put for `dlopen` (issue 18.3). Nothing of it is left in
//! a shared directory another user could prepare or swap, nor after a run that crashed:
//!
//! * normally the image lives in an anonymous memory file (`memfd_create`) and is opened
//!   as `/proc/<pid>/fd/<n>`: no name in any directory, gone with the process however it
//!   ends. gdb (which reads that path of the debuggee) and the crash reporter's
//!   backtraces still find the symbols; the descriptor stays open for the life of the
//!   process, as objects are never unloaded.
//! * where memory files cannot be mapped executable, or `OPENR_SCRATCH_FILES=1` asks for
//!   it, the image is written into a fresh private directory (`mkdtemp`, mode 0700,
//!   under `$TMPDIR` or /tmp) with `O_EXCL | O_NOFOLLOW`, and file and directory are
//!   removed as soon as `dlopen` returns.
use std::ffi::{CStr, CString};
use std::io::Write;
use std::os::fd::{FromRawFd, IntoRawFd};
use std::os::unix::ffi::{OsStrExt, OsStringExt};
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};

/// The environment variable that makes images go through files.
pub const FILES_VAR: &str = "OPENR_SCRATCH_FILES";

/// What `dlopen` gave: the handle, or its error message (taken at once: the next libc
/// call of the runtime may clear it).
pub type Opened = std::result::Result<*mut libc::c_void, String>;

/// `dlopen`s `elf` (named `name` where a name shows) with `flags`; returns what dlopen
/// gave and the path it opened, or why the image could not be placed.
pub fn dlopen_image(name: &str, elf: &[u8], flags: libc::c_int) -> std::io::Result<(Opened, PathBuf)> {
    let files_asked = std::env::var_os(FILES_VAR).is_some_and(|v| v == "1");
    if !files_asked {
        // Without memory files (old kernel, seccomp, vm.memfd_noexec=2): a file.
        if let Ok(path) = memory_file(name, elf) {
            return Ok((dlopen(&path, flags)?, path));
        }
    }
    let dir = private_dir()?;
    let path = dir.join(name);
    let opened = write_new(&path, elf).and_then(|()| dlopen(&path, flags));
    let _ = std::fs::remove_file(&path);
    let _ = std::fs::remove_dir(&dir);
    opened.map(|o| (o, path))
}

fn dlopen(path: &Path, flags: libc::c_int) -> std::io::Result<Opened> {
    let c = CString::new(path.as_os_str().as_bytes()).map_err(|_| std::io::ErrorKind::InvalidInput)?;
    // SAFETY: a NUL-terminated path; running the object's constructors is the point.
    let handle = unsafe { libc::dlopen(c.as_ptr(), flags) };
    if !handle.is_null() {
        return Ok(Ok(handle));
    }
    // SAFETY: dlerror's string is valid until the next dl* call; copied at once.
    let err = unsafe { libc::dlerror() };
    // SAFETY: `err` is non-null: dlerror's C string, copied before any other dl* call.
    let text = if err.is_null() { "unknown dlopen error".into() } else { unsafe { CStr::from_ptr(err) }.to_string_lossy().into_owned() };
    Ok(Err(text))
}

/// The image in a memory file, as a path of this process's descriptor table.
fn memory_file(name: &str, elf: &[u8]) -> std::io::Result<PathBuf> {
    const MFD_EXEC: libc::c_uint = 0x10; // Linux 6.3+: executable even where the default is not
    let cname = CString::new(name).map_err(|_| std::io::ErrorKind::InvalidInput)?;
    // SAFETY: `cname` is a C string that outlives the closure.
    let create = |flags| unsafe { libc::memfd_create(cname.as_ptr(), flags) };
    let mut fd = create(libc::MFD_CLOEXEC | MFD_EXEC);
    if fd < 0 && std::io::Error::last_os_error().raw_os_error() == Some(libc::EINVAL) {
        fd = create(libc::MFD_CLOEXEC); // older kernels know no MFD_EXEC
    }
    if fd < 0 {
        return Err(std::io::Error::last_os_error());
    }
    // SAFETY: a descriptor just created and owned here.
    let mut file = unsafe { std::fs::File::from_raw_fd(fd) };
    file.write_all(elf)?;
    // Kept open for the life of the process: the loaded object is known by this path.
    let fd = file.into_raw_fd();
    Ok(PathBuf::from(format!("/proc/{}/fd/{fd}", std::process::id())))
}

/// A new directory only this user can enter.
fn private_dir() -> std::io::Result<PathBuf> {
    let base = std::env::var_os("TMPDIR").filter(|v| !v.is_empty()).map(PathBuf::from).unwrap_or_else(|| "/tmp".into());
    let mut template = base.join("cargo-openr-XXXXXX").into_os_string().into_vec();
    template.push(0);
    // SAFETY: a writable NUL-terminated template.
    let made = unsafe { libc::mkdtemp(template.as_mut_ptr().cast()) };
    if made.is_null() {
        let e = std::io::Error::last_os_error();
        return Err(std::io::Error::new(e.kind(), format!("cannot make a private directory in {}: {e}", base.display())));
    }
    // SAFETY: mkdtemp returned the template, still NUL-terminated.
    let path = unsafe { CStr::from_ptr(made) };
    Ok(PathBuf::from(std::ffi::OsStr::from_bytes(path.to_bytes())))
}

/// Creates `path`, which must not exist (not even as a link), and writes `bytes`.
fn write_new(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut f = std::fs::OpenOptions::new().write(true).create_new(true).mode(0o700).custom_flags(libc::O_NOFOLLOW | libc::O_CLOEXEC).open(path)?;
    f.write_all(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::PermissionsExt;

    #[test]
    fn private_dirs_are_new_and_private() {
        let (a, b) = (private_dir().unwrap(), private_dir().unwrap());
        assert_ne!(a, b);
        assert_eq!(std::fs::metadata(&a).unwrap().permissions().mode() & 0o777, 0o700);
        for d in [a, b] {
            std::fs::remove_dir(d).unwrap();
        }
    }

    #[test]
    fn write_new_follows_no_link_and_overwrites_nothing() {
        let d = tempfile::tempdir().unwrap();
        let victim = d.path().join("victim");
        std::fs::write(&victim, "keep").unwrap();
        std::os::unix::fs::symlink(&victim, d.path().join("link")).unwrap();
        assert!(write_new(&d.path().join("link"), b"evil").is_err());
        assert!(write_new(&victim, b"evil").is_err());
        assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep");
    }
}
