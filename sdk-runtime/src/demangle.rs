//! C++ names for messages: `_Z14missing_helperi` → `missing_helper(int)`, with the
//! demangler of the C++ runtime every object links anyway (`__cxa_demangle` of
//! libstdc++, found with `dlopen`; the runtime executable itself is not C++).
use std::ffi::{c_char, c_int, CStr, CString};
use std::sync::OnceLock;

type CxaDemangle = unsafe extern "C" fn(*const c_char, *mut c_char, *mut usize, *mut c_int) -> *mut c_char;

fn cxa_demangle() -> Option<CxaDemangle> {
    static FN: OnceLock<usize> = OnceLock::new();
    // SAFETY: C string names; the handle is kept open for the process (never dlclosed).
    let p = *FN.get_or_init(|| unsafe {
        let lib = libc::dlopen(c"libstdc++.so.6".as_ptr(), libc::RTLD_LAZY | libc::RTLD_LOCAL);
        if lib.is_null() {
            return 0;
        }
        libc::dlsym(lib, c"__cxa_demangle".as_ptr()) as usize
    });
    // SAFETY: libstdc++'s __cxa_demangle has this signature.
    (p != 0).then(|| unsafe { std::mem::transmute::<usize, CxaDemangle>(p) })
}

/// The demangled form of a C++ symbol name, or `None` (not mangled, or no demangler).
pub fn demangle(symbol: &str) -> Option<String> {
    if !symbol.starts_with("_Z") {
        return None;
    }
    let f = cxa_demangle()?;
    let c = CString::new(symbol).ok()?;
    let mut status: c_int = -1;
    // SAFETY: a NUL-terminated name; a NULL buffer asks for a malloc'd result.
    let out = unsafe { f(c.as_ptr(), std::ptr::null_mut(), std::ptr::null_mut(), &mut status) };
    if out.is_null() {
        return None;
    }
    // SAFETY: on success the result is a NUL-terminated malloc'd string we now own.
    let s = unsafe { CStr::from_ptr(out) }.to_string_lossy().into_owned();
    // SAFETY: `out` is __cxa_demangle's malloc'd result, no longer used.
    unsafe { libc::free(out.cast()) };
    (status == 0).then_some(s)
}

/// `symbol` for a message: `missing_helper(int)` (`_Z14missing_helperi`) for a C++ name,
/// the name itself for a C one.
pub fn describe(symbol: &str) -> String {
    match demangle(symbol) {
        Some(d) => format!("{d} ({symbol})"),
        None => symbol.to_string(),
    }
}

/// `text` (a loader message) with every mangled word followed by its demangled form.
pub fn annotate(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("_Z") {
        let end = rest[i..].find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.' || c == '$')).map_or(rest.len(), |e| i + e);
        out.push_str(&rest[..i]);
        let word = &rest[i..end];
        let starts_word = i == 0 || !rest[..i].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_');
        match demangle(word).filter(|_| starts_word) {
            Some(d) => out.push_str(&format!("`{d}` ({word})")),
            None => out.push_str(word),
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cxx_names_are_demangled_c_names_kept() {
        assert_eq!(demangle("_Z14missing_helperi").as_deref(), Some("missing_helper(int)"));
        assert_eq!(demangle("missing_helper"), None);
        assert_eq!(demangle("_Znot a name"), None);
        assert_eq!(describe("_ZN7Counter7DoStartERK12OSystemEvent"), "Counter::DoStart(OSystemEvent const&) (_ZN7Counter7DoStartERK12OSystemEvent)");
        assert_eq!(describe("printf"), "printf");
    }

    #[test]
    fn loader_messages_are_annotated() {
        assert_eq!(annotate("x.so: undefined symbol: _Z14missing_helperi"), "x.so: undefined symbol: `missing_helper(int)` (_Z14missing_helperi)");
        assert_eq!(annotate("undefined symbol: foo_Zbar"), "undefined symbol: foo_Zbar");
    }
}
