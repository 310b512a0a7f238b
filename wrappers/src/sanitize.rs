//! `OPENR_SANITIZE=address|undefined|thread`: a sanitizer for Makefile builds, the way
//! `cargo openr build --sanitize` gives one (the Makefile's own `CXXFLAGS` and `LDFLAGS`
//! stay untouched). `mipsel-linux-g++`/`gcc` add the instrumentation, `mkbin` links the
//! sanitizer's runtime; `cargo openr run` then preloads it.
use crate::error::Error;

pub const VAR: &str = "OPENR_SANITIZE";

/// The sanitizer `OPENR_SANITIZE` names, if set; an unknown value is an error.
pub fn from_env() -> Result<Option<&'static str>, Error> {
    let Some(v) = std::env::var_os(VAR).filter(|v| !v.is_empty()) else { return Ok(None) };
    match v.to_string_lossy().as_ref() {
        "address" => Ok(Some("address")),
        "undefined" => Ok(Some("undefined")),
        "thread" => Ok(Some("thread")),
        other => Err(Error::usage(format!("{VAR}={other}: expected address, undefined or thread"))),
    }
}

/// Compiler flags for the sanitizer in `OPENR_SANITIZE`.
pub fn compile_flags() -> Result<Vec<&'static str>, Error> {
    Ok(match from_env()? {
        Some("address") => vec!["-fsanitize=address", "-fno-omit-frame-pointer"],
        Some("undefined") => vec!["-fsanitize=undefined", "-fno-omit-frame-pointer"],
        Some(_) => vec!["-fsanitize=thread", "-fno-omit-frame-pointer"],
        None => vec![],
    })
}

/// Link flags for the sanitizer in `OPENR_SANITIZE`.
pub fn link_flags() -> Result<Vec<String>, Error> {
    Ok(from_env()?.map(|s| vec![format!("-fsanitize={s}")]).unwrap_or_default())
}
