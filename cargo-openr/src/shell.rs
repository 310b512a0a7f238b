//! All human-facing output, cargo style: status lines right-aligned to 12 columns on
//! stderr; machine-readable results on stdout. Colour as cargo's: `--color
//! auto|always|never` (or `CARGO_TERM_COLOR`), `auto` meaning "stderr is a terminal".
use std::io::{IsTerminal, Write};

/// `--color`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum ColorChoice {
    #[default]
    Auto,
    Always,
    Never,
}

pub struct Shell {
    quiet: bool,
    color: bool,
}

const GREEN: &str = "\x1b[1;32m";
const RED: &str = "\x1b[1;31m";
const YELLOW: &str = "\x1b[1;33m";
const CYAN: &str = "\x1b[1;36m";
const RESET: &str = "\x1b[0m";

impl Shell {
    pub fn new() -> Shell {
        Shell { quiet: false, color: false }
    }

    pub fn set_color(&mut self, choice: ColorChoice) {
        self.color = match choice {
            ColorChoice::Always => true,
            ColorChoice::Never => false,
            ColorChoice::Auto => std::io::stderr().is_terminal() && std::env::var_os("TERM").is_none_or(|t| t != "dumb"),
        };
    }

    /// Whether stderr output is coloured (the compiler is asked for colour too).
    pub fn color(&self) -> bool {
        self.color
    }

    fn paint(&self, colour: &str, text: &str) -> String {
        if self.color {
            format!("{colour}{text}{RESET}")
        } else {
            text.to_string()
        }
    }

    /// No status lines or warnings from now on (errors and stdout results still appear).
    pub fn set_quiet(&mut self, quiet: bool) {
        self.quiet = quiet;
    }

    /// `   Installing OPEN-R SDK root` on stderr.
    pub fn status(&mut self, verb: &str, msg: &str) {
        if !self.quiet {
            let verb = self.paint(GREEN, &format!("{verb:>12}"));
            let _ = writeln!(std::io::stderr(), "{verb} {msg}");
        }
    }

    pub fn error(&mut self, msg: &str) {
        let _ = writeln!(std::io::stderr(), "{}: {msg}", self.paint(RED, "error"));
    }

    pub fn warn(&mut self, msg: &str) {
        if !self.quiet {
            let _ = writeln!(std::io::stderr(), "{}: {msg}", self.paint(YELLOW, "warning"));
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

    /// The runtime's messages (`sdk_runtime::runtime::Report`) in this shell's style.
    pub fn reporter(&self) -> std::sync::Arc<dyn sdk_runtime::runtime::Report> {
        std::sync::Arc::new(RuntimeReport { color: self.color })
    }

    /// A result line on stdout (paths, JSON).
    pub fn out(&mut self, line: &str) {
        let _ = writeln!(std::io::stdout(), "{line}");
    }
}

/// The shell's colours for messages from the runtime's threads (it is `Send`; the
/// `Shell` is not).
struct RuntimeReport {
    color: bool,
}

impl RuntimeReport {
    fn labelled(&self, colour: &str, label: &str, msg: &str) {
        let label = if self.color { format!("{colour}{label}{RESET}") } else { label.to_string() };
        // One write per line: objects' threads report concurrently.
        let _ = std::io::stderr().write_all(format!("{label} {msg}\n").as_bytes());
    }
}

impl sdk_runtime::runtime::Report for RuntimeReport {
    fn warn(&self, msg: &str) {
        self.labelled(YELLOW, "warning:", msg);
    }
    fn error(&self, msg: &str) {
        self.labelled(RED, "error:", msg);
    }
    fn note(&self, msg: &str) {
        self.labelled(CYAN, &format!("{:>12}", "note:"), msg);
    }
    fn line(&self, text: &str) {
        let _ = std::io::stderr().write_all(format!("{text}\n").as_bytes());
    }
}

/// The exit status of a child tool the command ran in the foreground (gdb, valgrind),
/// which `main` passes on without a message of its own.
#[derive(Debug)]
pub struct ChildStatus(pub u8);

impl std::fmt::Display for ChildStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "the tool exited with status {}", self.0)
    }
}

impl std::error::Error for ChildStatus {}
