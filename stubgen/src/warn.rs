//! Warnings: what a `stub.cfg` says that Sony's `stubgen2` accepted but that is dubious.
//!
//! Sony's tool wrote `const int obs<SubName> = <index>;` once per service, so a SubName
//! used twice by services of one kind gave two definitions of one constant, and projects
//! patched the generated `def.h` in their Makefile (a `sed` line). We accept the file
//! too, keep each definition line as Sony wrote it (so such a patch still applies), and
//! make the unpatched output compile: `obs<SubName>` names the first service, and the
//! line of every later one is compiled under another name (see `def.h.hbs`).

use std::fmt;
use std::path::PathBuf;

use crate::parse::{Service, ServiceKind, StubCfg};

/// A dubious but accepted construct, with the `stub.cfg` line it is on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Warning {
    /// The file, as it was named by the caller.
    pub file: PathBuf,
    /// 1-based line number.
    pub line: usize,
    /// The message without the `<file>:<line>: ` prefix.
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: warning: {}", self.file.display(), self.line, self.message)
    }
}

/// For each service of `list`, how many services before it have the same SubName
/// (0 for the first use of a SubName).
pub(crate) fn repeats(list: &[Service]) -> Vec<usize> {
    list.iter().enumerate().map(|(i, svc)| list[..i].iter().filter(|s| s.sub_name == svc.sub_name).count()).collect()
}

/// The warnings for `cfg`, in file order within each kind (subjects first).
pub fn warnings(cfg: &StubCfg) -> Vec<Warning> {
    let mut out = Vec::new();
    for list in [&cfg.subjects, &cfg.observers] {
        for (i, n) in repeats(list).into_iter().enumerate() {
            if n == 0 {
                continue;
            }
            let svc = &list[i];
            let first = list.iter().find(|s| s.sub_name == svc.sub_name).expect("an earlier use");
            let (prefix, kind) = match svc.kind {
                ServiceKind::Subject => ("sbj", "subject"),
                ServiceKind::Observer => ("obs", "observer"),
            };
            let same = if first.name == svc.name { " (the same service name: only one can be registered)" } else { "" };
            out.push(Warning {
                file: svc.file.clone(),
                line: svc.line,
                message: format!(
                    "SubName '{sub}' is already used by the {kind} service on {}:{}{same}; \
                     '{prefix}{sub}' in def.h is {} (the first), the line defining it as {i} is \
                     compiled under another name unless the project patches def.h",
                    first.file.display(),
                    first.line,
                    list.iter().position(|s| s.sub_name == svc.sub_name).unwrap_or(0),
                    sub = svc.sub_name,
                ),
            });
        }
    }
    out
}
