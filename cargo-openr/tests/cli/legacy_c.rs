//! Real AIBO code of 2002–2008 compiles unmodified (issue 13) and C++ exceptions stop at
//! the entry boundary (issue 14): programs of `testdata/programs/` that use the names the
//! robot's toolchain (newlib, gcc 3.3's libstdc++, Sony's stubgen2) gave them.
use std::fs;

use crate::support::{build, make_install, run_ms, RunOutput};

const RUN: [&str; 4] = ["--speed", "max", "--for", "1s"];

fn assert_ok(out: &RunOutput) {
    assert_eq!(out.code, Some(0), "exit code\nstdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
}

fn assert_lines(out: &RunOutput, prefix: &str, want: &[&str]) {
    assert_eq!(out.lines_starting(prefix), want, "stdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
}

#[test]
fn a_class_header_with_using_namespace_std_is_included_by_the_stub() {
    let p = build("using-std");
    let out = run_ms(&p.ms(), &RUN);
    assert_ok(&out);
    assert_lines(&out, "MotionList :", &["MotionList : 3 motions: sit stand walk", "MotionList : total 2400 ms", "MotionList : stopped"]);
}

#[test]
fn newlib_string_extensions_work_without_c_headers() {
    let p = build("newlib-string");
    let out = run_ms(&p.ms(), &RUN);
    assert_ok(&out);
    assert_lines(
        &out,
        "ConfigReader :",
        &[
            "ConfigReader : mode 'Penalty' kept as 'penal' (5 of 7 chars)",
            "ConfigReader : unknown key 'colour'",
            "ConfigReader : name = Aibo7, team = RED, player = 2, mode = penal",
            "ConfigReader : stricmp(\"ERS-7\", \"ers-7\") = 0",
        ],
    );
}

#[test]
fn math_functions_and_m_pi_work_without_math_h() {
    let p = build("implicit-math");
    let out = run_ms(&p.ms(), &RUN);
    assert_ok(&out);
    // The same computation as LegKin.cc, here.
    let (l1, l2) = (69.5_f64, 76.4_f64);
    let (a, b) = (30.0_f64.to_radians(), 45.0_f64.to_radians());
    let x = l1 * a.sin() + l2 * (a + b).sin();
    let z = -(l1 * a.cos() + l2 * (a + b).cos());
    let reach = (x * x + z * z).sqrt();
    let angle = x.atan2(z.abs()).to_degrees();
    let slope = 10.0_f64.to_radians().tan();
    let want = [
        format!("LegKin : foot x = {x:.3} mm, z = {z:.3} mm"),
        format!("LegKin : reach = {reach:.3} mm, angle = {angle:.3} deg"),
        format!("LegKin : tan(10 deg) = {slope:.5}, rise over 40 mm = {:.3} mm", 40.0 * slope),
        "LegKin : sin(pi/2) + cos(pi) = 0.0, fabs(-2.5) = 2.5".to_string(),
    ];
    let want: Vec<&str> = want.iter().map(String::as_str).collect();
    assert_lines(&out, "LegKin :", &want);
    assert_eq!(want[0], "LegKin : foot x = 108.547 mm, z = -79.963 mm");
}

#[test]
fn a_subname_used_twice_builds_with_the_projects_def_h_patch() {
    let (p, ok, log) = make_install("dup-subname", &[]);
    assert!(ok, "{log}");
    assert!(
        log.contains("stubgen2: stub.cfg:14: warning: SubName 'Stdin' is already used by the observer service on stub.cfg:13;"),
        "stubgen2 warns with file:line:\n{log}"
    );
    let def = fs::read_to_string(p.dir.path().join("dup-subname/Console/def.h")).unwrap();
    assert!(def.contains("const int obsStdin = 0;\n"), "{def}");
    assert!(def.contains("const int obsStdinLine = 1;\n"), "the Makefile's sed step applied:\n{def}");
    let out = run_ms(&p.ms(), &RUN);
    assert_ok(&out);
    assert_lines(
        &out,
        "Console :",
        &["Console : obsStdin = 0 (Console.Stdin.char.O)", "Console : obsStdinLine = 1 (Console.Stdin.RCRegion.O)", "Console : 2 observers, 12 basic entries"],
    );
}

#[test]
fn an_exception_escaping_do_start_is_reported_and_fails_the_run() {
    let p = build("throw-start");
    let out = run_ms(&p.ms(), &RUN);
    assert_ne!(out.code, Some(0), "stdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("Calib : loading /MS/OPEN-R/MW/DATA/P/CALIB.DAT"), "{}", out.stdout);
    assert!(out.stderr.contains("error: object `calib`: uncaught C++ exception std::runtime_error in DoStart: calibration file missing\n"), "{}", out.stderr);
    assert!(out.stderr.contains("error: object `calib`") && out.stderr.contains("SIGABRT"), "then the crash report:\n{}", out.stderr);
    assert!(!out.stderr.contains("Rust cannot catch foreign exceptions"), "{}", out.stderr);
    assert!(!out.stdout.contains("Calib : offsets"), "{}", out.stdout);

    // An exception that is not a std::exception: its demangled type, no what().
    let data = p.ms().join("OPEN-R/MW/DATA/P");
    fs::create_dir_all(&data).unwrap();
    fs::write(data.join("CALIB.DAT"), "1.5\nabc\n2.0\n").unwrap();
    let out = run_ms(&p.ms(), &RUN);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("error: object `calib`: uncaught C++ exception CalibError in DoStart\n"), "{}", out.stderr);

    // A good file: no exception, a clean run.
    fs::write(data.join("CALIB.DAT"), "1.5\n-2.0\n0.5\n").unwrap();
    let out = run_ms(&p.ms(), &RUN);
    assert_ok(&out);
    assert_lines(&out, "Calib :", &["Calib : loading /MS/OPEN-R/MW/DATA/P/CALIB.DAT", "Calib : offsets 1.5 -2.0 0.5"]);
    assert!(!out.stderr.contains("uncaught"), "{}", out.stderr);
}

#[test]
fn an_exception_escaping_a_notify_function_names_it() {
    let p = build("throw-notify");
    let out = run_ms(&p.ms(), &RUN);
    assert_ne!(out.code, Some(0), "stdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("SampleObserver::Notify() !!! Hello world !!! (length 19)"), "the first string is handled:\n{}", out.stdout);
    assert!(
        out.stderr.contains("error: object `sampleObserver`: uncaught C++ exception std::out_of_range in Notify: vector::_M_range_check"),
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("crashed with SIGABRT"), "{}", out.stderr);
}
