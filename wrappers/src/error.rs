//! Errors of the SDK-root tools.
use std::fmt;
use std::path::PathBuf;

/// An error of one tool run; `Display` is the one-line message shown to the user.
#[derive(Debug)]
pub struct Error {
    kind: ErrorKind,
}

/// What went wrong.
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// Bad command line: the text says what was expected.
    Usage(String),
    /// A file could not be read or written.
    Io { path: PathBuf, source: std::io::Error },
    /// A host tool (g++, ar, ...) is not installed.
    MissingHostTool { tool: String, hint: String },
    /// A host tool ran and failed.
    CommandFailed { command: String, status: String },
    /// An `.ocf` file is malformed (object-model 1.3).
    Ocf { path: PathBuf, line: usize, message: String },
    /// The link failed; `log` is what the linker printed.
    LinkFailed { command: String, status: String, log: String },
    /// The link failed on symbols nothing defines (`-z defs`).
    Undefined { output: PathBuf, references: Vec<crate::ldlog::UndefinedRef>, log: String },
    /// The linked object lacks what the runtime needs.
    BadObject { path: PathBuf, message: String },
}

impl Error {
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }
    pub(crate) fn usage(msg: impl Into<String>) -> Error {
        ErrorKind::Usage(msg.into()).into()
    }
    pub(crate) fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Error {
        ErrorKind::Io { path: path.into(), source }.into()
    }
}

impl From<ErrorKind> for Error {
    fn from(kind: ErrorKind) -> Error {
        Error { kind }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            ErrorKind::Usage(m) => write!(f, "{m}"),
            ErrorKind::Io { path, source } => write!(f, "{}: {source}", path.display()),
            ErrorKind::MissingHostTool { tool, hint } => {
                write!(f, "host tool {tool} not found; {hint}")
            }
            ErrorKind::CommandFailed { command, status } => {
                write!(f, "running the following command failed ({status}):\n  {command}")
            }
            ErrorKind::Ocf { path, line, message } => {
                write!(f, "{}:{line}: ocf format error: {message}", path.display())
            }
            ErrorKind::LinkFailed { command, status, log } => {
                write!(f, "running the following command failed ({status}):\n  {command}")?;
                indented(f, "the linker said:", log)
            }
            ErrorKind::Undefined { output, references, log } => {
                write!(f, "cannot link {}:", output.display())?;
                for r in references {
                    write!(f, "\n  {r}")?;
                }
                write!(
                    f,
                    "\n  hint: no object, archive or library of the link defines {}; define {}, add the object or \
                           archive that does (libraries, -lNAME, after the objects that use them), or check the \
                           spelling and parameter types of the declaration",
                    if references.len() == 1 { "it" } else { "them" },
                    if references.len() == 1 { "it" } else { "them" }
                )?;
                indented(f, "the linker said:", log)
            }
            ErrorKind::BadObject { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

/// `title` and `text` indented under it, when there is text.
fn indented(f: &mut fmt::Formatter<'_>, title: &str, text: &str) -> fmt::Result {
    if text.trim().is_empty() {
        return Ok(());
    }
    write!(f, "\n  {title}")?;
    for line in text.trim_end().lines() {
        write!(f, "\n    {line}")?;
    }
    Ok(())
}

impl std::error::Error for Error {}
