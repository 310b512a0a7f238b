//! What `-fpermissive` cannot make g++ 12 accept from gcc-3.3-era code (legacy-code 1),
//! when the legacy repair (repair/mod.rs) could not make the whole unit compile: the
//! compiler's error stays as it is, and a `note:` line with the same file:line says why it
//! compiled on the robot toolchain and what to change.
use std::collections::HashMap;
use std::path::Path;

/// Notes for the diagnostics in `stderr` (g++'s `file:line:col: error: …` lines).
pub fn notes(stderr: &str, cwd: &Path) -> Vec<String> {
    let mut sources = Sources { cwd, files: HashMap::new() };
    let mut out: Vec<String> = Vec::new();
    for line in stderr.lines() {
        // The assembler's: MIPS inline assembly the SDK's gcc plugin did not leave out.
        if let Some((loc, msg)) = line.split_once(": Error: ").filter(|(_, m)| m.starts_with("no such instruction")) {
            let text = format!(
                "{loc}: note: [cargo-openr] {msg}: MIPS inline assembly the PC cannot run; the SDK's gcc plugin leaves it out, but this root has none for this compiler (`cargo openr doctor` says why); or put it under `#ifdef __mips__`"
            );
            if !out.contains(&text) {
                out.push(text);
            }
            continue;
        }
        let Some((loc, msg)) = line.split_once(": error: ") else { continue };
        let note = if msg.contains("need \u{2018}typename\u{2019} before") || msg.contains("need 'typename' before") {
            Some("gcc 3.3 accepted a dependent type without `typename` (implicit typename, removed in gcc 3.4); g++ 12 cannot: add `typename` before it (repaired automatically once the unit's other errors are fixed)".to_string())
        } else if msg.starts_with("redefinition of") && is_parameter_redefinition(sources.before(loc, 1)) {
            Some("gcc 3.3 accepted the same parameter name twice in one declaration; g++ 12 cannot: rename one of the parameters (repaired automatically once the unit's other errors are fixed)".to_string())
        } else if let Some(name) = undeclared_name(msg) {
            declared_in_earlier_for(sources.before(loc, 60), &name).then(|| {
                format!("`{name}` is declared in an earlier `for` statement: gcc 3.3's old for-scope rule kept it visible after the loop; g++ 12 has no switch for that: declare `{name}` before the loop (repaired automatically once the unit's other errors are fixed)")
            })
        } else {
            None
        };
        if let Some(n) = note {
            let text = format!("{loc}: note: [cargo-openr] {n}");
            if !out.contains(&text) {
                out.push(text);
            }
        }
    }
    out
}

/// `‘i’ was not declared in this scope` → `i`.
fn undeclared_name(msg: &str) -> Option<String> {
    let rest = msg.strip_suffix(" was not declared in this scope")?;
    let name = rest.trim_matches(|c| c == '\u{2018}' || c == '\u{2019}' || c == '\'');
    (!name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_')).then(|| name.to_string())
}

/// The source files the diagnostics name, each read once.
struct Sources<'a> {
    cwd: &'a Path,
    files: HashMap<String, Option<Vec<String>>>,
}

impl Sources<'_> {
    /// Up to `count` source lines ending with the line of a `file:line:col` location
    /// (none when the file cannot be read or the line is not in it: `#line` can say anything).
    fn before(&mut self, loc: &str, count: usize) -> &[String] {
        let mut parts = loc.rsplitn(3, ':');
        let (Some(_col), Some(line), Some(file)) = (parts.next(), parts.next(), parts.next()) else { return &[] };
        let Ok(line) = line.parse::<usize>() else { return &[] };
        let cwd = self.cwd;
        let lines =
            self.files.entry(file.to_string()).or_insert_with(|| std::fs::read_to_string(cwd.join(file)).ok().map(|t| t.lines().map(str::to_string).collect()));
        match lines {
            Some(lines) if (1..=lines.len()).contains(&line) => &lines[line.saturating_sub(count)..line],
            _ => &[],
        }
    }
}

fn is_parameter_redefinition(line: &[String]) -> bool {
    // g++ reports it inside a parameter list: the line has '(' before the column.
    line.last().is_some_and(|l| l.contains('('))
}

fn declared_in_earlier_for(lines: &[String], name: &str) -> bool {
    lines.iter().any(|l| {
        let l: String = l.split_whitespace().collect::<Vec<_>>().join(" ");
        l.find("for (").or_else(|| l.find("for(")).is_some_and(|i| {
            let head = &l[i..];
            let decl = head.split(';').next().unwrap_or("");
            // The name is declared (left of `=`), not merely used in the initialiser.
            let declarator = decl.split('=').next().unwrap_or("");
            declarator.split(|c: char| !(c.is_alphanumeric() || c == '_')).any(|w| w == name) && decl.contains('=')
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn explains_what_gcc_3_3_accepted() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("a.cc"),
            "template <class T> void f() { Box<T>::value_type x; }\nint g() {\n  for (int i = 0; i < 3; i++) {}\n  return i;\n}\nstruct A { void m(int a, int a); };\n",
        )
        .unwrap();
        let err = "a.cc:1:31: error: need \u{2018}typename\u{2019} before \u{2018}Box<T>::value_type\u{2019}\n\
                   a.cc:4:10: error: \u{2018}i\u{2019} was not declared in this scope\n\
                   a.cc:6:30: error: redefinition of \u{2018}int a\u{2019}\n\
                   a.cc:6:1: error: \u{2018}zz\u{2019} was not declared in this scope\n";
        let n = notes(err, dir.path());
        assert_eq!(n.len(), 3, "{n:#?}");
        assert!(n[0].starts_with("a.cc:1:31: note: [cargo-openr] gcc 3.3 accepted a dependent type without `typename`"));
        assert!(n[1].starts_with("a.cc:4:10: note: [cargo-openr] `i` is declared in an earlier `for` statement"));
        assert!(n[2].starts_with("a.cc:6:30: note: [cargo-openr] gcc 3.3 accepted the same parameter name twice"));
    }

    #[test]
    fn locations_outside_the_file_get_no_note_and_no_panic() {
        // `#line 200` makes g++ name lines the file does not have; line 0 is not a line.
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("a.cc"), "#line 200\nint g() { return i; }\n").unwrap();
        let err = "a.cc:200:19: error: \u{2018}i\u{2019} was not declared in this scope\n\
                   a.cc:0:1: error: redefinition of \u{2018}int a\u{2019}\n\
                   gone.cc:3:1: error: \u{2018}i\u{2019} was not declared in this scope\n";
        assert!(notes(err, dir.path()).is_empty());
    }
}
