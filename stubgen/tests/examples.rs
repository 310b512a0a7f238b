//! The worked examples of object-model 1.2.5, from our own stub.cfg texts.

mod common;
use common::*;

#[test]
fn objectcomm_sample_subject() {
    let (cfg, f) = generate_fixture("objectcomm-subject.cfg");
    assert_eq!((cfg.subjects.len(), cfg.observers.len(), cfg.extras.len()), (1, 1, 0));
    let def = &f["def.h"];
    assert!(def.contains("const char* const objectName = \"SampleSubject\";"));
    assert!(def.contains("const int sbjSendString = 0;"));
    assert!(def.contains("const int obsDummyObserver = 0;"));
    assert!(has_lines(def, &["const char* const subjectService[numOfSubject] = {", "\"SampleSubject.SendString.char.S\"", "};",]));
    assert!(has_lines(def, &["const char* const observerService[numOfObserver] = {", "\"SampleSubject.DummyObserver.DoNotConnect.O\"", "};",]));
    let entry = &f["entry.h"];
    assert!(entry.contains("const int numOfHook = 4;"));
    assert!(entry.contains("const ::Selector Entry_Hook[numOfHook] = { 0, 1, 2, 3 };"));
    assert!(entry.contains("const ::Selector Entry_Control[::numOfSubject] = { 4 };"));
    assert!(entry.contains("const ::Selector Entry_Ready[::numOfSubject] = { 5 };"));
    assert!(entry.contains("const ::Selector Entry_Connect[::numOfObserver] = { 6 };"));
    assert!(entry.contains("const ::Selector Entry_Notify[::numOfObserver] = { 7 };"));
    assert!(entry.contains("const ::longword numOfBasicEntries = 8;"));
    assert!(!entry.contains("Extra_Entry"));
    let cc = &f["SampleSubjectStub.cc"];
    assert!(has_lines(
        cc,
        &["StubFuncDefine_Control_nofunc(0)", "StubFuncDefine_Ready(0, Ready)", "StubFuncDefine_Connect_nofunc(0)", "StubFuncDefine_Notify_nofunc(0)",]
    ));
    assert_eq!(gnuc_table(cc), expected_table(1, 1, &[]));
    assert!(f.contains_key("SampleSubjectStub.h"));
}

#[test]
fn objectcomm_sample_observer() {
    let (_, f) = generate_fixture("objectcomm-observer.cfg");
    assert!(f["def.h"].contains("const int sbjDummySubject = 0;"));
    assert!(f["def.h"].contains("const int obsReceiveString = 0;"));
    assert!(f["entry.h"].contains("const ::longword numOfBasicEntries = 8;"));
    let cc = &f["SampleObserverStub.cc"];
    assert!(has_lines(
        cc,
        &["StubFuncDefine_Control_nofunc(0)", "StubFuncDefine_Ready_nofunc(0)", "StubFuncDefine_Connect_nofunc(0)", "StubFuncDefine_Notify(0, Notify)",]
    ));
    assert_eq!(gnuc_table(cc), expected_table(1, 1, &[]));
}

#[test]
fn moving_legs7() {
    let (_, f) = generate_fixture("movinglegs7.cfg");
    assert!(f["def.h"].contains("const int sbjMove = 0;"));
    assert!(f["def.h"].contains("const int obsDummyObserver = 0;"));
    assert!(f["entry.h"].contains("const ::Selector Entry_Ready[::numOfSubject] = { 5 };"));
    let cc = &f["MovingLegs7Stub.cc"];
    assert!(cc.contains("StubFuncDefine_Ready(0, Ready)"));
    assert_eq!(cc.matches("_nofunc(").count(), 3);
    assert!(cc.contains("#include \"MovingLegs7.h\"\n#ifdef Self\n#undef Self") && cc.contains("#endif\n::MovingLegs7 Self;"));
}

#[test]
fn echo_server_four_extras() {
    let (cfg, f) = generate_fixture("echoserver.cfg");
    let extras = ["ListenCont", "SendCont", "ReceiveCont", "CloseCont"];
    assert_eq!(cfg.extras, extras);
    let entry = &f["entry.h"];
    assert!(entry.contains("const ::longword numOfBasicEntries = 8;"));
    assert!(entry.contains("const ::Selector Extra_Entry[] = { 8, 9, 10, 11 };"));
    for (i, x) in extras.iter().enumerate() {
        assert!(entry.contains(&format!("const int entry{x} = {i};")), "{x}");
    }
    let cc = &f["EchoServerStub.cc"];
    assert_eq!(cc.matches("_nofunc(").count(), 4);
    for x in extras {
        assert!(
            has_lines(
                cc,
                &[
                    &format!("extern \"C\" void _{x}(void* openr_msg)"),
                    "{",
                    "try {",
                    &format!("::Self.{x}(openr_msg);"),
                    "} catch (...) {",
                    &format!("::openr_entry_exception(\"{x}\");"),
                    "}",
                    "::Return();",
                    "}",
                ]
            ),
            "{x}"
        );
        assert!(cc.contains(&format!("GEN_ENTRY(_{x}stub, _{x});")));
        assert!(f["EchoServerStub.h"].contains(&format!("    void _{x}(void*);\n")));
    }
    assert_eq!(gnuc_table(cc), expected_table(1, 1, &extras));
}

#[test]
fn tiny_ftpd_nine_extras_in_file_order() {
    let (cfg, f) = generate_fixture("tinyftpd.cfg");
    assert_eq!(cfg.extras.len(), 9);
    let entry = &f["entry.h"];
    assert!(entry.contains("const ::Selector Extra_Entry[] = { 8, 9, 10, 11, 12, 13, 14, 15, 16 };"));
    assert!(entry.contains("const int entryListenContforPI = 0;"));
    assert!(entry.contains("const int entryCloseContforDTP = 8;"));
    let extras: Vec<&str> = cfg.extras.iter().map(String::as_str).collect();
    assert_eq!(gnuc_table(&f["TinyFTPDStub.cc"]), expected_table(1, 1, &extras));
}

#[test]
fn monet_interleaved_three_subjects_two_observers() {
    let (cfg, f) = generate_fixture("monet.cfg");
    let subs: Vec<&str> = cfg.subjects.iter().map(|s| s.sub_name.as_str()).collect();
    let obs: Vec<&str> = cfg.observers.iter().map(|s| s.sub_name.as_str()).collect();
    assert_eq!(subs, ["ClientResult", "MotionAgentCommand", "SoundAgentCommand"]);
    assert_eq!(obs, ["ClientCommand", "AgentResult"]);
    let def = &f["def.h"];
    for l in [
        "const int sbjClientResult = 0;",
        "const int sbjMotionAgentCommand = 1;",
        "const int sbjSoundAgentCommand = 2;",
        "const int obsClientCommand = 0;",
        "const int obsAgentResult = 1;",
    ] {
        assert!(def.contains(l), "{l}");
    }
    let entry = &f["entry.h"];
    assert!(entry.contains("Entry_Control[::numOfSubject] = { 4, 5, 6 };"));
    assert!(entry.contains("Entry_Ready[::numOfSubject] = { 7, 8, 9 };"));
    assert!(entry.contains("Entry_Connect[::numOfObserver] = { 10, 11 };"));
    assert!(entry.contains("Entry_Notify[::numOfObserver] = { 12, 13 };"));
    assert!(entry.contains("const ::longword numOfBasicEntries = 14;"));
    let cc = &f["MoNetStub.cc"];
    assert!(cc.contains("StubFuncDefine_Notify(0, NotifyClientCommand)"));
    assert!(cc.contains("StubFuncDefine_Notify(1, NotifyAgentResult)"));
    assert_eq!(gnuc_table(cc), expected_table(3, 2, &[]));
}

#[test]
fn ball_tracking_head7_two_subjects_three_observers() {
    let (_, f) = generate_fixture("balltrackinghead7.cfg");
    let def = &f["def.h"];
    for l in ["const int sbjCommand = 0;", "const int sbjJoint = 1;", "const int obsResult = 0;", "const int obsSensor = 1;", "const int obsImage = 2;"] {
        assert!(def.contains(l), "{l}");
    }
    let entry = &f["entry.h"];
    assert!(entry.contains("Entry_Control[::numOfSubject] = { 4, 5 };"));
    assert!(entry.contains("Entry_Ready[::numOfSubject] = { 6, 7 };"));
    assert!(entry.contains("Entry_Connect[::numOfObserver] = { 8, 9, 10 };"));
    assert!(entry.contains("Entry_Notify[::numOfObserver] = { 11, 12, 13 };"));
    assert!(entry.contains("const ::longword numOfBasicEntries = 14;"));
    let cc = &f["BallTrackingHead7Stub.cc"];
    assert_eq!(cc.matches("StubFuncDefine_Notify(").count(), 3);
    assert!(cc.contains("StubFuncDefine_Notify(2, NotifyImage)"));
    assert_eq!(gnuc_table(cc), expected_table(2, 3, &[]));
}

#[test]
fn stub_h_structure() {
    let (_, f) = generate_fixture("balltrackinghead7.cfg");
    let h = &f["BallTrackingHead7Stub.h"];
    assert!(
        has_lines(
            h,
            &[
                "#ifndef _stub_h_DEFINED",
                "#define _stub_h_DEFINED",
                "",
                "#ifndef OPENR_STUBGEN",
                "#define OPENR_STUBGEN",
                "#endif",
                "",
                "#include <OPENR/OPENR.h>",
                "#include <OPENR/OPENRMessages.h>",
                "#include <OPENR/ObjcommMessages.h>",
                "#include <OPENR/stub_macro.h>",
                "#include \"def.h\"",
                "",
                "extern \"C\" {",
                "StubFuncDeclare_Basic(Init)",
                "StubFuncDeclare_Basic(Start)",
                "StubFuncDeclare_Basic(Stop)",
                "StubFuncDeclare_Basic(Destroy)",
                "StubFuncDeclare_Subject(0)",
                "StubFuncDeclare_Subject(1)",
                "StubFuncDeclare_Observer(0)",
                "StubFuncDeclare_Observer(1)",
                "StubFuncDeclare_Observer(2)",
                "}",
                "",
                "#endif // _stub_h_DEFINED",
            ]
        ),
        "{h}"
    );
}

#[test]
fn stub_cc_structure() {
    let (_, f) = generate_fixture("objectcomm-subject.cfg");
    let cc = &f["SampleSubjectStub.cc"];
    assert!(
        has_lines(
            cc,
            &[
                "#ifndef OPENR_STUBGEN",
                "#define OPENR_STUBGEN",
                "#endif",
                "",
                "#if defined(__GNUC__)",
                "#include <apsys.h>",
                "#endif",
                "#include <MCOOP.h>",
                "#include <ObjectEntryTable.h>",
                "#include <OPENR/stub_macro.h>",
                "#include \"def.h\"",
                "#include \"entry.h\"",
                "#include \"SampleSubjectStub.h\"",
            ]
        ),
        "{cc}"
    );
    assert!(has_lines(
        cc,
        &[
            "#include \"SampleSubject.h\"",
            "#ifdef Self",
            "#undef Self // a macro of the program's header must not rename the instance below",
            "#endif",
            "::SampleSubject Self;"
        ]
    ));
    assert!(has_lines(cc, &["StubFuncDefine_Basic(Init)", "StubFuncDefine_Basic(Start)", "StubFuncDefine_Basic(Stop)", "StubFuncDefine_Basic(Destroy)",]));
    assert!(
        has_lines(
            cc,
            &[
                "#if defined(__GNUC__)",
                "",
                "GEN_ENTRY(_hookstub0, _Init);",
                "GEN_ENTRY(_hookstub1, _Start);",
                "GEN_ENTRY(_hookstub2, _Stop);",
                "GEN_ENTRY(_hookstub3, _Destroy);",
                "GEN_ENTRY(_controlstub0, _Control0);",
                "GEN_ENTRY(_readystub0, _Ready0);",
                "GEN_ENTRY(_connectstub0, _Connect0);",
                "GEN_ENTRY(_notifystub0, _Notify0);",
                "GEN_ENTRY(PrologueEntry, Prologue);",
                "",
                "::ObjectEntry ObjectEntryTable[] = {",
                "{0, (::Entry)::_hookstub0},",
            ]
        ),
        "{cc}"
    );
    // PrologueEntry is not a table row; the table ends with the sentinel, then #else.
    assert!(!gnuc_table(cc).iter().any(|(_, e)| e.contains("Prologue")));
    assert!(has_lines(cc, &["{::UNDEF, ENTRY_UNDEF}", "};", "", "#else // !__GNUC__: entry points are the C functions themselves"]));
    assert!(cc.trim_end().ends_with("#endif // __GNUC__"));
    assert_eq!(cc.matches("ObjectEntry ObjectEntryTable[]").count(), 2);
}

#[test]
fn headers_have_guards_and_entry_h_includes() {
    let (_, f) = generate_fixture("echoserver.cfg");
    let def = &f["def.h"];
    assert!(has_lines(def, &["#ifndef _def_h_DEFINED", "#define _def_h_DEFINED"]));
    assert!(!def.contains("#include"));
    assert!(def.trim_end().ends_with("#endif // _def_h_DEFINED"));
    let entry = &f["entry.h"];
    assert!(has_lines(entry, &["#ifndef _entry_h_DEFINED", "#define _entry_h_DEFINED", "", "#include <Types.h>", "#include \"def.h\""]));
    assert!(entry.trim_end().ends_with("#endif // _entry_h_DEFINED"));
}

#[test]
fn all_function_kinds_aliases_and_blanks() {
    let (cfg, f) = generate_fixture("all-functions.cfg");
    assert_eq!(cfg.object_name, "Everything");
    assert_eq!(cfg.subjects[0].func1.as_deref(), Some("Control"));
    assert_eq!(cfg.observers[0].func2.as_deref(), Some("Notify"));
    assert_eq!(cfg.observers[1].func1.as_deref(), Some("ConnectIn2"));
    assert_eq!(cfg.observers[1].func2, None);
    assert_eq!(cfg.extras, ["UpdatePowerStatus"]);
    let cc = &f["EverythingStub.cc"];
    assert!(
        has_lines(
            cc,
            &[
                "StubFuncDefine_Control(0, Control)",
                "StubFuncDefine_Ready(0, Ready)",
                "StubFuncDefine_Control_nofunc(1)",
                "StubFuncDefine_Ready(1, ReadyOut)",
                "StubFuncDefine_Connect(0, Connect)",
                "StubFuncDefine_Notify(0, Notify)",
                "StubFuncDefine_Connect(1, ConnectIn2)",
                "StubFuncDefine_Notify_nofunc(1)",
            ]
        ),
        "{cc}"
    );
    assert_eq!(gnuc_table(cc), expected_table(2, 2, &["UpdatePowerStatus"]));
}

#[test]
fn crlf_fixture() {
    let bytes = std::fs::read(good("battchecker-crlf.cfg")).unwrap();
    assert!(bytes.windows(2).any(|w| w == b"\r\n"), "fixture lost its CRLF line ends");
    let (cfg, f) = generate_fixture("battchecker-crlf.cfg");
    assert_eq!(cfg.object_name, "BattChecker");
    assert_eq!(cfg.subjects[0].name, "BattChecker.DummySubject.DoNotConnect.S");
    assert!(f.values().all(|t| !t.contains('\r')));
}
