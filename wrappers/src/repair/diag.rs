//! g++'s diagnostics as the repair rounds ask for them (`-fdiagnostics-parseable-fixits
//! -fdiagnostics-column-unit=byte -fno-diagnostics-show-caret`): `file:line:col: error: …`
//! lines, the `note:`s that follow an error, and `fix-it:"file":{l:c-l:c}:"text"` lines.

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Loc {
    pub file: String,
    pub line: usize,
    pub col: usize,
}

impl std::fmt::Display for Loc {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.col)
    }
}

/// Replace `[from, to)` (same file, byte columns) by `text`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct FixIt {
    pub from: Loc,
    pub to: Loc,
    pub text: String,
}

#[derive(Debug, Clone)]
pub(crate) struct Diag {
    pub loc: Loc,
    pub msg: String,
    pub fixits: Vec<FixIt>,
    /// The `note:` diagnostics g++ attached to this error.
    pub notes: Vec<Diag>,
}

/// The errors (fatal or not) of one g++ run, with their notes and fix-its.
pub(crate) fn errors(stderr: &str) -> Vec<Diag> {
    // Where a fix-it line belongs: the last error, its last note, or nothing (a warning's).
    #[derive(PartialEq)]
    enum To {
        Error,
        Note,
        Nothing,
    }
    let mut out: Vec<Diag> = Vec::new();
    let mut leads: Vec<usize> = Vec::new();
    let mut to = To::Nothing;
    for line in stderr.lines() {
        if let Some(rest) = line.strip_prefix("fix-it:") {
            let (Some(fix), Some(d)) = (parse_fixit(rest), out.last_mut()) else { continue };
            match to {
                To::Error => d.fixits.push(fix),
                To::Note => d.notes.last_mut().expect("a note").fixits.push(fix),
                To::Nothing => {}
            }
            continue;
        }
        let Some((loc, level, msg)) = split_diag(line) else { continue };
        let diag = Diag { loc, msg: msg.to_string(), fixits: Vec::new(), notes: Vec::new() };
        // The warning at a dependent member template without `template` is where the
        // parse went wrong: it leads the errors that follow it.
        let lead = level == "warning" && super::rules::is_missing_template_keyword(msg);
        to = match (level, out.last_mut()) {
            ("error" | "fatal error", _) => {
                out.push(diag);
                To::Error
            }
            _ if lead => {
                leads.push(out.len());
                out.push(diag);
                To::Error
            }
            ("note", Some(d)) if to != To::Nothing => {
                d.notes.push(diag);
                To::Note
            }
            _ => To::Nothing,
        };
    }
    // Only where the parse then failed on that line: g++ also warns at code it accepts
    // (`a.b < c > (d)` read as comparisons).
    let followed = |i: usize| out.get(i + 1).is_some_and(|n| !leads.contains(&(i + 1)) && n.loc.file == out[i].loc.file && n.loc.line == out[i].loc.line);
    let keep: Vec<bool> = (0..out.len()).map(|i| !leads.contains(&i) || followed(i)).collect();
    let mut keep = keep.into_iter();
    out.retain(|_| keep.next().unwrap_or(true));
    out
}

/// g++'s message with its typographic quotes (‘x’) made ASCII ('x'), as the rules match.
pub(crate) fn ascii_quotes(msg: &str) -> String {
    msg.replace(['\u{2018}', '\u{2019}'], "'")
}

/// `a.cc:4:5: error: msg` → (loc, "error", "msg").
pub(crate) fn split_diag(line: &str) -> Option<(Loc, &str, &str)> {
    for level in ["fatal error", "error", "warning", "note"] {
        let tag = format!(": {level}: ");
        if let Some(i) = line.find(&tag) {
            let loc = parse_loc(&line[..i])?;
            return Some((loc, level, &line[i + tag.len()..]));
        }
    }
    None
}

fn parse_loc(s: &str) -> Option<Loc> {
    let mut parts = s.rsplitn(3, ':');
    let col = parts.next()?.parse().ok()?;
    let line = parts.next()?.parse().ok()?;
    let file = parts.next()?.to_string();
    Some(Loc { file, line, col })
}

/// `"file":{4:5-4:5}:"typename "` (the `fix-it:` prefix removed).
fn parse_fixit(s: &str) -> Option<FixIt> {
    let (file, rest) = quoted(s)?;
    let rest = rest.strip_prefix(":{")?;
    let (range, rest) = rest.split_once("}:")?;
    let (a, b) = range.split_once('-')?;
    let pos = |p: &str| -> Option<(usize, usize)> {
        let (l, c) = p.split_once(':')?;
        Some((l.parse().ok()?, c.parse().ok()?))
    };
    let ((l1, c1), (l2, c2)) = (pos(a)?, pos(b)?);
    let (text, _) = quoted(rest)?;
    Some(FixIt { from: Loc { file: file.clone(), line: l1, col: c1 }, to: Loc { file, line: l2, col: c2 }, text })
}

/// A C-escaped string literal at the start of `s` (gcc escapes `\`, `"` and
/// non-printable bytes as `\ooo`); returns it and what follows.
fn quoted(s: &str) -> Option<(String, &str)> {
    let b = s.as_bytes();
    if b.first() != Some(&b'"') {
        return None;
    }
    let mut out = Vec::new();
    let mut i = 1;
    while i < b.len() {
        match b[i] {
            b'"' => return Some((String::from_utf8_lossy(&out).into_owned(), &s[i + 1..])),
            b'\\' if i + 3 < b.len() && b[i + 1..i + 4].iter().all(|c| (b'0'..=b'7').contains(c)) => {
                out.push(u8::from_str_radix(&s[i + 1..i + 4], 8).ok()?);
                i += 4;
            }
            b'\\' if i + 1 < b.len() => {
                out.push(match b[i + 1] {
                    b'n' => b'\n',
                    b't' => b'\t',
                    c => c,
                });
                i += 2;
            }
            c => {
                out.push(c);
                i += 1;
            }
        }
    }
    None
}

/// The names a message quotes (‘…’ or '…'), in order.
pub(crate) fn quoted_names(msg: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = msg;
    loop {
        let open = match (rest.find('\u{2018}'), rest.find('\'')) {
            (Some(a), Some(b)) if b < a => (b, 1),
            (Some(a), _) => (a, '\u{2018}'.len_utf8()),
            (None, Some(b)) => (b, 1),
            (None, None) => return out,
        };
        let body = &rest[open.0 + open.1..];
        let Some(close) = body.find(['\u{2019}', '\'']) else { return out };
        out.push(&body[..close]);
        let skip = body[close..].chars().next().map_or(1, char::len_utf8);
        rest = &body[close + skip..];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_notes_and_fixits() {
        let err = "t.cc: In member function \u{2018}void f()\u{2019}:\n\
                   t.cc:4:5: error: need \u{2018}typename\u{2019} before \u{2018}B<T>::v\u{2019}\n\
                   fix-it:\"t.cc\":{4:5-4:5}:\"typename \"\n\
                   t.cc:20:30: error: redefinition of 'double* dp'\n\
                   t.cc:20:18: note: 'double* dp' previously declared here\n\
                   t.cc:21:1: warning: unused\n\
                   fix-it:\"t.cc\":{21:1-21:2}:\"x\"\n\
                   dir:with:colons/a.h:3:1: fatal error: gone\n";
        let e = errors(err);
        assert_eq!(e.len(), 3, "{e:#?}");
        assert_eq!(e[0].loc, Loc { file: "t.cc".into(), line: 4, col: 5 });
        assert_eq!(e[0].fixits, vec![FixIt { from: e[0].loc.clone(), to: e[0].loc.clone(), text: "typename ".into() }]);
        assert_eq!(e[1].notes[0].msg, "'double* dp' previously declared here");
        assert!(e[1].fixits.is_empty(), "a warning's fix-it is not the error's");
        assert_eq!(e[2].loc.file, "dir:with:colons/a.h");
        assert_eq!(quoted_names(&e[0].msg), vec!["typename", "B<T>::v"]);
        assert_eq!(quoted(r#""a\"b\\c\101" rest"#), Some(("a\"b\\cA".to_string(), " rest")));
    }

    #[test]
    fn a_missing_template_warning_leads_only_where_the_parse_then_failed() {
        let w = "warning: expected \u{2018}template\u{2019} keyword before dependent template name [-Wmissing-template-keyword]";
        let err = format!(
            "t.cc:2:41: {w}\nt.cc:2:45: error: expected primary-expression before \u{2018}int\u{2019}\n\
             t.cc:7:10: {w}\nt.cc:9:3: error: \u{2018}x\u{2019} was not declared in this scope\nt.cc:12:4: {w}\n"
        );
        let lines: Vec<(usize, usize)> = errors(&err).iter().map(|d| (d.loc.line, d.loc.col)).collect();
        assert_eq!(lines, [(2, 41), (2, 45), (9, 3)], "the warnings of lines 7 and 12 led to no error there");
    }
}
