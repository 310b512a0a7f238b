//! Diagnostics of the linters (`cargo openr check`, `cargo openr ms verify`), and their
//! one renderer: rustc's human format or one JSON object per line.
//!
//! Codes (stable; tests and editors match on them):
//!
//! | code | what |
//! |---|---|
//! | E0001 | a file or directory name under `MS/OPEN-R` is not FAT 8.3 |
//! | E0002 | OBJECT.CFG missing or malformed, or an object it lists does not exist |
//! | E0003 | a listed object is not loadable (not gzip/ELF x86-64 shared object, no entry symbols) |
//! | E0004 | a CONNECT.CFG line is malformed (field count, service name not `Obj.Sub.Data.S\|O`) |
//! | E0005 | subject and observer in the wrong order or of the wrong kind (must be S then O) |
//! | E0006 | the DataName parts of a connection differ |
//! | E0007 | a connection names a service no object registers (not in any stub, not a system service) |
//! | E0008 | a stub.cfg is rejected by stubgen2 (e.g. declared counts differ from the services) |
//! | E0009 | an `.ocf` file is malformed |
//! | E0010 | a connection is listed twice |
//! | E0011 | a Remote Processing gateway file (ROBOTGW.CFG, HOSTGW.CFG) is malformed or names a service twice, or a host stick loads TCPGW.BIN |
//! | W0001 | a name under `MS/OPEN-R` has lower-case letters (FAT stores it upper case) |
//! | W0002 | a registered subject or observer (or gateway service) is never connected |
//! | W0003 | what the gateway warns about at start: a gateway service in more than one connection, TCPGW.BIN without ROBOTGW.CFG, an unknown line option, an address on a robot line |
//! | W0004 | a connection is listed twice on a Remote Processing stick (left out, as the runtime does) |
use std::path::PathBuf;

use serde::Serialize;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    Error,
    Warning,
}

/// One finding, with the place it refers to.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Diagnostic {
    pub level: Level,
    pub code: &'static str,
    pub message: String,
    pub file: Option<PathBuf>,
    pub line: Option<usize>,
    pub help: Option<String>,
}

impl Diagnostic {
    pub fn error(code: &'static str, message: impl Into<String>) -> Diagnostic {
        Diagnostic { level: Level::Error, code, message: message.into(), file: None, line: None, help: None }
    }

    pub fn warning(code: &'static str, message: impl Into<String>) -> Diagnostic {
        Diagnostic { level: Level::Warning, ..Diagnostic::error(code, message) }
    }

    pub fn at(mut self, file: impl Into<PathBuf>, line: Option<usize>) -> Diagnostic {
        self.file = Some(file.into());
        self.line = line;
        self
    }

    pub fn help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }
}

/// How diagnostics are printed (`--message-format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum MessageFormat {
    /// rustc style, on stderr
    #[default]
    Human,
    /// one JSON object per line on stdout: level, code, message, file, line, help
    Json,
}

/// The text of one diagnostic in `format` (no trailing newline).
pub fn render(d: &Diagnostic, format: MessageFormat) -> String {
    match format {
        MessageFormat::Json => serde_json::to_string(d).expect("diagnostics serialise"),
        MessageFormat::Human => {
            let level = match d.level {
                Level::Error => "error",
                Level::Warning => "warning",
            };
            let mut s = format!("{level}[{}]: {}", d.code, d.message);
            if let Some(file) = &d.file {
                s.push_str(&format!("\n  --> {}", file.display()));
                if let Some(line) = d.line {
                    s.push_str(&format!(":{line}"));
                }
            }
            if let Some(help) = &d.help {
                s.push_str(&format!("\n   = help: {help}"));
            }
            s
        }
    }
}

/// The findings of one lint run.
#[derive(Debug, Default)]
pub struct Report {
    pub diagnostics: Vec<Diagnostic>,
}

impl Report {
    pub fn push(&mut self, d: Diagnostic) {
        self.diagnostics.push(d);
    }

    pub fn errors(&self) -> usize {
        self.diagnostics.iter().filter(|d| d.level == Level::Error).count()
    }

    pub fn warnings(&self) -> usize {
        self.diagnostics.iter().filter(|d| d.level == Level::Warning).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn human_and_json() {
        let d = Diagnostic::error("E0007", "unknown service `A.B.c.O`").at("MS/CONNECT.CFG", Some(3)).help("declare it");
        assert_eq!(render(&d, MessageFormat::Human), "error[E0007]: unknown service `A.B.c.O`\n  --> MS/CONNECT.CFG:3\n   = help: declare it");
        let v: serde_json::Value = serde_json::from_str(&render(&d, MessageFormat::Json)).unwrap();
        assert_eq!(v["level"], "error");
        assert_eq!(v["line"], 3);
        let w = Diagnostic::warning("W0001", "x");
        let v: serde_json::Value = serde_json::from_str(&render(&w, MessageFormat::Json)).unwrap();
        assert_eq!((v["level"].as_str(), v["file"].is_null()), (Some("warning"), true));
    }
}
