//! `cargo openr run`: programs of the corpus, built with the SDK root, behave as on the
//! robot (object-model 2), and bad Memory Stick trees give one clear error.
use std::fs;
use std::io::Write;
use std::time::Duration;

use crate::support::{build, run_ms, run_ms_signalled, RunOutput};

fn assert_ok(out: &RunOutput) {
    assert_eq!(out.code, Some(0), "exit code\nstdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
}

/// Index of the first stdout line containing `needle`.
fn line_of(out: &RunOutput, needle: &str) -> usize {
    out.stdout.lines().position(|l| l.contains(needle)).unwrap_or_else(|| panic!("no line with {needle:?} in:\n{}\nstderr:\n{}", out.stdout, out.stderr))
}

#[test]
fn hand_written_stub_hello_world_runs_its_life_cycle() {
    let p = build("hello");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    let hello = line_of(&out, "!!! Hello World !!!");
    let bye = line_of(&out, "Bye Bye ...");
    assert!(hello < bye, "DoStart before DoStop:\n{}", out.stdout);
    assert!(out.stdout.lines().any(|l| l == "[oid:80000040,prio:1] Bye Bye ..."), "OSYSLOG1 format of 4.2:\n{}", out.stdout);
    assert!(!out.stdout.contains("DoInit") && !out.stdout.contains("DoDestroy"), "OSYSDEBUG is off without -DOPENR_DEBUG:\n{}", out.stdout);
}

#[test]
fn osysdebug_lines_appear_when_built_with_openr_debug() {
    let p = build("hello");
    // What a user does: uncomment the Makefile's `#CXXFLAGS+= -DOPENR_DEBUG`, rebuild.
    let mk = p.dir.path().join("hello/HelloWorld/Makefile");
    let text = fs::read_to_string(&mk).unwrap().replace("#CXXFLAGS+= -DOPENR_DEBUG", "CXXFLAGS+= -DOPENR_DEBUG");
    fs::write(&mk, text).unwrap();
    let (ok, log) = crate::support::run(
        std::process::Command::new("make")
            .arg(format!("OPENRSDK_ROOT={}", crate::support::sdk_root().display()))
            .args(["clean", "install"])
            .current_dir(p.dir.path().join("hello")),
    );
    assert!(ok, "{log}");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    let order = ["HelloWorld::DoInit()", "HelloWorld::DoStart()", "!!! Hello World !!!", "Bye Bye ...", "HelloWorld::DoDestroy()"];
    let at: Vec<usize> = order.iter().map(|n| line_of(&out, n)).collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "life cycle order {order:?}:\n{}", out.stdout);
}

#[test]
fn stubgen_hello_world_runs_its_life_cycle() {
    let p = build("hello-stubgen");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    assert!(line_of(&out, "!!! Hello World !!!") < line_of(&out, "Bye Bye ..."));
}

#[test]
fn subject_and_observer_follow_the_ready_notify_protocol() {
    let p = build("objcomm");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    let lines = out.lines_starting("Sample");
    assert_eq!(
        lines,
        [
            "SampleSubject::Ready() : ASSERT READY",
            "SampleObserver::Notify() !!! Hello world !!!",
            "SampleSubject::Ready() : ASSERT READY",
            "SampleObserver::Notify() !!! Hello world again !!!",
            "SampleSubject::Ready() : ASSERT READY",
            "SampleSubject::Ready() : DEASSERT READY",
        ],
        "object-model 2.8.5; the DEASSERT comes from the observer's DoStop\nstderr:\n{}",
        out.stderr
    );
}

#[test]
fn sigterm_runs_the_shutdown_sequence_and_exits_zero() {
    let p = build("objcomm");
    let out = run_ms_signalled(&p.ms(), &[], &[(Duration::from_millis(1500), 15)]);
    assert_ok(&out);
    assert!(out.stdout.contains("DEASSERT READY"), "Stop ran:\n{}", out.stdout);
}

#[test]
fn one_class_loaded_as_several_objects_fans_out_and_in() {
    let p = build("objcomm-multi");
    let out = run_ms(&p.ms(), &["--for", "2s"]);
    assert_ok(&out);
    let count = |obs: &str| out.lines_starting(&format!("{obs}::Notify()")).len();
    assert_eq!((count("SampleObserver1"), count("SampleObserver2"), count("SampleObserver3")), (2, 2, 4), "stdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
    // IsAllReady() counts: SBJ1 waits for all three observers before each send.
    assert_eq!(out.lines_starting("SampleSubject1 : send"), ["SampleSubject1 : send #1 to 3 observer(s)", "SampleSubject1 : send #2 to 3 observer(s)"]);
}

#[test]
fn a_producer_outrunning_its_consumer_hits_the_queue_limit() {
    let p = build("objcomm-buffer");
    let out = run_ms(&p.ms(), &["--for", "2s"]);
    assert_ok(&out);
    let statuses: Vec<&str> = out.lines_starting("Producer : SetData").iter().map(|l| l.rsplit(' ').next().unwrap()).collect();
    assert_eq!(statuses, ["0", "0", "0", "0", "0", "25", "25", "25"], "2.8.3: a 10-entry queue holds 5 units; then oOVERFLOW\n{}", out.stdout);
    assert_eq!(out.lines_starting("Consumer :"), ["Consumer : NumOfData 5 NumOfNotify 5 : 4 5 6 7 8"], "oldest units dropped, the rest in one notification");
    assert_eq!(
        out.lines_starting("Producer : Ready"),
        ["Producer : Ready ASSERT references 1 1 1 2 2 2 2 2", "Producer : Ready ASSERT references 1 1 1 1 1 1 1 1"],
        "dropped regions lose the queue's reference at once, delivered ones when the observer asserts again\n{}",
        out.stdout
    );
}

#[test]
fn a_subject_connected_to_its_own_object_and_kernel_calls_work() {
    let p = build("objcomm-self");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    let talk: Vec<&str> = out.lines_starting("SelfTalk : ").into_iter().filter(|l| l.contains("Ready") || l.contains("Notify")).collect();
    assert_eq!(
        talk,
        [
            "SelfTalk : Ready ASSERT (IsReady 1)",
            "SelfTalk : Notify self #1 (NumOfData 1)",
            "SelfTalk : Ready ASSERT (IsReady 1)",
            "SelfTalk : Notify self #2 (NumOfData 1)",
            "SelfTalk : Ready ASSERT (IsReady 1)",
        ],
        "2.8.1 step 6: self connection without deadlock\nstderr:\n{}",
        out.stderr
    );
    for line in [
        "SelfTalk : RFC2822 Sat, 1 Jan 2000 09:00:00 +0900",
        "SelfTalk : Sprint Mon Jan 01 00:00:00 2001",
        "SelfTalk : round trip ok",
        "SelfTalk : Wait ok",
        "SelfTalk : shared memory ok",
    ] {
        assert!(out.stdout.lines().any(|l| l == line), "missing {line:?}:\n{}", out.stdout);
    }
    assert!(out.stdout.contains("SelfTalk : timer fired"), "SetTimeEvent delivered:\n{}", out.stdout);
    let long = out.stdout.lines().find(|l| l.starts_with("[oid:80000040,prio:1] xxx")).expect("OSYSLOG1 line");
    assert_eq!(long.len() - "[oid:80000040,prio:1] ".len(), 243, "osyslogMAX_SIZE truncation (4.2)");
}

#[test]
fn uncompressed_objects_load_too() {
    let p = build("hello");
    let bin = p.ms().join("OPEN-R/MW/OBJS/HELLO.BIN");
    let gz = fs::read(&bin).unwrap();
    let mut elf = Vec::new();
    std::io::Read::read_to_end(&mut flate2::read::GzDecoder::new(&gz[..]), &mut elf).unwrap();
    fs::write(&bin, elf).unwrap();
    let out = run_ms(&p.ms(), &["--for", "500ms"]);
    assert_ok(&out);
    assert!(out.stdout.contains("!!! Hello World !!!"));
}

#[test]
fn robot_design_selects_sections_and_reads_design_data() {
    let p = build("robot-design");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    assert!(out.stdout.contains("OPENR::GetRobotDesign() : ERS-7"), "{}", out.stdout);
    assert!(out.stdout.contains("SAMPLE_DATA : This is an ERS-7 (DRX-1000)."), "{}", out.stdout);
    // PowerMonitor sets the time difference to +9 first: GetPowerStatus reports it.
    assert!(out.stdout.contains("PowerMonitor::DoStart() robotStatus") && out.stdout.contains("timeDif 9\n"), "{}", out.stdout);
    let out = run_ms(&p.ms(), &["--for", "1s", "--design", "ERS-220"]);
    assert_ok(&out);
    assert!(out.stdout.contains("OPENR::GetRobotDesign() : ERS-220"), "ERS-220 section and its gzipped data file:\n{}", out.stdout);
}

#[test]
fn pause_button_reaches_power_observers_which_shut_down() {
    let p = build("robot-design");
    let out = run_ms_signalled(&p.ms(), &["--for", "20s"], &[(Duration::from_millis(1500), 10)]);
    assert_ok(&out);
    assert!(out.stdout.contains("PowerMonitor::UpdatePowerStatus()"), "power event delivered:\n{}", out.stdout);
    assert!(out.stdout.contains("PowerMonitor : pause switch pressed, shutting down"), "{}", out.stdout);
    assert!(out.stderr.contains("OPENR::Shutdown"), "the run ended by Shutdown, not by --for:\n{}", out.stderr);
}

#[test]
fn memory_stick_files_are_case_insensitive_and_confined() {
    let p = build("filesys");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    assert!(!out.stdout.contains("FAILED"), "{}", out.stdout);
    assert!(out.stdout.contains("fopen(\"/MS/../../etc/passwd\") refused"), "{}", out.stdout);
    let ok_steps = out.lines_starting("FileSys :").iter().filter(|l| l.ends_with(" ok")).count();
    assert!(ok_steps >= 8, "every step reports ok:\n{}", out.stdout);
}

#[test]
fn legacy_iostreams_and_c_library_work_inside_objects() {
    let p = build("legacy");
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ok(&out);
    assert!(out.lines_starting("Legacy :").len() >= 3, "cout output reaches the console:\n{}\n{}", out.stdout, out.stderr);
}

fn crash_with(fault: &str) -> RunOutput {
    let p = build("crash");
    fs::write(p.ms().join("OPEN-R/MW/CONF/CRASH.CFG"), format!("{fault}\n")).unwrap();
    let out = run_ms(&p.ms(), &["--for", "5s"]);
    drop(p);
    out
}

#[test]
fn a_crashing_object_is_reported_with_its_entry_and_backtrace() {
    for (fault, sig) in [("1", "SIGSEGV"), ("2", "SIGFPE"), ("3", "SIGABRT")] {
        let out = crash_with(fault);
        assert_ne!(out.code, Some(0), "fault {fault}: non-zero exit");
        assert!(out.stdout.contains(&format!("Crash : fault {fault}")), "output before the crash is kept:\n{}", out.stdout);
        assert!(out.stderr.contains("error: object `crash`") && out.stderr.contains(sig), "fault {fault}:\n{}", out.stderr);
        assert!(out.stderr.contains("StartEntry") || out.stderr.contains("selector 1"), "names the entry being run:\n{}", out.stderr);
        assert!(out.stderr.contains("backtrace:"), "{}", out.stderr);
    }
}

/// Runs the crash program's fault `fault` (its CRASH.CFG) on an already built copy.
fn commit_fault(p: &crate::support::Built, fault: u32, extra: &[&str]) -> RunOutput {
    fs::write(p.ms().join("OPEN-R/MW/CONF/CRASH.CFG"), format!("{fault}\n")).unwrap();
    let mut args = vec!["--for", "2s", "--speed", "max"];
    args.extend_from_slice(extra);
    run_ms(&p.ms(), &args)
}

#[test]
fn floating_point_errors_fault_the_object_as_on_the_robot() {
    let p = build("crash");
    for (fault, kind) in [
        (7, "FP exception: invalid operation"),
        (8, "FP exception: invalid operation"),
        (9, "FP exception: invalid operation"),
        (10, "FP exception: division by zero"),
        (11, "FP exception: overflow"),
        (12, "FP exception: denormal operand"),
    ] {
        let out = commit_fault(&p, fault, &[]);
        assert_eq!(out.code, Some(128 + 8), "fault {fault}: SIGFPE\n{}\n{}", out.stdout, out.stderr);
        let header = out.stderr.lines().find(|l| l.starts_with("error: object `crash`")).unwrap_or_default();
        assert!(header.contains(&format!("crashed with SIGFPE: {kind}")) && header.contains("in entry StartEntry"), "fault {fault}:\n{}", out.stderr);
        assert!(out.stderr.contains("Crash::CommitFault(int)"), "demangled frame of the object:\n{}", out.stderr);
        assert!(!out.stdout.contains("survived"), "{}", out.stdout);
        // --no-fp-traps: the PC's quiet NaN / infinity / garbage instead
        let off = commit_fault(&p, fault, &["--no-fp-traps"]);
        assert_eq!(off.code, Some(0), "fault {fault} with --no-fp-traps:\n{}", off.stderr);
        assert!(off.stdout.contains(&format!("Crash : survived fault {fault}")), "{}", off.stdout);
    }
    // The C library on an object thread does not trip the traps: NaN and infinity print.
    let out = commit_fault(&p, 18, &[]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("Crash : printf nan -inf 1.000000e-300 3.142\n"), "{}", out.stdout);
    assert!(out.stdout.contains("Crash : cout nan -inf 1e-300 2.5\n"), "{}", out.stdout);
    assert!(out.stdout.contains("Crash : math 0.8415 7.3891 0.4636\n"), "{}", out.stdout);
}

#[test]
fn a_misaligned_access_faults_where_the_robot_would() {
    let p = build("crash");
    let out = commit_fault(&p, 13, &[]);
    assert_eq!(out.code, Some(128 + 7), "SIGBUS\n{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("crashed with SIGBUS: misaligned access in entry StartEntry"), "{}", out.stderr);
    assert!(out.stderr.contains("for type 'volatile int', which the robot's CPU needs 4-byte aligned, at Crash.cc:"), "{}", out.stderr);
    // Built without the check (OPENR_ALIGNMENT_TRAP=0), the PC does the access.
    let (ok, log) = crate::support::run(
        std::process::Command::new("make")
            .env("OPENR_ALIGNMENT_TRAP", "0")
            .arg(format!("OPENRSDK_ROOT={}", crate::support::sdk_root().display()))
            .args(["clean", "install"])
            .current_dir(p.dir.path().join("crash")),
    );
    assert!(ok, "{log}");
    let out = commit_fault(&p, 13, &[]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.contains("Crash : misaligned word = 42"), "{}", out.stdout);
}

#[test]
fn a_function_without_a_return_returns_as_with_gcc_3_3() {
    let p = build("crash");
    // g++ 12 alone takes the end of such a function for unreachable: the call ran on
    // into the next function's code and crashed (SIGSEGV).
    let out = commit_fault(&p, 20, &[]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("Crash : servos 1..3\nCrash : count_servos returned\nCrash : survived fault 20\n"), "{}", out.stdout);
    // A __builtin_unreachable() the program reaches faults it, saying where.
    let out = commit_fault(&p, 21, &[]);
    assert_eq!(out.code, Some(128 + 4), "SIGILL\n{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("crashed with SIGILL: unreachable code reached in entry StartEntry"), "{}", out.stderr);
    assert!(out.stderr.contains("  reached __builtin_unreachable() at Crash.cc:"), "{}", out.stderr);
    assert!(!out.stdout.contains("Crash : gain"), "{}", out.stdout);
}

#[test]
fn a_long_aligned_to_four_runs_as_on_the_robot_unless_the_build_makes_it_fatal() {
    let p = build("crash");
    // The PC's long wants 8 bytes, the robot's is a 4-byte word: no fault.
    let out = commit_fault(&p, 19, &[]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("Crash : word-aligned long = 7"), "{}", out.stdout);
    // -fno-sanitize-recover: gcc takes the check's handler for one that never returns,
    // so the access cannot go ahead; the fault says why.
    let root = crate::support::sdk_root();
    let flags = format!("CXXFLAGS=-O2 -g -I. -I{0}/OPEN_R/include/R4000 -I{0}/OPEN_R/include -fno-sanitize-recover=alignment", root.display());
    let (ok, log) = crate::support::run(
        std::process::Command::new("make")
            .arg(format!("OPENRSDK_ROOT={}", root.display()))
            .arg(flags)
            .args(["clean", "install"])
            .current_dir(p.dir.path().join("crash")),
    );
    assert!(ok, "{log}");
    let out = commit_fault(&p, 19, &[]);
    assert_eq!(out.code, Some(128 + 7), "SIGBUS\n{}\n{}", out.stdout, out.stderr);
    assert!(
        out.stderr.contains("which the PC wants 8-byte aligned (the robot would not fault; -fno-sanitize-recover made it fatal), at Crash.cc:"),
        "{}",
        out.stderr
    );
    assert!(!out.stdout.contains("word-aligned long ="), "{}", out.stdout);
}

#[test]
fn stack_smash_double_free_and_own_threads_are_reported() {
    let p = build("crash");
    // A return through a smashed frame (default wrapper flags: no stack protector).
    let out = commit_fault(&p, 14, &[]);
    assert_eq!(out.code, Some(128 + 11), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("error: object `crash` (/MS/OPEN-R/MW/OBJS/CRASH.BIN) crashed with SIGSEGV"), "{}", out.stderr);
    assert!(!out.stdout.contains("survived"), "{}", out.stdout);
    // glibc detects the double free and aborts inside malloc: the report must not hang
    // on malloc's lock (run_ms kills a run after 60 s of real time: a safety net only).
    let out = commit_fault(&p, 15, &[]);
    assert_eq!(out.code, Some(128 + 6), "{}\n{}", out.stdout, out.stderr);
    let header = out.stderr.lines().position(|l| l.starts_with("error: object `crash`") && l.contains("SIGABRT: abort in entry StartEntry"));
    assert!(header.is_some(), "{}", out.stderr);
    assert!(out.stderr.contains("double free detected"), "glibc's own message is kept:\n{}", out.stderr);
    assert!(out.stderr.contains("__libc_free") && out.stderr.contains("Crash::DoStart"), "backtrace through free:\n{}", out.stderr);
    // Endless recursion: reported from the alternate signal stack.
    let out = commit_fault(&p, 6, &[]);
    assert_eq!(out.code, Some(128 + 11), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("crashed with SIGSEGV: stack overflow"), "{}", out.stderr);
    // A fault in a pthread the object started names the object.
    let out = commit_fault(&p, 17, &[]);
    assert_eq!(out.code, Some(128 + 11), "{}\n{}", out.stdout, out.stderr);
    assert!(
        out.stderr.contains("error: object `crash` (/MS/OPEN-R/MW/OBJS/CRASH.BIN) crashed with SIGSEGV: invalid memory access (unmapped address) in a thread the object started"),
        "{}",
        out.stderr
    );
}

#[test]
fn underscore_exit_in_an_object_is_reported_and_flushes_the_console() {
    let p = build("crash");
    let out = commit_fault(&p, 16, &[]);
    assert_eq!(out.code, Some(3), "the object's status\n{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.ends_with("Crash : this line has no newline yet..."), "pending stdout flushed:\n{}", out.stdout);
    assert!(out.stderr.contains("error: object `crash` (/MS/OPEN-R/MW/OBJS/CRASH.BIN) called _exit(3)"), "{}", out.stderr);
}

#[test]
fn console_input_never_ends_a_reader_waits_and_the_run_ends_at_for() {
    let p = build("console-read");
    let conf = p.ms().join("OPEN-R/MW/CONF/READER.CFG");
    for (style, said) in [("gets", "line"), ("cin", "word")] {
        fs::write(&conf, format!("{style}\n")).unwrap();
        // stdin closed (/dev/null): one prompt, then the object waits
        let out = run_ms(&p.ms(), &["--for", "2s", "--speed", "max"]);
        assert_eq!(out.code, Some(0), "{style}: {}\n{}", out.stdout, out.stderr);
        assert!(out.stderr.contains("time limit reached; 250 frames"), "{style}: virtual time went on:\n{}", out.stderr);
        assert_eq!(out.stdout, format!("ConsoleRead : reading the console with {style}\nConsoleRead > "), "{style}: no flood");
        // a short file: the prompts for the lines given plus one
        let input: &[(std::time::Duration, &[u8])] = &[(std::time::Duration::ZERO, b"one\ntwo\n")];
        let out = crate::support::run_ms_with_stdin(&p.ms(), &["--for", "2s", "--speed", "max"], input);
        assert_eq!(out.code, Some(0), "{style}: {}\n{}", out.stdout, out.stderr);
        let want = format!(
            "ConsoleRead : reading the console with {style}\nConsoleRead > ConsoleRead : {said} 1: one\nConsoleRead > ConsoleRead : {said} 2: two\nConsoleRead > "
        );
        assert_eq!(out.stdout, want, "{style}");
        assert!(!out.stderr.contains("did not answer"), "a waiting reader costs no Stop timeout:\n{}", out.stderr);
    }
}

#[test]
fn a_crash_keeps_what_other_objects_printed() {
    // HELLO (built with -DOPENR_DEBUG: prints in DoInit) and CRASH on one stick.
    let hello = build("hello");
    let mk = hello.dir.path().join("hello/HelloWorld/Makefile");
    fs::write(&mk, fs::read_to_string(&mk).unwrap().replace("#CXXFLAGS+= -DOPENR_DEBUG", "CXXFLAGS+= -DOPENR_DEBUG")).unwrap();
    let (ok, log) = crate::support::run(
        std::process::Command::new("make")
            .arg(format!("OPENRSDK_ROOT={}", crate::support::sdk_root().display()))
            .args(["clean", "install"])
            .current_dir(hello.dir.path().join("hello")),
    );
    assert!(ok, "{log}");
    let p = build("crash");
    fs::copy(hello.ms().join("OPEN-R/MW/OBJS/HELLO.BIN"), p.ms().join("OPEN-R/MW/OBJS/HELLO.BIN")).unwrap();
    fs::write(p.ms().join("OPEN-R/MW/CONF/OBJECT.CFG"), "/MS/OPEN-R/MW/OBJS/HELLO.BIN\n/MS/OPEN-R/MW/OBJS/CRASH.BIN\n").unwrap();
    fs::write(p.ms().join("OPEN-R/MW/CONF/CRASH.CFG"), "1\n").unwrap();
    let out = run_ms(&p.ms(), &["--for", "5s"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stdout.contains("HelloWorld::DoInit()"), "other objects' output survives the crash:\n{}", out.stdout);
    assert!(out.stderr.contains("error: object `crash`"), "{}", out.stderr);
}

// ---- bad Memory Stick trees ----

fn run_err(ms: &std::path::Path) -> String {
    run_err_with(ms, &[])
}

/// `run_err` with more options.
fn run_err_with(ms: &std::path::Path, extra: &[&str]) -> String {
    let args: Vec<&str> = ["--for", "1s"].iter().chain(extra).copied().collect();
    let out = run_ms(ms, &args);
    assert_ne!(out.code, Some(0), "must fail\nstdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
    assert!(!out.stderr.contains("panicked"), "no panic:\n{}", out.stderr);
    out.stderr
}

#[test]
fn a_directory_without_object_cfg_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let err = run_err(dir.path());
    assert!(err.contains("OPEN-R/MW/CONF/OBJECT.CFG: not found"), "{err}");
}

#[test]
fn a_memory_stick_path_that_does_not_exist_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let ms = dir.path().join("NO-SUCH-MS");
    let err = run_err(&ms);
    let ms = ms.display();
    assert!(err.contains(&format!("error: cannot run {ms}: {ms}: No such file or directory")), "{err}");
}

#[test]
fn an_unknown_robot_design_is_refused_with_the_known_ones() {
    let p = build("hello");
    let err = run_err_with(&p.ms(), &["--design", "ERS-9"]);
    assert!(err.contains(&format!("error: cannot run {}: unknown robot design `ERS-9` (known: ERS-7, ERS-210, ERS-220)", p.ms().display())), "{err}");
    assert!(!err.contains("Hello World"), "no object ran");
    // Also where OBJECT.CFG has only design sections (the design is checked first).
    let p = build("robot-design");
    let err = run_err_with(&p.ms(), &["--design", "ERS-9"]);
    assert!(err.contains("unknown robot design `ERS-9` (known: ERS-7, ERS-210, ERS-220)"), "{err}");
}

#[test]
fn object_cfg_naming_a_missing_bin_is_refused_with_its_line() {
    let p = build("hello");
    let cfg = p.ms().join("OPEN-R/MW/CONF/OBJECT.CFG");
    fs::write(&cfg, "# objects\n/MS/OPEN-R/MW/OBJS/HELLO.BIN\n/MS/OPEN-R/MW/OBJS/MISSING.BIN\n").unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("OBJECT.CFG:3: object `/MS/OPEN-R/MW/OBJS/MISSING.BIN` not found"), "{err}");
}

#[test]
fn corrupt_gzip_and_non_elf_objects_are_refused() {
    let p = build("hello");
    let bin = p.ms().join("OPEN-R/MW/OBJS/HELLO.BIN");
    let mut gz = fs::read(&bin).unwrap();
    gz.truncate(gz.len() / 2);
    fs::write(&bin, &gz).unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("HELLO.BIN: corrupt gzip data"), "{err}");

    fs::write(&bin, b"#!/bin/sh\necho not an object\n").unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("HELLO.BIN: not an OPEN-R object: expected a gzipped or plain ELF shared object"), "{err}");

    // a gzip bomb: ~65 KB that would unpack to 65 MiB
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    enc.write_all(&vec![0u8; 65 << 20]).unwrap();
    fs::write(&bin, enc.finish().unwrap()).unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("HELLO.BIN: refused: it unpacks to more than 64 MiB, more than the robot's memory"), "{err}");
}

#[test]
fn an_elf_without_entry_table_is_refused() {
    let p = build("hello");
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("x.c"), "int not_an_object(void) { return 1; }\n").unwrap();
    let st = std::process::Command::new("gcc").args(["-shared", "-fPIC", "-o", "x.so", "x.c"]).current_dir(dir.path()).status().unwrap();
    assert!(st.success());
    let so = fs::read(dir.path().join("x.so")).unwrap();
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    enc.write_all(&so).unwrap();
    fs::write(p.ms().join("OPEN-R/MW/OBJS/HELLO.BIN"), enc.finish().unwrap()).unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("HELLO.BIN: no ObjectEntryTable"), "{err}");
    assert!(err.contains("OBJECT.CFG:"), "names the OBJECT.CFG line too: {err}");
}

#[test]
fn connect_cfg_with_an_unknown_service_lists_the_registered_ones() {
    let p = build("objcomm");
    let cfg = p.ms().join("OPEN-R/MW/CONF/CONNECT.CFG");
    fs::write(&cfg, "SampleSubject.SendString.char.S SampleObserver.ReceiveStrng.char.O\n").unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("CONNECT.CFG:1: unknown service `SampleObserver.ReceiveStrng.char.O`"), "{err}");
    assert!(err.contains("SampleObserver.ReceiveString.char.O") && err.contains("SampleSubject.SendString.char.S"), "lists what exists: {err}");
    // The robot's behaviour is available on request: a warning, the line skipped.
    let out = run_ms(&p.ms(), &["--for", "500ms", "--lenient-connect"]);
    assert_ok(&out);
    let warning = out
        .stderr
        .lines()
        .find(|l| l.contains("CONNECT.CFG:1: unknown service `SampleObserver.ReceiveStrng.char.O`; registered services: "))
        .unwrap_or_else(|| panic!("no warning for the skipped line:\n{}", out.stderr));
    assert!(warning.starts_with("warning: ") && warning.ends_with(" (line skipped)"), "{warning}");
    assert!(warning.contains("SampleObserver.ReceiveString.char.O"), "lists what exists: {warning}");
}

#[test]
fn duplicate_connections_are_refused() {
    let p = build("objcomm");
    let cfg = p.ms().join("OPEN-R/MW/CONF/CONNECT.CFG");
    let line = "SampleSubject.SendString.char.S SampleObserver.ReceiveString.char.O\n";
    fs::write(&cfg, format!("{line}{line}")).unwrap();
    let err = run_err(&p.ms());
    assert!(err.contains("CONNECT.CFG:2: duplicate connection"), "{err}");
}
