//! The `stub.cfg` parser (object-model 1.1).

use std::path::{Path, PathBuf};

use crate::error::{Error, ErrorKind};

/// Sony's message texts (spelling kept on purpose).
pub(crate) mod msg {
    pub const MISSING_FUNC_PARENS: &str = "Missing () for function name.";
    pub const MISSING_EXTRA_PARENS: &str = "Missing () for extra-function name.";
    pub const NO_SUBJECT: &str = "At least one Subject-Service should be specified.";
    pub const NO_OBSERVER: &str = "At least one Observer-Service should be specified.";
    pub const SUBJECT_MISMATCH: &str = "Inconsitency found between service and numOfOSubject.";
    pub const OBSERVER_MISMATCH: &str = "Inconsitency found between service and numOfOObserver.";
}

/// Whether a service is a subject (`S`, sending side) or an observer (`O`, receiving side).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ServiceKind {
    /// `"...S"`: a subject service.
    Subject,
    /// `"...O"`: an observer service.
    Observer,
}

/// One accepted `Service` line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Service {
    /// The full service name without the quotes, e.g. `SampleSubject.SendString.char.S`.
    pub name: String,
    /// 2nd part of the name; gives the index constant `sbj<SubName>` / `obs<SubName>`.
    pub sub_name: String,
    /// 3rd part of the name (data type name, informative only).
    pub data_name: String,
    /// Function field 1: Control function (subject) or Connect function (observer).
    pub func1: Option<String>,
    /// Function field 2: Ready function (subject) or Notify function (observer).
    pub func2: Option<String>,
    /// Subject or observer.
    pub kind: ServiceKind,
    /// 1-based line number of the `Service` line in [`Service::file`].
    pub line: usize,
    /// The file the line comes from, as it was named by the caller.
    pub file: PathBuf,
}

/// The contents of one or more concatenated `stub.cfg` files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StubCfg {
    /// C++ class name of the core class (`ObjectName`).
    pub object_name: String,
    /// Subject services in file order (their position is the subject index).
    pub subjects: Vec<Service>,
    /// Observer services in file order (their position is the observer index).
    pub observers: Vec<Service>,
    /// Extra entry point names (without `()`), in file order.
    pub extras: Vec<String>,
}

/// Read and parse `stub.cfg` files; all are concatenated in the given order.
///
/// Errors name the file as it appears in `paths`.
pub fn parse_files(paths: &[PathBuf]) -> Result<StubCfg, Error> {
    let named: Vec<(PathBuf, PathBuf)> = paths.iter().map(|p| (p.clone(), p.clone())).collect();
    parse_named_files(&named)
}

/// Like [`parse_files`], but each entry is `(name used in messages, path to open)`.
pub(crate) fn parse_named_files(files: &[(PathBuf, PathBuf)]) -> Result<StubCfg, Error> {
    if files.is_empty() {
        return Err(Error::bare(ErrorKind::NoInput, "no stub.cfg file given"));
    }
    let mut sources = Vec::with_capacity(files.len());
    for (name, path) in files {
        let bytes = std::fs::read(path).map_err(|e| Error::io(ErrorKind::Read, name, "cannot read", e))?;
        sources.push((name.clone(), bytes));
    }
    parse_sources(&sources)
}

/// Parse one `stub.cfg` given as text; `name` is used in error messages.
pub fn parse_str(name: &str, text: &str) -> Result<StubCfg, Error> {
    parse_sources(&[(PathBuf::from(name), text.as_bytes().to_vec())])
}

const BLANKS: [char; 2] = [' ', '\t'];

/// The longest file name Linux file systems take (`NAME_MAX`).
const NAME_MAX: usize = 255;
/// `<ObjectName>Stub.cc` must fit in a file name.
const MAX_OBJECT_NAME: usize = NAME_MAX - "Stub.cc".len();
/// `oserviceNAME_MAX` of OPENR.h: the name buffers of the object model end there.
const MAX_SERVICE_NAME: usize = 127;

#[derive(Clone, Copy)]
enum Keyword {
    ObjectName,
    NumOfSubject,
    NumOfObserver,
    Service,
    Extra,
}

const KEYWORDS: [(&str, Keyword); 7] = [
    ("ObjectName", Keyword::ObjectName),
    ("NumOfOSubject", Keyword::NumOfSubject),
    ("NumOfSubject", Keyword::NumOfSubject),
    ("NumOfOObserver", Keyword::NumOfObserver),
    ("NumOfObserver", Keyword::NumOfObserver),
    ("Service", Keyword::Service),
    ("Extra", Keyword::Extra),
];

/// Recognise a keyword line: optional blanks, keyword, optional blanks, `:`.
/// Returns the keyword and the text after the colon.
fn keyword(line: &str) -> Option<(Keyword, &str)> {
    let t = line.trim_start_matches(BLANKS);
    KEYWORDS.iter().find_map(|&(word, kw)| {
        let rest = t.strip_prefix(word)?.trim_start_matches(BLANKS);
        rest.strip_prefix(':').map(|value| (kw, value))
    })
}

fn first_token(s: &str) -> Option<&str> {
    s.split(BLANKS).find(|t| !t.is_empty())
}

/// Where a line is: file and 1-based line number.
#[derive(Clone)]
struct Loc<'a> {
    file: &'a Path,
    line: usize,
}

impl Loc<'_> {
    fn err(&self, kind: ErrorKind, message: impl Into<String>) -> Error {
        Error::at(kind, self.file, self.line, message)
    }
}

/// A declared count (`NumOfOSubject : <token>`).
enum Count {
    Number(usize),
    Empty,
    NotNumber(String),
}

struct Declared<'a, T> {
    value: T,
    loc: Loc<'a>,
}

#[derive(Default)]
struct State<'a> {
    object_name: Option<Declared<'a, Option<String>>>,
    num_subject: Option<Declared<'a, Count>>,
    num_observer: Option<Declared<'a, Count>>,
    subjects: Vec<Service>,
    observers: Vec<Service>,
    extras: Vec<Declared<'a, String>>,
}

/// Split into lines at LF and delete every CR (and LF) of each line.
fn lines(bytes: &[u8]) -> impl Iterator<Item = String> + '_ {
    let body = bytes.strip_suffix(b"\n").unwrap_or(bytes);
    body.split(|&b| b == b'\n').map(|l| {
        let l: Vec<u8> = l.iter().copied().filter(|&b| b != b'\r').collect();
        String::from_utf8_lossy(&l).into_owned()
    })
}

fn line_count(bytes: &[u8]) -> usize {
    lines(bytes).count()
}

pub(crate) fn parse_sources(sources: &[(PathBuf, Vec<u8>)]) -> Result<StubCfg, Error> {
    let Some((last_file, last_bytes)) = sources.last() else {
        return Err(Error::bare(ErrorKind::NoInput, "no stub.cfg file given"));
    };
    for (file, bytes) in sources {
        if bytes.iter().all(|b| b.is_ascii_whitespace()) {
            return Err(Error::at(
                ErrorKind::EmptyFile,
                file,
                1,
                "empty stub.cfg: expected at least 'ObjectName', 'NumOfOSubject', 'NumOfOObserver' and 'Service' lines",
            ));
        }
    }

    let mut st = State::default();
    for (file, bytes) in sources {
        for (i, text) in lines(bytes).enumerate() {
            let loc = Loc { file, line: i + 1 };
            if let Some((kw, value)) = keyword(&text) {
                parse_keyword_line(&mut st, kw, value, loc)?;
            }
        }
    }

    let end = Loc { file: last_file, line: line_count(last_bytes).max(1) };
    check_count(&st.num_subject, st.subjects.len(), &end, &SUBJECT_RULE)?;
    check_count(&st.num_observer, st.observers.len(), &end, &OBSERVER_RULE)?;

    let object_name = match st.object_name {
        None => return Err(end.err(ErrorKind::NoObjectName, "no ObjectName line: expected 'ObjectName : <ClassName>'")),
        Some(Declared { value: None, loc }) => return Err(loc.err(ErrorKind::NoObjectName, "ObjectName has no value: expected 'ObjectName : <ClassName>'")),
        Some(Declared { value: Some(name), loc }) => {
            if !is_c_identifier(&name) {
                return Err(loc.err(ErrorKind::InvalidObjectName, format!("ObjectName '{name}' is not a valid C++ class name")));
            }
            if name.len() > MAX_OBJECT_NAME {
                return Err(loc.err(
                    ErrorKind::InvalidObjectName,
                    format!(
                        "ObjectName '{}…' is {} characters long: the file <ObjectName>Stub.cc \
                         stubgen2 writes would pass the file-name limit of {NAME_MAX} bytes \
                         (at most {MAX_OBJECT_NAME} characters)",
                        &name[..16],
                        name.len()
                    ),
                ));
            }
            name
        }
    };

    Ok(StubCfg { object_name, subjects: st.subjects, observers: st.observers, extras: st.extras.into_iter().map(|e| e.value).collect() })
}

/// How one of the two declared counts is checked.
struct CountRule {
    keyword: &'static str,
    what: &'static str,
    letter: char,
    none_kind: ErrorKind,
    none_msg: &'static str,
    mismatch_kind: ErrorKind,
    mismatch_msg: &'static str,
}

const SUBJECT_RULE: CountRule = CountRule {
    keyword: "NumOfOSubject",
    what: "subject",
    letter: 'S',
    none_kind: ErrorKind::NoSubject,
    none_msg: msg::NO_SUBJECT,
    mismatch_kind: ErrorKind::SubjectCountMismatch,
    mismatch_msg: msg::SUBJECT_MISMATCH,
};

const OBSERVER_RULE: CountRule = CountRule {
    keyword: "NumOfOObserver",
    what: "observer",
    letter: 'O',
    none_kind: ErrorKind::NoObserver,
    none_msg: msg::NO_OBSERVER,
    mismatch_kind: ErrorKind::ObserverCountMismatch,
    mismatch_msg: msg::OBSERVER_MISMATCH,
};

fn check_count(declared: &Option<Declared<'_, Count>>, accepted: usize, end: &Loc<'_>, rule: &CountRule) -> Result<(), Error> {
    let CountRule { keyword, what, letter, none_kind, none_msg, mismatch_kind, mismatch_msg } = *rule;
    let Some(Declared { value, loc }) = declared else {
        return Err(end.err(none_kind, format!("{none_msg} (no {keyword} line)")));
    };
    match value {
        Count::Empty => Err(loc.err(none_kind, format!("{none_msg} ({keyword} has no value)"))),
        Count::NotNumber(t) => Err(loc.err(none_kind, format!("{none_msg} ({keyword} value '{t}' is not a number)"))),
        Count::Number(0) => Err(loc.err(none_kind, format!("{none_msg} ({keyword} is 0)"))),
        Count::Number(n) if *n != accepted => Err(loc.err(
            mismatch_kind,
            format!(
                "{mismatch_msg} ({keyword} = {n}, but {accepted} {what} service(s) found; \
                 Service lines whose name is not \"<Obj>.<Sub>.<Data>.{letter}\" are ignored)"
            ),
        )),
        Count::Number(_) => Ok(()),
    }
}

fn parse_keyword_line<'a>(st: &mut State<'a>, kw: Keyword, value: &str, loc: Loc<'a>) -> Result<(), Error> {
    match kw {
        Keyword::ObjectName => {
            st.object_name = Some(Declared { value: first_token(value).map(str::to_owned), loc });
        }
        Keyword::NumOfSubject => st.num_subject = Some(Declared { value: count(value), loc }),
        Keyword::NumOfObserver => st.num_observer = Some(Declared { value: count(value), loc }),
        Keyword::Service => {
            if let Some(svc) = parse_service(value, &loc)? {
                let list = match svc.kind {
                    ServiceKind::Subject => &mut st.subjects,
                    ServiceKind::Observer => &mut st.observers,
                };
                // A SubName used twice is accepted, as Sony's tool did (see
                // generate::warnings): projects patched the generated def.h themselves.
                list.push(svc);
            }
        }
        Keyword::Extra => {
            let name = parse_extra(value, &loc)?;
            if let Some(prev) = st.extras.iter().find(|e| e.value == name || e.value == format!("{name}stub") || name == format!("{}stub", e.value)) {
                let detail = if prev.value == name {
                    format!("Extra '{name}' is given twice")
                } else {
                    format!("Extras '{}' and '{name}' give clashing entry names", prev.value)
                };
                return Err(loc.err(ErrorKind::DuplicateExtra, format!("{detail} (first on {}:{})", prev.loc.file.display(), prev.loc.line)));
            }
            st.extras.push(Declared { value: name, loc });
        }
    }
    Ok(())
}

/// A declared count, read like C's `atoi` on the first token (Sony's tool treats a
/// non-numeric value like 0): optional `+`, then the leading digits; anything after
/// them is ignored (`1;` is 1). No leading digit (including a `-` sign) = not a number.
fn count(value: &str) -> Count {
    let Some(token) = first_token(value) else {
        return Count::Empty;
    };
    let unsigned = token.strip_prefix('+').unwrap_or(token);
    let digits = unsigned.bytes().take_while(u8::is_ascii_digit).count();
    if digits == 0 {
        return Count::NotNumber(token.to_owned());
    }
    Count::Number(unsigned[..digits].parse().unwrap_or(usize::MAX))
}

/// Parse the text after `Service :`. `Ok(None)` = silently dropped (Sony's rule).
fn parse_service(value: &str, loc: &Loc<'_>) -> Result<Option<Service>, Error> {
    let fields: Vec<&str> = value.split(',').map(|f| f.trim_matches(BLANKS)).collect();
    let quoted = fields[0];
    let parts: Vec<&str> = quoted.split('.').collect();
    let kind = match parts.as_slice() {
        [first, _, _, "S\""] if first.starts_with('"') => ServiceKind::Subject,
        [first, _, _, "O\""] if first.starts_with('"') => ServiceKind::Observer,
        _ => return Ok(None),
    };
    let func1 = parse_function(fields.get(1).copied(), 1, loc)?;
    let func2 = parse_function(fields.get(2).copied(), 2, loc)?;

    let name = &quoted[1..quoted.len() - 1];
    if let Some(c) = name.chars().find(|&c| !(' '..='~').contains(&c) || c == '"' || c == '\\') {
        return Err(
            loc.err(ErrorKind::InvalidServiceName, format!("service name \"{name}\" contains {c:?}; only printable ASCII without '\"' and '\\' is allowed"))
        );
    }
    if name.len() > MAX_SERVICE_NAME {
        return Err(loc.err(
            ErrorKind::InvalidServiceName,
            format!(
                "service name \"{}…\" is {} characters long; OPEN-R service names have at most \
                 {MAX_SERVICE_NAME} (oserviceNAME_MAX)",
                &name[..32],
                name.len()
            ),
        ));
    }
    let sub_name = parts[1];
    if sub_name.is_empty() || !sub_name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
        let prefix = if kind == ServiceKind::Subject { "sbj" } else { "obs" };
        return Err(loc.err(
            ErrorKind::InvalidSubName,
            format!(
                "SubName '{sub_name}' of service \"{name}\" cannot form the C identifier '{prefix}{sub_name}' \
                 (use letters, digits and '_')"
            ),
        ));
    }
    Ok(Some(Service {
        name: name.to_owned(),
        sub_name: sub_name.to_owned(),
        data_name: parts[2].to_owned(),
        func1,
        func2,
        kind,
        line: loc.line,
        file: loc.file.to_path_buf(),
    }))
}

/// A function field: `null` or `Name()` (blanks before `()` allowed).
fn parse_function(field: Option<&str>, n: usize, loc: &Loc<'_>) -> Result<Option<String>, Error> {
    let Some(field) = field else {
        return Err(
            loc.err(ErrorKind::MissingFunctionParens, format!("{} (function field {n} is missing; write 'null' or 'Name()')", msg::MISSING_FUNC_PARENS))
        );
    };
    if field == "null" {
        return Ok(None);
    }
    let Some(name) = field.strip_suffix("()") else {
        return Err(
            loc.err(ErrorKind::MissingFunctionParens, format!("{} (function field {n} is '{field}'; write 'null' or 'Name()')", msg::MISSING_FUNC_PARENS))
        );
    };
    let name = name.trim_end_matches(BLANKS);
    if !is_c_identifier(name) {
        return Err(loc.err(ErrorKind::InvalidFunctionName, format!("function field {n} '{field}': '{name}' is not a valid C++ member function name")));
    }
    Ok(Some(name.to_owned()))
}

/// The text after `Extra :`: first blank-free token, must end in `()`.
fn parse_extra(value: &str, loc: &Loc<'_>) -> Result<String, Error> {
    let token = first_token(value).unwrap_or("");
    let Some(name) = token.strip_suffix("()") else {
        let detail = if token.is_empty() { "Extra has no value".to_owned() } else { format!("Extra token is '{token}'") };
        return Err(
            loc.err(ErrorKind::MissingExtraParens, format!("{} ({detail}; write 'Extra : Name()' with no blank before '()')", msg::MISSING_EXTRA_PARENS))
        );
    };
    if !is_c_identifier(name) {
        return Err(loc.err(ErrorKind::InvalidExtraName, format!("Extra '{token}': '{name}' is not a valid C++ member function name")));
    }
    if is_reserved_extra(name) {
        return Err(loc.err(ErrorKind::InvalidExtraName, format!("Extra '{token}': the C function '_{name}' would clash with a generated stub function")));
    }
    Ok(name.to_owned())
}

/// Names whose `_<Name>` / `_<Name>stub` would collide with names stubgen2 generates anyway.
pub(crate) fn is_reserved_extra(name: &str) -> bool {
    if matches!(name, "Init" | "Start" | "Stop" | "Destroy") {
        return true;
    }
    const NUMBERED: [&str; 9] = ["Control", "Ready", "Connect", "Notify", "hookstub", "controlstub", "readystub", "connectstub", "notifystub"];
    NUMBERED.iter().any(|p| name.strip_prefix(p).is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit())))
}

/// C++98 keywords (plus a few alternative tokens), which cannot name a class or member.
const CXX_KEYWORDS: &[&str] = &[
    "and",
    "and_eq",
    "asm",
    "auto",
    "bitand",
    "bitor",
    "bool",
    "break",
    "case",
    "catch",
    "char",
    "class",
    "compl",
    "const",
    "const_cast",
    "continue",
    "default",
    "delete",
    "do",
    "double",
    "dynamic_cast",
    "else",
    "enum",
    "explicit",
    "export",
    "extern",
    "false",
    "float",
    "for",
    "friend",
    "goto",
    "if",
    "inline",
    "int",
    "long",
    "mutable",
    "namespace",
    "new",
    "not",
    "not_eq",
    "operator",
    "or",
    "or_eq",
    "private",
    "protected",
    "public",
    "register",
    "reinterpret_cast",
    "return",
    "short",
    "signed",
    "sizeof",
    "static",
    "static_cast",
    "struct",
    "switch",
    "template",
    "this",
    "throw",
    "true",
    "try",
    "typedef",
    "typeid",
    "typename",
    "union",
    "unsigned",
    "using",
    "virtual",
    "void",
    "volatile",
    "wchar_t",
    "while",
    "xor",
    "xor_eq",
];

/// `[A-Za-z_][A-Za-z0-9_]*`, keywords included.
pub fn is_identifier(s: &str) -> bool {
    let mut bytes = s.bytes();
    matches!(bytes.next(), Some(b) if b.is_ascii_alphabetic() || b == b'_') && bytes.all(|b| b.is_ascii_alphanumeric() || b == b'_')
}

/// `[A-Za-z_][A-Za-z0-9_]*` and not a C++ keyword.
pub(crate) fn is_c_identifier(s: &str) -> bool {
    is_identifier(s) && !CXX_KEYWORDS.contains(&s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keyword_recognition() {
        assert!(matches!(keyword("ObjectName : X"), Some((Keyword::ObjectName, " X"))));
        assert!(matches!(keyword(" \tObjectName\t:X"), Some((Keyword::ObjectName, "X"))));
        assert!(matches!(keyword("NumOfSubject:1"), Some((Keyword::NumOfSubject, "1"))));
        assert!(matches!(keyword("NumOfOObserver :1"), Some((Keyword::NumOfObserver, "1"))));
        assert!(keyword("objectName : X").is_none());
        assert!(keyword("ObjectNameX : X").is_none());
        assert!(keyword("ObjectName X : X").is_none());
        assert!(keyword("#ObjectName : X").is_none());
        assert!(keyword("// Service : \"a.b.c.S\"").is_none());
        assert!(keyword("").is_none());
    }

    #[test]
    fn lines_strip_cr_anywhere() {
        let v: Vec<String> = lines(b"a\r\nb\rc\r\n\nd").collect();
        assert_eq!(v, ["a", "bc", "", "d"]);
        assert_eq!(line_count(b"a\nb\n"), 2);
        assert_eq!(line_count(b"a\nb"), 2);
        assert_eq!(line_count(b"a\nb\n\n"), 3);
    }

    #[test]
    fn identifiers() {
        assert!(is_c_identifier("Foo_1"));
        assert!(is_c_identifier("_x"));
        assert!(!is_c_identifier("1x"));
        assert!(!is_c_identifier(""));
        assert!(!is_c_identifier("a-b"));
        assert!(!is_c_identifier("class"));
        assert!(!is_c_identifier("Ü"));
    }

    #[test]
    fn reserved_extras() {
        for n in ["Init", "Destroy", "Control0", "Notify12", "hookstub3", "readystub0"] {
            assert!(is_reserved_extra(n), "{n}");
        }
        for n in ["Control", "ListenCont", "Initialize", "hookstub", "Ready1x"] {
            assert!(!is_reserved_extra(n), "{n}");
        }
    }

    #[test]
    fn function_fields() {
        let loc = Loc { file: Path::new("f"), line: 1 };
        assert_eq!(parse_function(Some("null"), 1, &loc).unwrap(), None);
        assert_eq!(parse_function(Some("Foo()"), 1, &loc).unwrap().as_deref(), Some("Foo"));
        assert_eq!(parse_function(Some("Foo \t()"), 1, &loc).unwrap().as_deref(), Some("Foo"));
        let e = parse_function(Some("NULL"), 2, &loc).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::MissingFunctionParens);
        let e = parse_function(None, 2, &loc).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::MissingFunctionParens);
        let e = parse_function(Some("()"), 2, &loc).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::InvalidFunctionName);
        let e = parse_function(Some("Foo Bar()"), 2, &loc).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::InvalidFunctionName);
    }
}
