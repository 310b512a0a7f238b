//! Lexical and syntactic rules of object-model 1.1, on inline texts.

use std::path::PathBuf;

use stubgen::{parse_files, parse_str, ErrorKind, ServiceKind};

const MIN: &str = "ObjectName : Obj
NumOfOSubject : 1
NumOfOObserver : 1
Service : \"Obj.Sub.char.S\", null, null
Service : \"Obj.Obs.char.O\", null, null
";

#[test]
fn minimal() {
    let cfg = parse_str("stub.cfg", MIN).unwrap();
    assert_eq!(cfg.object_name, "Obj");
    let s = &cfg.subjects[0];
    assert_eq!((s.name.as_str(), s.sub_name.as_str(), s.data_name.as_str()), ("Obj.Sub.char.S", "Sub", "char"));
    assert_eq!((s.func1.as_deref(), s.func2.as_deref()), (None, None));
    assert_eq!(s.kind, ServiceKind::Subject);
    assert_eq!((s.line, s.file.clone()), (4, PathBuf::from("stub.cfg")));
    assert_eq!(cfg.observers[0].kind, ServiceKind::Observer);
    assert_eq!(cfg.observers[0].line, 5);
    assert!(cfg.extras.is_empty());
}

#[test]
fn crlf_and_stray_cr_are_deleted() {
    let crlf = MIN.replace('\n', "\r\n");
    assert_eq!(parse_str("a", &crlf).unwrap(), parse_str("a", MIN).unwrap());
    // A CR in the middle of a line is deleted too.
    let text = MIN.replace("ObjectName : Obj", "ObjectName : O\rbj");
    assert_eq!(parse_str("a", &text).unwrap().object_name, "Obj");
    // No final line end.
    assert!(parse_str("a", MIN.trim_end()).is_ok());
}

#[test]
fn comments_and_unknown_lines_are_ignored() {
    let text = format!(
        "// comment\n# another\n\n   \nobjectname : lower\nNumOfFoo : 3\nService = \"Obj.X.c.S\", null, null\n\
         random text : with colon\n#ObjectName : Hidden\n// Service : \"Obj.Y.c.S\", null, null\n{MIN}# Extra : Foo()\n"
    );
    let cfg = parse_str("a", &text).unwrap();
    assert_eq!(cfg.object_name, "Obj");
    assert_eq!(cfg.subjects.len(), 1);
    assert!(cfg.extras.is_empty());
}

#[test]
fn keywords_are_case_sensitive_and_need_a_colon() {
    let text = format!("{MIN}extra : Foo()\nEXTRA : Bar()\nExtra Baz()\nExtras : Q()\n");
    assert!(parse_str("a", &text).unwrap().extras.is_empty());
}

#[test]
fn blanks_around_keyword_and_colon() {
    let text = "  \tObjectName\t \t:Obj\n\tNumOfOSubject:1\n NumOfOObserver   :   1\n\
                \t Service\t: \"Obj.Sub.char.S\" ,null ,  Ready ()  \nService:\"Obj.Obs.char.O\",\tnull\t,\tnull\t\n\
                  Extra\t:\tFoo()\tbar\n";
    let cfg = parse_str("a", text).unwrap();
    assert_eq!(cfg.object_name, "Obj");
    assert_eq!(cfg.subjects[0].func2.as_deref(), Some("Ready"));
    assert_eq!(cfg.extras, ["Foo"]);
}

#[test]
fn object_name_takes_the_first_token() {
    let text = MIN.replace("ObjectName : Obj", "ObjectName : Obj   and some words");
    assert_eq!(parse_str("a", &text).unwrap().object_name, "Obj");
}

#[test]
fn keyword_aliases() {
    let text = MIN.replace("NumOfOSubject", "NumOfSubject").replace("NumOfOObserver", "NumOfObserver");
    let cfg = parse_str("a", &text).unwrap();
    assert_eq!((cfg.subjects.len(), cfg.observers.len()), (1, 1));
    // Mixed: the alias and the full keyword set the same value; the last one wins.
    let text = format!("NumOfSubject : 7\n{MIN}");
    assert!(parse_str("a", &text).is_ok());
}

#[test]
fn last_value_wins_for_scalars() {
    let text = format!("ObjectName : First\nNumOfOSubject : 9\nNumOfObserver : 0\n{MIN}ObjectName : Last\n");
    let cfg = parse_str("a", &text).unwrap();
    assert_eq!(cfg.object_name, "Last");
    let text = format!("{MIN}NumOfOObserver : 2\nService : \"Obj.Obs2.char.O\", null, null\n");
    assert_eq!(parse_str("a", &text).unwrap().observers.len(), 2);
}

#[test]
fn counts_may_come_in_any_order_and_after_services() {
    let text = "Service : \"Obj.Obs.char.O\", null, null\nService : \"Obj.Sub.char.S\", null, null\n\
                NumOfOObserver : 1\nObjectName : Obj\nNumOfOSubject : 1 trailing words\n";
    assert!(parse_str("a", text).is_ok());
}

#[test]
fn interleaved_services_are_numbered_per_kind() {
    let text = "ObjectName : Obj\nNumOfOSubject : 2\nNumOfOObserver : 3\n\
        Service : \"Obj.O1.c.O\", null, null\n\
        Service : \"Obj.S1.c.S\", null, null\n\
        Service : \"Obj.O2.c.O\", null, null\n\
        Service : \"Obj.O3.c.O\", null, null\n\
        Service : \"Obj.S2.c.S\", null, null\n";
    let cfg = parse_str("a", text).unwrap();
    let s: Vec<_> = cfg.subjects.iter().map(|s| (s.sub_name.as_str(), s.line)).collect();
    let o: Vec<_> = cfg.observers.iter().map(|s| (s.sub_name.as_str(), s.line)).collect();
    assert_eq!(s, [("S1", 5), ("S2", 8)]);
    assert_eq!(o, [("O1", 4), ("O2", 6), ("O3", 7)]);
    let def = &stubgen::generate(&cfg).unwrap()[0].1;
    assert!(def.contains("const int sbjS2 = 1;"));
    assert!(def.contains("const int obsO3 = 2;"));
}

#[test]
fn the_same_sub_name_may_be_used_by_a_subject_and_an_observer() {
    let text = MIN.replace("Obj.Obs.char.O", "Obj.Sub.char.O");
    let cfg = parse_str("a", &text).unwrap();
    let def = &stubgen::generate(&cfg).unwrap()[0].1;
    assert!(def.contains("const int sbjSub = 0;") && def.contains("const int obsSub = 0;"));
}

#[test]
fn service_name_details() {
    // First part need not be the ObjectName; SubName may start with a digit (it is only a
    // fragment of "sbj<SubName>"); DataName may hold anything printable.
    let text = MIN
        .replace("Obj.Sub.char.S", "Other.3D.unsigned char [4].S")
        .replace("\"Obj.Obs.char.O\", null, null", "\"Obj.Obs.char.O\", null, null, extra, fields");
    let cfg = parse_str("a", &text).unwrap();
    assert_eq!(cfg.subjects[0].name, "Other.3D.unsigned char [4].S");
    assert_eq!(cfg.subjects[0].sub_name, "3D");
    assert_eq!(cfg.subjects[0].data_name, "unsigned char [4]");
    let def = &stubgen::generate(&cfg).unwrap()[0].1;
    assert!(def.contains("const int sbj3D = 0;"));
    assert!(def.contains("\"Other.3D.unsigned char [4].S\""));
}

#[test]
fn invalid_service_names_are_dropped_silently() {
    for bad in [
        "Obj.Sub.char.S",       // no quotes
        "\"Obj.Sub.char.s\"",   // lower-case type
        "\"Obj.Sub.char.x.S\"", // five parts
        "\"Obj.Sub.S\"",        // three parts
        "\"Obj.Sub.char.S \"",  // blank before the quote
        "\"Obj.Sub.char.SO\"",  // two letters
        "Obj.Sub.char.S\"",     // no opening quote
        "\"Obj.Sub,char.S\"",   // comma splits the name
        "",                     // nothing at all
    ] {
        let text = format!("{MIN}Service : {bad}, Foo, Bar\n");
        let cfg = parse_str("a", &text).unwrap_or_else(|e| panic!("{bad}: {e}"));
        assert_eq!((cfg.subjects.len(), cfg.observers.len()), (1, 1), "{bad}");
    }
}

#[test]
fn dropped_service_leads_to_count_mismatch() {
    let text = MIN.replace("Obj.Sub.char.S\"", "Obj.Sub.char.s\"");
    let e = parse_str("x.cfg", &text).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::SubjectCountMismatch);
    assert_eq!(e.line(), Some(2));
    assert!(e.to_string().starts_with("x.cfg:2: Inconsitency found between service and numOfOSubject."));
}

#[test]
fn function_fields() {
    let text = MIN.replace("\"Obj.Sub.char.S\", null, null", "\"Obj.Sub.char.S\", Ctl  (), Rdy()   ");
    let cfg = parse_str("a", &text).unwrap();
    assert_eq!(cfg.subjects[0].func1.as_deref(), Some("Ctl"));
    assert_eq!(cfg.subjects[0].func2.as_deref(), Some("Rdy"));
}

#[test]
fn extras_accumulate_in_file_order() {
    let text = format!("Extra : B()\n{MIN}Extra : A()\nExtra : C() // comment after the token\n");
    assert_eq!(parse_str("a", &text).unwrap().extras, ["B", "A", "C"]);
}

#[test]
fn non_utf8_comment_lines_are_harmless() {
    let mut bytes = b"// \x93\xfa\x96\x7b\x8c\xea (Shift-JIS comment)\n".to_vec();
    bytes.extend_from_slice(MIN.as_bytes());
    bytes.extend_from_slice(b"ObjectName : Obj // \xff\xfe\n");
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("stub.cfg");
    std::fs::write(&p, &bytes).unwrap();
    assert_eq!(parse_files(&[p]).unwrap().object_name, "Obj");
}

#[test]
fn multiple_files_are_concatenated() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.cfg");
    let b = dir.path().join("b.cfg");
    std::fs::write(&a, "ObjectName : Obj\nNumOfOSubject : 2\nService : \"Obj.S1.c.S\", null, null\n").unwrap();
    std::fs::write(&b, "// second file\nNumOfOObserver : 1\nService : \"Obj.O1.c.O\", null, null\nService : \"Obj.S2.c.S\", null, Ready()\nExtra : X()\n")
        .unwrap();
    let cfg = parse_files(&[a.clone(), b.clone()]).unwrap();
    assert_eq!(cfg.subjects.len(), 2);
    assert_eq!((cfg.subjects[0].file.clone(), cfg.subjects[0].line), (a.clone(), 3));
    assert_eq!((cfg.subjects[1].file.clone(), cfg.subjects[1].line), (b.clone(), 4));
    assert_eq!(cfg.extras, ["X"]);

    // Errors name the file and line in that file; "absent" counts point at the last line
    // of the last file.
    std::fs::write(&b, "Service : \"Obj.O1.c.O\", null, null\nService : \"Obj.S2.c.S\", null, null\n// end\n").unwrap();
    let e = parse_files(&[a.clone(), b.clone()]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::NoObserver);
    assert_eq!(e.to_string(), format!("{}:3: At least one Observer-Service should be specified. (no NumOfOObserver line)", b.display()));
    std::fs::write(&b, "NumOfOObserver : 1\nService : \"Obj.O1.c.O\", null, Bad\n").unwrap();
    let e = parse_files(&[a, b.clone()]).unwrap_err();
    assert_eq!((e.file(), e.line()), (Some(b.as_path()), Some(2)));
}

#[test]
fn the_same_file_twice_duplicates_its_services() {
    // Sony's tool concatenates: two services of each kind, but the count (last wins) is 1.
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.cfg");
    std::fs::write(&a, MIN).unwrap();
    let e = parse_files(&[a.clone(), a.clone()]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::SubjectCountMismatch);
    assert!(e.message().contains("but 2 subject service(s) found"), "{e}");
}

#[test]
fn a_subname_used_twice_is_accepted_with_a_warning() {
    let text = "ObjectName : Obj
NumOfOSubject : 1
NumOfOObserver : 3
Service : \"Obj.Sub.char.S\", null, null
Service : \"Obj.Stdin.char.O\", null, Notify()
Service : \"Obj.Other.char.O\", null, null
Service : \"Obj.Stdin.OSensorFrameVectorData.O\", null, NotifySensor()
";
    let cfg = parse_str("stub.cfg", text).unwrap();
    assert_eq!(cfg.observers.len(), 3);
    let w = stubgen::warnings(&cfg);
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!((w[0].file.as_path(), w[0].line), (std::path::Path::new("stub.cfg"), 7));
    let shown = w[0].to_string();
    assert!(shown.starts_with("stub.cfg:7: warning: SubName 'Stdin' is already used by the observer service on stub.cfg:5;"), "{shown}");
    assert!(shown.contains("'obsStdin' in def.h is 0"), "{shown}");
    // A subject and an observer sharing a SubName give sbjX and obsX: nothing dubious.
    let text = MIN.replace("Obj.Obs.char.O", "Obj.Sub.char.O");
    assert!(stubgen::warnings(&parse_str("a", &text).unwrap()).is_empty());
}

#[test]
fn counts_are_read_like_atoi() {
    for v in ["1;", "+1", "1st", "01"] {
        let text = MIN.replace("NumOfOSubject : 1", &format!("NumOfOSubject : {v}"));
        assert!(parse_str("a", &text).is_ok(), "{v}");
    }
    for v in ["-1", "x1", ";"] {
        let text = MIN.replace("NumOfOSubject : 1", &format!("NumOfOSubject : {v}"));
        let e = parse_str("a", &text).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::NoSubject, "{v}");
        assert!(e.message().ends_with(&format!("(NumOfOSubject value '{v}' is not a number)")), "{e}");
    }
}

#[test]
fn huge_count_is_a_mismatch_not_a_crash() {
    let text = MIN.replace("NumOfOSubject : 1", "NumOfOSubject : 99999999999999999999999999");
    assert_eq!(parse_str("a", &text).unwrap_err().kind(), ErrorKind::SubjectCountMismatch);
}
