//! The error type of the parser and generator.

use std::fmt;
use std::path::{Path, PathBuf};

/// What went wrong. New kinds may be added, so match with a `_` arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// No input file was given.
    NoInput,
    /// An input file could not be read (missing, a directory, no permission...).
    Read,
    /// An input file is empty or holds only blanks and line ends.
    EmptyFile,
    /// A `Service` function field is neither `null` nor `Name()`
    /// (Sony: `Missing () for function name.`).
    MissingFunctionParens,
    /// A function field ends in `()` but the name before it is not a C identifier.
    InvalidFunctionName,
    /// The `Extra` token does not end in `()` (Sony: `Missing () for extra-function name.`).
    MissingExtraParens,
    /// The `Extra` name is not a C identifier or collides with a generated stub name.
    InvalidExtraName,
    /// The same `Extra` name is given twice.
    DuplicateExtra,
    /// The SubName (2nd part of a service name) is not made of C identifier characters.
    InvalidSubName,
    /// The service name contains characters that cannot go into a C string literal.
    InvalidServiceName,
    /// Declared subject count is 0, absent or not a number
    /// (Sony: `At least one Subject-Service should be specified.`).
    NoSubject,
    /// Declared subject count differs from the number of accepted `S` services
    /// (Sony: `Inconsitency found between service and numOfOSubject.`).
    SubjectCountMismatch,
    /// Declared observer count is 0, absent or not a number
    /// (Sony: `At least one Observer-Service should be specified.`).
    NoObserver,
    /// Declared observer count differs from the number of accepted `O` services
    /// (Sony: `Inconsitency found between service and numOfOObserver.`).
    ObserverCountMismatch,
    /// No `ObjectName` line (or an empty one). Sony's tool accepted this and wrote
    /// uncompilable output; we refuse.
    NoObjectName,
    /// The `ObjectName` value is not a C identifier.
    InvalidObjectName,
    /// A handlebars template failed to render (a bug in this crate).
    Template,
    /// An output file could not be written.
    Write,
}

/// An error with the place it refers to.
///
/// `Display` gives `<file>:<line>: <message>` when a line is known, `<file>: <message>`
/// when only the file is known, and the bare message otherwise.
#[derive(Debug)]
pub struct Error {
    kind: ErrorKind,
    file: Option<PathBuf>,
    line: Option<usize>,
    message: String,
    source: Option<std::io::Error>,
}

impl Error {
    pub(crate) fn at(kind: ErrorKind, file: &Path, line: usize, message: impl Into<String>) -> Self {
        Error { kind, file: Some(file.to_path_buf()), line: Some(line), message: message.into(), source: None }
    }

    pub(crate) fn io(kind: ErrorKind, file: &Path, what: &str, err: std::io::Error) -> Self {
        Error { kind, file: Some(file.to_path_buf()), line: None, message: format!("{what}: {err}"), source: Some(err) }
    }

    pub(crate) fn bare(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error { kind, file: None, line: None, message: message.into(), source: None }
    }

    /// The kind of error.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// The file the error refers to, if any.
    pub fn file(&self) -> Option<&Path> {
        self.file.as_deref()
    }

    /// The 1-based line number the error refers to, if any.
    pub fn line(&self) -> Option<usize> {
        self.line
    }

    /// The message without the `<file>:<line>: ` prefix.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.file, self.line) {
            (Some(file), Some(line)) => write!(f, "{}:{}: {}", file.display(), line, self.message),
            (Some(file), None) => write!(f, "{}: {}", file.display(), self.message),
            _ => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.source.as_ref().map(|e| e as &(dyn std::error::Error + 'static))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_forms() {
        let e = Error::at(ErrorKind::NoSubject, Path::new("a/stub.cfg"), 3, "msg");
        assert_eq!(e.to_string(), "a/stub.cfg:3: msg");
        assert_eq!(e.kind(), ErrorKind::NoSubject);
        assert_eq!(e.line(), Some(3));
        assert_eq!(e.file(), Some(Path::new("a/stub.cfg")));
        assert_eq!(e.message(), "msg");
        let io = std::io::Error::new(std::io::ErrorKind::NotFound, "gone");
        let e = Error::io(ErrorKind::Read, Path::new("x.cfg"), "cannot read", io);
        assert_eq!(e.to_string(), "x.cfg: cannot read: gone");
        assert!(std::error::Error::source(&e).is_some());
        let e = Error::bare(ErrorKind::NoInput, "no input");
        assert_eq!(e.to_string(), "no input");
        assert!(std::error::Error::source(&e).is_none());
    }
}
