//! All human-facing output, cargo style: status lines right-aligned to 12 columns on
//! stderr; machine-readable results on stdout.
use std::io::Write;

pub struct Shell {
    quiet: bool,
}

impl Shell {
    pub fn new() -> Shell {
        Shell { quiet: false }
    }

    /// No status lines or warnings from now on (errors and stdout results still appear).
    pub fn set_quiet(&mut self, quiet: bool) {
        self.quiet = quiet;
    }

    /// `   Installing OPEN-R SDK root` on stderr.
    pub fn status(&mut self, verb: &str, msg: &str) {
        if !self.quiet {
            let _ = writeln!(std::io::stderr(), "{verb:>12} {msg}");
        }
    }

    pub fn error(&mut self, msg: &str) {
        let _ = writeln!(std::io::stderr(), "error: {msg}");
    }

    pub fn warn(&mut self, msg: &str) {
        if !self.quiet {
            let _ = writeln!(std::io::stderr(), "warning: {msg}");
        }
    }

    /// A lint finding: rustc's human format on stderr, or one JSON line on stdout.
    pub fn diagnostic(&mut self, d: &crate::ops::diag::Diagnostic, format: crate::ops::diag::MessageFormat) {
        let text = crate::ops::diag::render(d, format);
        match format {
            crate::ops::diag::MessageFormat::Json => self.out(&text),
            crate::ops::diag::MessageFormat::Human => {
                let _ = writeln!(std::io::stderr(), "{text}\n");
            }
        }
    }

    /// A result line on stdout (paths, JSON).
    pub fn out(&mut self, line: &str) {
        let _ = writeln!(std::io::stdout(), "{line}");
    }
}
