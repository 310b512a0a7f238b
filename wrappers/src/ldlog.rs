//! Reading the GNU linker's diagnostics: which symbols were undefined, and where from.
//!
//! With `LC_ALL=C` and `--demangle`, ld (bfd) reports an unresolved reference as
//! ```text
//! /usr/bin/ld: Missing.o: in function `Missing::DoStart(OSystemEvent const&)':
//! Missing.cc:31:(.text+0x2b): undefined reference to `missing_helper(int)'
//! ```
//! (a data reference has no `in function` line and the object in place of the source).

/// One undefined symbol and its first reference.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UndefinedRef {
    /// Demangled, as ld printed it: `missing_helper(int)`.
    pub symbol: String,
    /// The object (or `archive(member)`) holding the reference.
    pub object: Option<String>,
    /// The function making it, when ld names one.
    pub function: Option<String>,
    /// `file:line` of the reference (from debug info), or the object and section.
    pub location: Option<String>,
    /// References to the same symbol, this one included.
    pub count: usize,
}

impl std::fmt::Display for UndefinedRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "undefined symbol `{}`", self.symbol)?;
        let mut from = Vec::new();
        if let Some(o) = &self.object {
            from.push(o.clone());
        }
        if let Some(func) = &self.function {
            from.push(format!("in {func}"));
        }
        if let Some(l) = self.location.as_ref().filter(|l| Some(*l) != self.object.as_ref()) {
            from.push(format!("at {l}"));
        }
        if !from.is_empty() {
            write!(f, ", referenced from {}", from.join(" "))?;
        }
        if self.count > 1 {
            write!(f, " and {} more place(s)", self.count - 1)?;
        }
        Ok(())
    }
}

/// The undefined symbols ld reported in `log`, in order of first mention.
pub fn undefined_references(log: &str) -> Vec<UndefinedRef> {
    const MARK: &str = ": undefined reference to `";
    let mut out: Vec<UndefinedRef> = Vec::new();
    let (mut object, mut function) = (None::<String>, None::<String>);
    for line in log.lines() {
        let line = strip_tool(line);
        if let Some(rest) = line.strip_suffix("':") {
            if let Some((obj, func)) = rest.split_once(": in function `") {
                (object, function) = (Some(obj.to_string()), Some(func.to_string()));
                continue;
            }
        }
        let Some(i) = line.find(MARK) else {
            continue;
        };
        let symbol = line[i + MARK.len()..].trim_end().trim_end_matches('\'').to_string();
        let location = strip_section(&line[..i]).to_string();
        if let Some(seen) = out.iter_mut().find(|u| u.symbol == symbol) {
            seen.count += 1;
            continue;
        }
        // A data reference names its object (`X.o`, `libA.a(x.o)`) in place of a source.
        let data = location.ends_with(".o") || location.ends_with(')') || function.is_none();
        let (obj, func) = if data { (Some(location.clone()), None) } else { (object.clone(), function.clone()) };
        out.push(UndefinedRef { symbol, object: obj, function: func, location: Some(location), count: 1 });
    }
    out
}

/// `/usr/bin/ld: rest` → `rest` (any linker program path: `ld`, `ld.bfd`, `x86_64-linux-gnu-ld`).
fn strip_tool(line: &str) -> &str {
    match line.split_once(": ") {
        Some((tool, rest)) if tool.rsplit('/').next().is_some_and(|n| n == "ld" || n.ends_with("-ld") || n.starts_with("ld.")) => rest,
        _ => line,
    }
}

/// `Missing.cc:31:(.text+0x2b)` → `Missing.cc:31`; `X.o:(.data+0x0)` → `X.o`.
fn strip_section(loc: &str) -> &str {
    match loc.rfind(":(") {
        Some(i) if loc.ends_with(')') => &loc[..i],
        _ => loc,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_call_from_a_function_with_debug_info() {
        let log = "/usr/bin/ld: Missing.o: in function `Missing::DoStart(OSystemEvent const&)':\n\
                   /src/Missing/Missing.cc:31:(.text+0x2b): undefined reference to `missing_helper(int)'\n\
                   /usr/bin/ld: /src/Missing/Missing.cc:33:(.text+0x40): undefined reference to `missing_helper(int)'\n\
                   collect2: error: ld returned 1 exit status\n";
        let u = undefined_references(log);
        assert_eq!(u.len(), 1, "{u:?}");
        assert_eq!(u[0].symbol, "missing_helper(int)");
        assert_eq!(u[0].object.as_deref(), Some("Missing.o"));
        assert_eq!(u[0].count, 2);
        assert_eq!(
            u[0].to_string(),
            "undefined symbol `missing_helper(int)`, referenced from Missing.o in Missing::DoStart(OSystemEvent const&) at /src/Missing/Missing.cc:31 and 1 more place(s)"
        );
    }

    #[test]
    fn data_references_and_archive_members() {
        let log = "/usr/bin/ld: f.o: in function `f()':\nf.cc:(.text+0x1): undefined reference to `g()'\n\
                   /usr/bin/ld: Table.o:(.data.rel+0x8): undefined reference to `handler'\n\
                   /usr/bin/x86_64-linux-gnu-ld: libA.a(a.o): in function `a()':\n\
                   a.cc:(.text+0x5): undefined reference to `b()'\n";
        let u = undefined_references(log);
        assert_eq!(u.len(), 3, "{u:?}");
        assert_eq!(u[1].to_string(), "undefined symbol `handler`, referenced from Table.o");
        assert_eq!(u[2].to_string(), "undefined symbol `b()`, referenced from libA.a(a.o) in a() at a.cc");
    }

    #[test]
    fn other_failures_have_none() {
        assert!(undefined_references("/usr/bin/ld: cannot find -lfoo: No such file or directory\n").is_empty());
    }
}
