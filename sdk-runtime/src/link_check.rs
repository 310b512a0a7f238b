//! Would `dlopen` resolve every symbol of this object? Asked of the system's dynamic
//! loader itself, in a child process and without running any of the object's code: the
//! interpreter of the running executable (`PT_INTERP`, e.g. `ld-linux-x86-64.so.2`)
//! started in trace mode (`LD_TRACE_LOADED_OBJECTS`, `LD_BIND_NOW`, `LD_WARN`: what
//! `ldd -r` does) loads the object and its libraries, binds every symbol now and prints
//! each one it cannot bind, each library it cannot find and each symbol version missing.
//!
//! The runtime loads objects with `RTLD_LOCAL` into an executable that exports its own
//! tables (`openr_runtime_api_v1`, …); a symbol the loader reports unbound is therefore
//! not a problem when this executable (the same one that runs objects) defines it
//! globally (`dlsym(RTLD_DEFAULT)`).
use std::ffi::CString;
use std::path::Path;
use std::process::Command;

use crate::demangle;
use crate::error::{Error, Result};

/// Why the dynamic loader would refuse the ELF file at `so` (one line each, C++ names
/// demangled); empty when it loads. `bin` names the `.BIN` in errors.
pub fn load_problems(bin: &Path, so: &Path) -> Result<Vec<String>> {
    let interp = interpreter().ok_or_else(|| Error::load(bin, "cannot test-load: the dynamic loader of this executable is unknown (no PT_INTERP)"))?;
    let out = Command::new(&interp)
        .arg(so)
        .env("LD_TRACE_LOADED_OBJECTS", "1")
        .env("LD_BIND_NOW", "1")
        .env("LD_WARN", "yes")
        .env_remove("LD_PRELOAD")
        .output()
        .map_err(|e| Error::load(bin, format!("cannot test-load with {interp}: {e}")))?;
    if let Some(sig) = std::os::unix::process::ExitStatusExt::signal(&out.status) {
        return Ok(vec![format!("the dynamic loader died loading it (signal {sig}): the file is damaged")]);
    }
    let mut problems = Vec::new();
    let text = String::from_utf8_lossy(&out.stderr).into_owned() + &String::from_utf8_lossy(&out.stdout);
    for line in text.lines().map(str::trim) {
        if let Some(rest) = line.strip_prefix("undefined symbol: ") {
            let sym = rest.split(['\t', ' ']).next().unwrap_or(rest);
            if !defined_here(sym) {
                problems.push(format!("undefined symbol {}", demangle::describe(sym)));
            }
        } else if let Some(lib) = line.strip_suffix(" => not found") {
            problems.push(format!("needs {lib}, which the dynamic loader cannot find"));
        } else if line.contains("version `") && line.contains("not found") {
            problems.push(line.to_string());
        }
    }
    if problems.is_empty() && !out.status.success() {
        problems.push(format!("the dynamic loader refused it: {}", text.trim()));
    }
    Ok(problems)
}

/// True when this executable provides `sym` to every object (its exported tables).
fn defined_here(sym: &str) -> bool {
    let Ok(c) = CString::new(sym) else { return false };
    // SAFETY: a NUL-terminated name; RTLD_DEFAULT searches the global scope.
    !unsafe { libc::dlsym(libc::RTLD_DEFAULT, c.as_ptr()) }.is_null()
}

/// The running executable's program interpreter.
fn interpreter() -> Option<String> {
    let exe = std::fs::read("/proc/self/exe").ok()?;
    crate::elf_check::interpreter(&exe)
}
