//! Error paths not covered by the `testdata/stubcfg/bad` fixtures: input files, empty
//! input, hand-built configurations given to `generate`, and write failures.

use std::path::{Path, PathBuf};

use stubgen::{generate, parse_files, parse_str, write_outputs, ErrorKind, Service, ServiceKind, StubCfg};

const MIN: &str = "ObjectName : Obj
NumOfOSubject : 1
NumOfOObserver : 1
Service : \"Obj.Sub.char.S\", null, null
Service : \"Obj.Obs.char.O\", null, null
";

#[test]
fn missing_file() {
    let p = PathBuf::from("/nonexistent/dir/stub.cfg");
    let e = parse_files(std::slice::from_ref(&p)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Read);
    assert_eq!(e.file(), Some(p.as_path()));
    assert_eq!(e.line(), None);
    assert!(e.to_string().starts_with("/nonexistent/dir/stub.cfg: cannot read: No such file or directory"), "{e}");
    assert!(std::error::Error::source(&e).is_some());
}

#[test]
fn directory_instead_of_file() {
    let dir = tempfile::tempdir().unwrap();
    let e = parse_files(&[dir.path().to_path_buf()]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Read);
    assert!(e.to_string().starts_with(&format!("{}: cannot read: ", dir.path().display())), "{e}");
}

#[test]
fn second_file_missing() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.cfg");
    std::fs::write(&a, MIN).unwrap();
    let b = dir.path().join("b.cfg");
    let e = parse_files(&[a, b.clone()]).unwrap_err();
    assert_eq!((e.kind(), e.file()), (ErrorKind::Read, Some(b.as_path())));
}

#[test]
fn no_input_files() {
    let e = parse_files(&[]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::NoInput);
    assert_eq!(e.to_string(), "no stub.cfg file given");
}

#[test]
fn empty_and_blank_texts() {
    for text in ["", "\n", " \t\r\n\r\n"] {
        let e = parse_str("stub.cfg", text).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::EmptyFile);
        assert!(e.to_string().starts_with("stub.cfg:1: empty stub.cfg"), "{e}");
    }
}

#[test]
fn an_empty_file_among_several_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.cfg");
    let b = dir.path().join("b.cfg");
    std::fs::write(&a, MIN).unwrap();
    std::fs::write(&b, "").unwrap();
    let e = parse_files(&[a, b.clone()]).unwrap_err();
    assert_eq!((e.kind(), e.file(), e.line()), (ErrorKind::EmptyFile, Some(b.as_path()), Some(1)));
}

#[test]
fn comment_only_file_has_no_object_name_and_no_counts() {
    let e = parse_str("c.cfg", "// nothing\n// here\n").unwrap_err();
    assert_eq!(e.to_string(), "c.cfg:2: At least one Subject-Service should be specified. (no NumOfOSubject line)");
}

#[test]
fn missing_object_name_points_at_the_last_line() {
    let text = MIN.replace("ObjectName : Obj\n", "") + "\n// trailing\n";
    let e = parse_str("s.cfg", &text).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::NoObjectName);
    assert_eq!(e.to_string(), "s.cfg:6: no ObjectName line: expected 'ObjectName : <ClassName>'");
}

#[test]
fn sony_errors_come_before_our_object_name_check() {
    // Sony reports the count problem even when ObjectName is missing too.
    let e = parse_str("s.cfg", "NumOfOSubject : 1\n").unwrap_err();
    assert_eq!(e.kind(), ErrorKind::SubjectCountMismatch);
}

#[test]
fn object_name_keyword_is_rejected() {
    let e = parse_str("s.cfg", &MIN.replace("ObjectName : Obj", "ObjectName : class")).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidObjectName);
}

#[test]
fn extra_numbered_stub_names_are_reserved() {
    for name in ["Control0", "Ready1", "Connect2", "Notify3", "hookstub0", "notifystub9", "Destroy"] {
        let e = parse_str("s.cfg", &format!("{MIN}Extra : {name}()\n")).unwrap_err();
        assert_eq!((e.kind(), e.line()), (ErrorKind::InvalidExtraName, Some(6)), "{name}");
    }
}

fn service(kind: ServiceKind, sub: &str) -> Service {
    let letter = if kind == ServiceKind::Subject { 'S' } else { 'O' };
    Service {
        name: format!("Obj.{sub}.char.{letter}"),
        sub_name: sub.to_owned(),
        data_name: "char".to_owned(),
        func1: None,
        func2: None,
        kind,
        line: 7,
        file: PathBuf::from("built.cfg"),
    }
}

fn built() -> StubCfg {
    StubCfg {
        object_name: "Obj".to_owned(),
        subjects: vec![service(ServiceKind::Subject, "Sub")],
        observers: vec![service(ServiceKind::Observer, "Obs")],
        extras: vec![],
    }
}

#[test]
fn generate_accepts_a_hand_built_config() {
    assert_eq!(generate(&built()).unwrap().len(), 4);
    // A SubName used twice is accepted (as by Sony's tool), with a warning.
    let mut cfg = built();
    cfg.observers.push(service(ServiceKind::Observer, "Obs"));
    assert_eq!(generate(&cfg).unwrap().len(), 4);
    assert_eq!(stubgen::warnings(&cfg).len(), 1);
}

#[test]
fn generate_revalidates_hand_built_configs() {
    let check = |f: &dyn Fn(&mut StubCfg), kind: ErrorKind| {
        let mut cfg = built();
        f(&mut cfg);
        let e = generate(&cfg).unwrap_err();
        assert_eq!(e.kind(), kind, "{e}");
    };
    check(&|c| c.object_name.clear(), ErrorKind::NoObjectName);
    check(&|c| c.object_name = "a b".into(), ErrorKind::InvalidObjectName);
    check(&|c| c.subjects.clear(), ErrorKind::NoSubject);
    check(&|c| c.observers.clear(), ErrorKind::NoObserver);
    check(&|c| c.subjects[0].sub_name = "a.b".into(), ErrorKind::InvalidSubName);
    check(&|c| c.subjects[0].sub_name.clear(), ErrorKind::InvalidSubName);
    check(&|c| c.subjects[0].name = "with \"quote\"".into(), ErrorKind::InvalidServiceName);
    check(&|c| c.subjects[0].name = "tab\there".into(), ErrorKind::InvalidServiceName);
    check(&|c| c.observers[0].func2 = Some("Notify()".into()), ErrorKind::InvalidFunctionName);
    check(&|c| c.extras = vec!["a-b".into()], ErrorKind::InvalidExtraName);
    check(&|c| c.extras = vec!["Init".into()], ErrorKind::InvalidExtraName);
    check(&|c| c.extras = vec!["A".into(), "A".into()], ErrorKind::DuplicateExtra);
    check(&|c| c.extras = vec!["A".into(), "Astub".into()], ErrorKind::DuplicateExtra);

    let mut cfg = built();
    cfg.subjects[0].sub_name = "x y".into();
    assert!(generate(&cfg).unwrap_err().to_string().starts_with("built.cfg:7: SubName 'x y'"));
}

#[test]
fn write_into_missing_directory() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nope");
    let e = write_outputs(&built(), &missing).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Write);
    assert_eq!(e.file(), Some(missing.join("def.h").as_path()));
    assert!(e.to_string().contains(": cannot write: "), "{e}");
}

#[test]
fn failed_write_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    // A directory where ObjStub.cc should go makes the final rename fail.
    std::fs::create_dir(dir.path().join("ObjStub.cc")).unwrap();
    std::fs::write(dir.path().join("ObjStub.cc/keep"), "x").unwrap();
    let e = write_outputs(&built(), dir.path()).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Write);
    assert_eq!(names_in(dir.path()), ["ObjStub.cc"]);
}

#[test]
fn an_output_directory_that_is_a_file_fails_on_the_first_file_and_is_untouched() {
    // Unlike a read-only directory (which root, the CI user, writes anyway), a regular
    // file in the directory's place stops every user at the first file.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::write(&out, "not a directory").unwrap();
    let e = write_outputs(&built(), &out).unwrap_err();
    assert_eq!((e.kind(), e.file()), (ErrorKind::Write, Some(out.join("def.h").as_path())));
    assert!(e.to_string().contains(": cannot write: "), "{e}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "not a directory");
    assert_eq!(names_in(dir.path()), ["out"]);
}

#[test]
fn write_outputs_writes_the_four_files() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("entry.h"), "old contents").unwrap();
    let written = write_outputs(&built(), dir.path()).unwrap();
    let expected: Vec<PathBuf> = ["def.h", "entry.h", "ObjStub.h", "ObjStub.cc"].iter().map(|n| dir.path().join(n)).collect();
    assert_eq!(written, expected);
    assert_eq!(names_in(dir.path()), ["ObjStub.cc", "ObjStub.h", "def.h", "entry.h"]);
    let gen = generate(&built()).unwrap();
    for (name, text) in gen {
        assert_eq!(std::fs::read_to_string(dir.path().join(name)).unwrap(), text);
    }
}

fn names_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}
