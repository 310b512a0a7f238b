//! The runtime as a library: sticks run in this test process by `sdk_runtime::boot::run`,
//! several at once, each a runtime instance of its own (objects, clock, scheduler,
//! console, gateway and IPStack). The executable exports the host API tables and the
//! interposers as `cargo-openr` does (build.rs), so objects are confined to their own
//! stick here too.
#[path = "cli/support.rs"]
#[allow(dead_code)]
mod support;

use std::path::{Path, PathBuf};
use std::time::Duration;

use sdk_runtime::boot::{self, Ended, Outcome, RunOptions};
use support::{build, sdk_root};

/// What `cargo openr run MS --speed max --for 2s --trace TRACE` sets, as a library caller.
fn options(ms: &Path, trace: &Path) -> RunOptions {
    let root = sdk_root();
    RunOptions {
        ms_dir: ms.to_path_buf(),
        ms_base: Some(openr_wrappers::install::base_tree(root, "ERS-7", "WCONSOLE/nomemprot")),
        design: "ERS-7".into(),
        run_for: Some(Duration::from_secs(2)),
        diag: sdk_runtime::runtime::Diag::new(true, false),
        lenient_connect: false,
        system_objects: openr_wrappers::install::system_objects(root),
        trace: Some(trace.to_path_buf()),
        speed: sdk_runtime::clock::Speed::Max,
        speaker_wav: None,
        mic_wav: None,
        images: None,
        camera_phase_ms: 0,
        control: None,
        peers: Default::default(),
        fp_traps: true,
        observers: Default::default(),
        watchdog: Duration::from_secs(5),
        net: Default::default(),
    }
}

fn run_in_thread(opts: RunOptions) -> std::thread::JoinHandle<Outcome> {
    std::thread::spawn(move || boot::run(&opts).unwrap_or_else(|e| panic!("{}: {e}", opts.ms_dir.display())))
}

fn time_up(what: &str, outcome: &Outcome) {
    assert_eq!(outcome.ended, Ended::TimeUp, "{what}: {outcome:?}");
    assert!(outcome.failures.is_empty(), "{what}: {:?}", outcome.failures);
    assert_eq!(outcome.frames, 250, "{what}: 2 s of 8 ms frames");
}

#[test]
fn two_runtimes_run_side_by_side_in_one_process() {
    let (a, b, s) = (build("movelegs"), build("movelegs"), build("savelog"));
    let traces = tempfile::tempdir().unwrap();
    let trace = |n: &str| -> PathBuf { traces.path().join(n) };

    // The reference: the same stick run by the binary, alone in its process.
    let out = support::run_ms(&a.ms(), &["--speed", "max", "--for", "2s", "--trace", trace("alone.jsonl").to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);

    // Two copies of one program (the same object code loaded twice, statics and all)
    // and a program that writes to its /MS, all three at once.
    let runs = [
        run_in_thread(options(&a.ms(), &trace("a.jsonl"))),
        run_in_thread(options(&b.ms(), &trace("b.jsonl"))),
        run_in_thread(options(&s.ms(), &trace("s.jsonl"))),
    ];
    let outcomes: Vec<Outcome> = runs.into_iter().map(|t| t.join().expect("a run panicked")).collect();
    for (what, o) in ["movelegs (a)", "movelegs (b)", "savelog"].iter().zip(&outcomes) {
        time_up(what, o);
    }

    // Each runtime drove its own robot on its own clock: each trace is the one the
    // program makes alone, to the byte.
    let alone = std::fs::read(trace("alone.jsonl")).unwrap();
    assert!(alone.len() > 10_000 && String::from_utf8_lossy(&alone).contains("\"joints\""), "a movelegs trace has joint commands");
    for n in ["a.jsonl", "b.jsonl"] {
        let t = std::fs::read(trace(n)).unwrap();
        assert!(t == alone, "{n} ({} bytes) differs from the run alone ({} bytes)", t.len(), alone.len());
    }
    let s_trace = std::fs::read(trace("s.jsonl")).unwrap();
    assert!(s_trace != alone, "savelog's robot is not movelegs'");

    // /MS is each object's own stick: savelog's file is in its MS only.
    let log = std::fs::read_to_string(s.ms().join("OPEN-R/MW/DATA/P/LOG.TXT")).unwrap();
    assert_eq!(log, "joint 1 error 10\njoint 2 error 20\njoint 3 error 30\n");
    for m in [&a, &b] {
        assert!(!m.ms().join("OPEN-R/MW/DATA").exists(), "{}: savelog's file went to another stick", m.ms().display());
    }

    // A runtime's run is over when boot::run returns; another can start in the same thread.
    let again = boot::run(&options(&a.ms(), &trace("again.jsonl"))).unwrap();
    time_up("movelegs again", &again);
    assert!(std::fs::read(trace("again.jsonl")).unwrap() == alone, "a second run in one thread differs");
}
