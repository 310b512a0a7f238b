//! `.ocf` object configuration files (object-model 1.3). The host has no use for stack,
//! heap or priority, but `mkbin` still requires a well-formed ocf and records the object
//! name in the `.BIN` for logs.
use std::path::Path;

use crate::error::{Error, ErrorKind};

/// The parsed `object` line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ocf {
    pub name: String,
    pub stack: u64,
    pub heap: u64,
    pub priority: u64,
    pub cache: bool,
    pub tlb: bool,
    pub user_mode: bool,
}

/// Parses the text of `path`: `#` comments, any whitespace (CRLF included) between words.
pub fn parse(path: &Path, text: &str) -> Result<Ocf, Error> {
    let mut words: Vec<(usize, &str)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let code = line.split('#').next().unwrap_or("");
        words.extend(code.split_whitespace().map(|w| (i + 1, w)));
    }
    let err = |line: usize, message: String| -> Error { ErrorKind::Ocf { path: path.to_path_buf(), line, message }.into() };
    let Some(&(first_line, first)) = words.first() else {
        return Err(err(1, "empty file: expected `object NAME STACK HEAP PRIO CACHE TLB MODE`".into()));
    };
    if first != "object" {
        return Err(err(first_line, format!("expected the word `object`, found `{first}`")));
    }
    // (line, word) of each value: the 7-value form, or the 14-value form whose last six
    // fields match the short form's.
    let values = &words[1..];
    let v: [(usize, &str); 7] = match values.len() {
        7 => values.try_into().unwrap(),
        14 => [values[0], values[6], values[7], values[10], values[11], values[12], values[13]],
        n => return Err(err(first_line, format!("expected 7 values (`object NAME STACK HEAP PRIO CACHE TLB MODE`) or 14, found {n}"))),
    };
    let size = |field: &str, (line, value): (usize, &str)| -> Result<u64, Error> {
        let (digits, mult) = match value.strip_suffix(['k', 'K']) {
            Some(d) => (d, 1024),
            None => (value, 1),
        };
        let n = digits.parse::<u64>().map_err(|_| err(line, format!("{field} must be a number (optionally with a K suffix), found `{value}`")))?;
        n.checked_mul(mult).ok_or_else(|| err(line, format!("{field} `{value}` is too large (at most {} bytes)", u64::MAX)))
    };
    // Sony's gensnap took anything but the exact word as the other choice; a typo
    // (`cahce`) then silently changed the object's memory setup. Only the documented
    // words are accepted here.
    let choice = |field: &str, (line, value): (usize, &str), yes: &str, no: &str| -> Result<bool, Error> {
        match value {
            _ if value == yes => Ok(true),
            _ if value == no => Ok(false),
            _ => Err(err(line, format!("{field} must be `{yes}` or `{no}`, found `{value}`"))),
        }
    };
    let (prio_line, prio) = v[3];
    Ok(Ocf {
        name: v[0].1.to_string(),
        stack: size("STACK", v[1])?,
        heap: size("HEAP", v[2])?,
        priority: prio.parse().map_err(|_| err(prio_line, format!("PRIO must be a number, found `{prio}`")))?,
        cache: choice("CACHE", v[4], "cache", "nocache")?,
        tlb: choice("TLB", v[5], "tlb", "notlb")?,
        user_mode: choice("MODE", v[6], "user", "kernel")?,
    })
}

/// The text of an ocf read as bytes: UTF-8 (ASCII in practice), else an error at the
/// line of the first byte that is not.
pub fn decode<'a>(path: &Path, bytes: &'a [u8]) -> Result<&'a str, Error> {
    std::str::from_utf8(bytes).map_err(|e| {
        let at = e.valid_up_to();
        let line = 1 + bytes[..at].iter().filter(|b| **b == b'\n').count();
        let column = 1 + at - bytes[..at].iter().rposition(|b| *b == b'\n').map_or(0, |i| i + 1);
        let message = format!("byte 0x{:02x} at column {column} is not text (the file must be ASCII or UTF-8)", bytes[at]);
        ErrorKind::Ocf { path: path.to_path_buf(), line, message }.into()
    })
}

/// Reads and parses an ocf file.
pub fn read(path: &Path) -> Result<Ocf, Error> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse(path, decode(path, &bytes)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(text: &str) -> Result<Ocf, Error> {
        parse(Path::new("x.ocf"), text)
    }

    #[test]
    fn short_form_with_crlf_and_comments() {
        let o = p("# comment\r\nobject helloWorld 3072 16384 128 cache tlb user # tail\r\n").unwrap();
        assert_eq!(o.name, "helloWorld");
        assert_eq!((o.stack, o.heap, o.priority), (3072, 16384, 128));
        assert!(o.cache && o.tlb && o.user_mode);
    }

    #[test]
    fn k_suffix_and_multiline() {
        let o = p("object big\n 8K 16k\n144 nocache notlb kernel\n").unwrap();
        assert_eq!((o.stack, o.heap, o.priority), (8192, 16384, 144));
        assert!(!o.cache && !o.tlb && !o.user_mode);
    }

    #[test]
    fn long_form() {
        let o = p("object n mod mCOOP pic pid none 4096 8192 none -1 128 cache tlb user").unwrap();
        assert_eq!((o.name.as_str(), o.stack, o.heap, o.priority), ("n", 4096, 8192, 128));
    }

    #[test]
    fn errors_name_file_and_line() {
        let e = p("\n\nobjekt a 1 2 3 cache tlb user").unwrap_err().to_string();
        assert_eq!(e, "x.ocf:3: ocf format error: expected the word `object`, found `objekt`");
        let e = p("object a 1 2 3 cache tlb").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:1: ocf format error: expected 7 values"), "{e}");
        let e = p("object a 1\n zz 3 cache tlb user").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:2: ocf format error: HEAP must be a number"), "{e}");
        // The line of the value itself, even when the same word stood earlier.
        let e = p("object zz 1\nzz 3 cache tlb user").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:2: ocf format error: HEAP must be a number (optionally with a K suffix), found `zz`"), "{e}");
        let e = p("object a\n4k\n1 x cache tlb user").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:3: ocf format error: PRIO must be a number, found `x`"), "{e}");
        let e = p("object a 1q 2 3 cache tlb user").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:1: ocf format error: STACK must be a number"), "{e}");
        let e = p("  # only a comment\n").unwrap_err().to_string();
        assert!(e.contains("empty file"), "{e}");
    }

    #[test]
    fn only_the_documented_choice_words() {
        let e = p("object a 1 2 3\ncahce tlb user").unwrap_err().to_string();
        assert_eq!(e, "x.ocf:2: ocf format error: CACHE must be `cache` or `nocache`, found `cahce`");
        let e = p("object a 1 2 3 cache TLB user").unwrap_err().to_string();
        assert_eq!(e, "x.ocf:1: ocf format error: TLB must be `tlb` or `notlb`, found `TLB`");
        let e = p("object a 1 2 3 cache tlb\n\nsuper").unwrap_err().to_string();
        assert_eq!(e, "x.ocf:3: ocf format error: MODE must be `user` or `kernel`, found `super`");
    }

    #[test]
    fn sizes_that_overflow_are_errors() {
        let e = p("object a\n18446744073709551615K 2 3 cache tlb user").unwrap_err().to_string();
        assert_eq!(e, format!("x.ocf:2: ocf format error: STACK `18446744073709551615K` is too large (at most {} bytes)", u64::MAX));
        let e = p("object a 1 99999999999999999999 3 cache tlb user").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:1: ocf format error: HEAP must be a number"), "{e}");
        assert_eq!(p("object a 18014398509481983K 1 3 cache tlb user").unwrap().stack, 18014398509481983 * 1024);
    }

    #[test]
    fn a_byte_that_is_not_text_has_a_line() {
        let bytes = b"# ok\nobject a 1 2 3\ncache tlb us\xe9r\n";
        let e = decode(Path::new("x.ocf"), bytes).unwrap_err().to_string();
        assert_eq!(e, "x.ocf:3: ocf format error: byte 0xe9 at column 13 is not text (the file must be ASCII or UTF-8)");
        let e = decode(Path::new("x.ocf"), b"\xff").unwrap_err().to_string();
        assert!(e.starts_with("x.ocf:1: ocf format error: byte 0xff at column 1"), "{e}");
        assert_eq!(decode(Path::new("x.ocf"), "object \u{e9}".as_bytes()).unwrap(), "object \u{e9}");
    }
}
