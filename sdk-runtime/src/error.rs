//! Errors of the runtime: each names the file (and line) the user has to fix.
use std::fmt;
use std::path::PathBuf;

#[derive(Debug)]
pub struct Error {
    kind: ErrorKind,
}

#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A configuration file is malformed or names something that does not exist.
    Config { path: PathBuf, line: Option<usize>, message: String },
    /// A file could not be read.
    Io { path: PathBuf, source: std::io::Error },
    /// An object could not be loaded.
    Load { path: PathBuf, message: String },
    /// The runtime itself could not start (threads, temp files, signals).
    Runtime(String),
}

impl Error {
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }
    pub(crate) fn config(path: impl Into<PathBuf>, line: Option<usize>, message: impl Into<String>) -> Error {
        ErrorKind::Config { path: path.into(), line, message: message.into() }.into()
    }
    pub(crate) fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Error {
        ErrorKind::Io { path: path.into(), source }.into()
    }
    pub(crate) fn load(path: impl Into<PathBuf>, message: impl Into<String>) -> Error {
        ErrorKind::Load { path: path.into(), message: message.into() }.into()
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
            ErrorKind::Config { path, line: Some(l), message } => write!(f, "{}:{l}: {message}", path.display()),
            ErrorKind::Config { path, line: None, message } => write!(f, "{}: {message}", path.display()),
            ErrorKind::Io { path, source } => write!(f, "{}: {source}", path.display()),
            ErrorKind::Load { path, message } => write!(f, "{}: {message}", path.display()),
            ErrorKind::Runtime(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Error {}

pub type Result<T, E = Error> = std::result::Result<T, E>;
