//! The `stubgen2` command as a function: `run_stubgen2`.

use std::ffi::OsString;
use std::path::Path;

use stubgen::run_stubgen2;

fn run(args: &[&str], cwd: &Path) -> (i32, String, String) {
    let args: Vec<OsString> = args.iter().map(OsString::from).collect();
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = run_stubgen2(&args, cwd, &mut out, &mut err);
    (code, String::from_utf8(out).unwrap(), String::from_utf8(err).unwrap())
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

const CFG: &str = "ObjectName : SampleSubject
NumOfOSubject : 2
NumOfOObserver : 1
Service : \"SampleSubject.SendString.char.S\", null, Ready()
Service : \"SampleSubject.In.char.O\", Connect(), Notify()
Service : \"SampleSubject.Other.char.S\", Control(), null
Extra : UpdatePowerStatus()
Extra : Second()
";

#[test]
fn success_prints_the_summary_and_writes_into_cwd() {
    let dir = tempfile::tempdir().unwrap();
    let cwd = dir.path().join("robot");
    std::fs::create_dir(&cwd).unwrap();
    std::fs::write(dir.path().join("stub.cfg"), CFG).unwrap();
    let (code, out, err) = run(&["../stub.cfg"], &cwd);
    assert_eq!((code, err.as_str()), (0, ""));
    assert_eq!(
        out,
        "Object = SampleSubject\n\
         numOfSubject  = 2\n\
         numOfObserver = 1\n\
         Service name = \"SampleSubject.SendString.char.S\"\n\
         \x20   Control Function = null\n\
         \x20   Ready Function   = Ready\n\
         Service name = \"SampleSubject.Other.char.S\"\n\
         \x20   Control Function = Control\n\
         \x20   Ready Function   = null\n\
         Service name = \"SampleSubject.In.char.O\"\n\
         \x20   Connect Function = Connect\n\
         \x20   Notify Function  = Notify\n\
         Extra function = UpdatePowerStatus\n\
         Extra function = Second\n"
    );
    // Outputs go to cwd, not next to the input.
    assert_eq!(files_in(&cwd), ["SampleSubjectStub.cc", "SampleSubjectStub.h", "def.h", "entry.h"]);
    assert_eq!(files_in(dir.path()), ["robot", "stub.cfg"]);
    let cfg = stubgen::parse_str("x", CFG).unwrap();
    assert_eq!(out, stubgen::summary(&cfg));
}

#[test]
fn existing_outputs_are_overwritten() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("stub.cfg"), CFG).unwrap();
    std::fs::write(dir.path().join("def.h"), "stale").unwrap();
    let (code, _, _) = run(&["stub.cfg"], dir.path());
    assert_eq!(code, 0);
    assert!(std::fs::read_to_string(dir.path().join("def.h")).unwrap().contains("sbjSendString"));
}

#[test]
fn error_writes_nothing_and_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let bad = CFG.replace("NumOfOSubject : 2", "NumOfOSubject : 3");
    std::fs::write(dir.path().join("stub.cfg"), bad).unwrap();
    std::fs::write(dir.path().join("def.h"), "previous").unwrap();
    let (code, out, err) = run(&["stub.cfg"], dir.path());
    assert_eq!(code, 1);
    assert_eq!(out, "");
    assert!(err.starts_with("stubgen2: stub.cfg:2: Inconsitency found between service and numOfOSubject."), "{err}");
    assert!(err.ends_with('\n') && err.lines().count() == 1, "{err}");
    assert_eq!(files_in(dir.path()), ["def.h", "stub.cfg"]);
    assert_eq!(std::fs::read_to_string(dir.path().join("def.h")).unwrap(), "previous");
}

#[test]
fn unreadable_file_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let (code, out, err) = run(&["missing.cfg"], dir.path());
    assert_eq!((code, out.as_str()), (1, ""));
    assert!(err.starts_with("stubgen2: missing.cfg: cannot read: "), "{err}");
}

#[test]
fn several_files_are_concatenated() {
    let dir = tempfile::tempdir().unwrap();
    let (head, tail) = CFG.split_at(CFG.find("Service").unwrap());
    std::fs::write(dir.path().join("a.cfg"), head).unwrap();
    std::fs::write(dir.path().join("b.cfg"), tail).unwrap();
    let (code, out, err) = run(&["a.cfg", "b.cfg"], dir.path());
    assert_eq!((code, err.as_str()), (0, ""), "{out}");
    assert!(dir.path().join("SampleSubjectStub.cc").is_file());
}

#[test]
fn absolute_paths_work() {
    let dir = tempfile::tempdir().unwrap();
    let cfg = dir.path().join("stub.cfg");
    std::fs::write(&cfg, CFG).unwrap();
    let out_dir = tempfile::tempdir().unwrap();
    let (code, _, err) = run(&[cfg.to_str().unwrap()], out_dir.path());
    assert_eq!((code, err.as_str()), (0, ""));
    assert_eq!(files_in(out_dir.path()).len(), 4);
}

#[test]
fn no_arguments_prints_usage_and_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let (code, out, err) = run(&[], dir.path());
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("usage: stubgen2 <stub.cfg>"), "{err}");
    assert!(files_in(dir.path()).is_empty());
}

#[test]
fn help() {
    let dir = tempfile::tempdir().unwrap();
    for h in ["-h", "--help"] {
        let (code, out, err) = run(&[h], dir.path());
        assert_eq!((code, err.as_str()), (0, ""));
        assert!(out.starts_with("usage: stubgen2"));
    }
}

#[test]
fn write_failure_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("stub.cfg"), CFG).unwrap();
    std::fs::create_dir(dir.path().join("entry.h")).unwrap();
    std::fs::write(dir.path().join("entry.h/x"), "").unwrap();
    let (code, out, err) = run(&["stub.cfg"], dir.path());
    assert_eq!((code, out.as_str()), (1, ""));
    assert!(err.contains("entry.h: cannot write: is a directory"), "{err}");
    assert_eq!(files_in(dir.path()), ["entry.h", "stub.cfg"]);
}

#[test]
fn a_repeated_subname_is_a_warning_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let text = CFG.replace("SampleSubject.Other.char.S", "SampleSubject.SendString.int.S");
    std::fs::write(dir.path().join("stub.cfg"), text).unwrap();
    let (code, out, err) = run(&["stub.cfg"], dir.path());
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("Object = SampleSubject\n"), "{out}");
    assert!(err.starts_with("stubgen2: stub.cfg:6: warning: SubName 'SendString' is already used by the subject service on stub.cfg:4;"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    // def.h keeps Sony's two definition lines; the second is compiled under another name.
    let def = std::fs::read_to_string(dir.path().join("def.h")).unwrap();
    assert!(def.contains("const int sbjSendString = 0;\n"), "{def}");
    assert!(def.contains("#define sbjSendString openr_repeated_sbjSendString_1\nconst int sbjSendString = 1;\n#undef sbjSendString\n"), "{def}");
}

/// `CFG` with ObjectName and the first subject's SubName replaced.
fn cfg_named(object: &str, sub: &str) -> String {
    CFG.replace("ObjectName : SampleSubject", &format!("ObjectName : {object}")).replace("SampleSubject.SendString.", &format!("SampleSubject.{sub}."))
}

#[test]
fn an_object_name_too_long_for_a_file_name_is_an_error_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let long = "A".repeat(300);
    std::fs::write(dir.path().join("stub.cfg"), format!("# x\n{}", cfg_named(&long, "S"))).unwrap();
    let (code, out, err) = run(&["stub.cfg"], dir.path());
    assert_eq!((code, out.as_str()), (1, ""));
    assert_eq!(
        err,
        "stubgen2: stub.cfg:2: ObjectName 'AAAAAAAAAAAAAAAA…' is 300 characters long: the file \
         <ObjectName>Stub.cc stubgen2 writes would pass the file-name limit of 255 bytes (at most 248 characters)\n"
    );
    assert_eq!(files_in(dir.path()), ["stub.cfg"]);
    // The longest name that fits is written (and its temporary files fit too).
    let longest = "B".repeat(248);
    std::fs::write(dir.path().join("stub.cfg"), cfg_named(&longest, "S")).unwrap();
    let (code, _, err) = run(&["stub.cfg"], dir.path());
    assert_eq!(code, 0, "{err}");
    assert!(files_in(dir.path()).contains(&format!("{longest}Stub.cc")));
    let one_more = "C".repeat(249);
    std::fs::write(dir.path().join("stub.cfg"), cfg_named(&one_more, "S")).unwrap();
    let (code, _, err) = run(&["stub.cfg"], dir.path());
    assert_eq!(code, 1);
    assert!(err.contains("is 249 characters long"), "{err}");
}

#[test]
fn a_service_name_past_oservice_name_max_is_an_error_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    // "SampleSubject." + sub + ".char.S" is 127 characters: accepted; 128 is not.
    let fits = "S".repeat(127 - "SampleSubject..char.S".len());
    std::fs::write(dir.path().join("stub.cfg"), cfg_named("SampleSubject", &fits)).unwrap();
    let (code, _, err) = run(&["stub.cfg"], dir.path());
    assert_eq!(code, 0, "{err}");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("stub.cfg"), cfg_named("SampleSubject", &format!("{fits}T"))).unwrap();
    let (code, out, err) = run(&["stub.cfg"], dir.path());
    assert_eq!((code, out.as_str()), (1, ""));
    assert!(
        err.starts_with("stubgen2: stub.cfg:4: service name \"SampleSubject.SSSSSSSSSSSSSSSSSS…\" is 128 characters long; OPEN-R service names have at most 127 (oserviceNAME_MAX)\n"),
        "{err}"
    );
    assert_eq!(files_in(dir.path()), ["stub.cfg"]);
}
