//! Remote Processing OPEN-R (remote-processing.md): the `RP_OPEN_R/bin` tools, host objects
//! built by unmodified RP host Makefiles, and all-host programs run by `start-rp-openr`.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{build, run_ms, sdk_root};

/// A loopback port nobody listens on (bound, then let go).
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port()
}

pub fn rp_tool(name: &str) -> PathBuf {
    sdk_root().join("RP_OPEN_R/bin").join(name)
}

fn text(out: &Output) -> (String, String) {
    (String::from_utf8_lossy(&out.stdout).into_owned(), String::from_utf8_lossy(&out.stderr).into_owned())
}

/// `start-rp-openr <args>` in `dir`, in virtual time.
fn start_rp(dir: &Path, args: &[&str]) -> Output {
    Command::new(rp_tool("start-rp-openr")).args(args).current_dir(dir).output().expect("run start-rp-openr")
}

const OBJCOMM_LINES: [&str; 5] = [
    "SampleSubject::Ready() : ASSERT READY",
    "SampleObserver::Notify() !!! Hello world !!!",
    "SampleSubject::Ready() : ASSERT READY",
    "SampleObserver::Notify() !!! Hello world again !!!",
    "SampleSubject::Ready() : ASSERT READY",
];

fn assert_objcomm(stdout: &str, stderr: &str) {
    let lines: Vec<&str> = stdout.lines().filter(|l| l.starts_with("Sample")).collect();
    assert!(lines.len() >= 5, "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert_eq!(lines[..5], OBJCOMM_LINES, "stdout:\n{stdout}\nstderr:\n{stderr}");
}

#[test]
fn rp_config_prints_the_flags_of_the_sdk_root() {
    let root = sdk_root();
    let (out, err) = text(&Command::new(rp_tool("rp-openr-config")).arg("--cflags").output().unwrap());
    assert!(err.is_empty(), "{err}");
    assert_eq!(out.lines().count(), 1, "{out}");
    for want in ["-std=gnu++98".to_string(), "-fPIC".into(), format!("-I{}", root.join("OPEN_R/include").display())] {
        assert!(out.split_whitespace().any(|f| f == want), "--cflags lacks {want}: {out}");
    }
    let (out, _) = text(&Command::new(rp_tool("rp-openr-config")).arg("--libs").output().unwrap());
    for want in ["-shared".to_string(), "-lOPENR".into(), "-lObjectComm".into(), format!("-L{}", root.join("OPEN_R/lib").display())] {
        assert!(out.split_whitespace().any(|f| f == want), "--libs lacks {want}: {out}");
    }
    let bad = Command::new(rp_tool("rp-openr-config")).arg("--cflagz").output().unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(text(&bad).1.contains("rp-openr-config: unknown option --cflagz"), "{}", text(&bad).1);
    assert!(bad.stdout.is_empty());
    let none = Command::new(rp_tool("rp-openr-config")).output().unwrap();
    assert_eq!(none.status.code(), Some(1));
    assert!(text(&none).1.contains("no option given"));
    assert!(root.join("RP_OPEN_R/include/MCOOP.h").is_file());
    assert!(root.join("RP_OPEN_R/lib/libOPENR.a").is_file());
}

#[test]
fn rp_small_tools_check_their_arguments() {
    let tmp = tempfile::tempdir().unwrap();
    let stub = Command::new(rp_tool("rp-openr-stubgen2")).current_dir(tmp.path()).output().unwrap();
    assert_eq!(stub.status.code(), Some(2));
    assert!(text(&stub).1.contains("expected exactly one argument, the stub.cfg"), "{}", text(&stub).1);
    let two = Command::new(rp_tool("rp-openr-stubgen2")).args(["a.cfg", "b.cfg"]).current_dir(tmp.path()).output().unwrap();
    assert_eq!(two.status.code(), Some(2));
    let missing = Command::new(rp_tool("rp-openr-stubgen2")).arg("stub.cfg").current_dir(tmp.path()).output().unwrap();
    assert_eq!(missing.status.code(), Some(1));
    assert!(fs::read_dir(tmp.path()).unwrap().next().is_none(), "a failed stubgen wrote files");
    let ipcrm = Command::new(rp_tool("rp-openr-ipcrm")).output().unwrap();
    assert!(ipcrm.status.success() && text(&ipcrm).0.contains("no IPC objects to remove"));
    let ipcrm_arg = Command::new(rp_tool("rp-openr-ipcrm")).arg("-a").output().unwrap();
    assert_eq!(ipcrm_arg.status.code(), Some(1));
    let setup = Command::new(rp_tool("setup-rp-openr")).output().unwrap();
    assert!(setup.status.success(), "{:?}", text(&setup));
}

/// Host objects are native shared objects, copied without gzip, with the runtime's entry symbols.
fn assert_host_bin(path: &Path) {
    use object::{Object, ObjectSymbol};
    let raw = fs::read(path).unwrap();
    assert!(raw.starts_with(b"\x7fELF"), "{} is not a plain ELF file", path.display());
    let file = object::File::parse(&*raw).unwrap();
    assert_eq!(file.kind(), object::ObjectKind::Dynamic, "{}", path.display());
    assert!(file.dynamic_symbols().any(|s| s.is_definition() && s.name() == Ok("ObjectEntryTable")));
}

#[test]
fn rp_host_objects_build_unmodified_and_run_all_host() {
    let built = build("rp-objcomm");
    let host = built.dir.path().join("rp-objcomm/RP/host");
    for bin in ["SUBJECT.BIN", "OBSERVER.BIN"] {
        assert_host_bin(&host.join("MS/OPEN-R/MW/OBJS").join(bin));
    }
    let out = start_rp(&host, &["--for", "2s", "--speed", "max"]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stdout}\n{stderr}");
    assert_objcomm(&stdout, &stderr);
    // Sony's start-up log: one line per object, in OBJECT.CFG order, before the objects speak.
    let a = stderr.find("Object 0: MS/OPEN-R/MW/OBJS/SUBJECT.BIN").expect(&stderr);
    let b = stderr.find("Object 1: MS/OPEN-R/MW/OBJS/OBSERVER.BIN").expect(&stderr);
    assert!(a < b, "{stderr}");
    // The same tree runs under `cargo openr run` too.
    let run = run_ms(&host.join("MS"), &["--for", "2s", "--speed", "max"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_objcomm(&run.stdout, &run.stderr);
}

#[test]
fn start_rp_openr_outside_a_host_directory_is_an_error() {
    let tmp = tempfile::tempdir().unwrap();
    let out = start_rp(tmp.path(), &[]);
    assert_eq!(out.status.code(), Some(1));
    let (_, err) = text(&out);
    assert!(err.contains("start-rp-openr: no ") && err.contains("MS/OPEN-R/MW/CONF/OBJECT.CFG"), "{err}");
    assert!(err.contains("run start-rp-openr from the directory that holds MS/"), "{err}");
}

#[test]
fn host_gateway_lines_are_checked_and_reported() {
    let built = build("rp-objcomm");
    let host = built.dir.path().join("rp-objcomm/RP/host");
    let conf = host.join("MS/OPEN-R/MW/CONF");
    // A proxy line alone (HelloWorld-stubgen/RP) does not block the start, even with no
    // robot there: a warning, and the objects (which make no OPENR:: call) run.
    let port = free_port();
    fs::write(conf.join("HOSTGW.CFG"), format!("\n# proxy only\n! ROBOT_PROXY {port} 127.0.0.1\n")).unwrap();
    // Real time: the gateway's first try is on a thread of its own, as it is on the robot.
    let out = start_rp(&host, &["--for", "3s"]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains(&format!("HOSTGW.CFG:3: robot 127.0.0.1:{port} not reachable")), "{stderr}");
    assert_objcomm(&stdout, &stderr);
    // A bad line: file and line, nothing runs.
    fs::write(conf.join("HOSTGW.CFG"), "TCPGateway.Cam.Frame.S 590020 127.0.0.1\n").unwrap();
    let out = start_rp(&host, &["--for", "1s", "--speed", "max"]);
    assert_eq!(out.status.code(), Some(1));
    let (stdout, stderr) = text(&out);
    assert!(stderr.contains("HOSTGW.CFG:1: `590020` is not a TCP port (1-65535)"), "{stderr}");
    assert!(!stdout.contains("ASSERT READY"), "{stdout}");
    // Robot-design sections in host CFG files are reported, not silently used.
    fs::write(conf.join("HOSTGW.CFG"), "").unwrap();
    let connect = fs::read_to_string(conf.join("CONNECT.CFG")).unwrap();
    fs::write(conf.join("CONNECT.CFG"), format!("[ERS-7]\n{connect}")).unwrap();
    let (stdout, stderr) = text(&start_rp(&host, &["--for", "1s", "--speed", "max"]));
    assert!(stderr.contains("CONNECT.CFG:1: robot-design section [ERS-7] in a host CFG file"), "{stderr}");
    assert_objcomm(&stdout, &stderr);
}

/// ObjectComm-multi/RP: fan-out and fan-in among host objects print what the robot build prints.
#[test]
fn rp_all_host_fan_out_and_fan_in_match_the_robot_run() {
    let built = build("rp-objcomm-multi");
    let dir = built.dir.path().join("rp-objcomm-multi");
    let host = start_rp(&dir.join("RP/host"), &["--for", "2s", "--speed", "max"]);
    let (host_out, host_err) = text(&host);
    assert!(host.status.success(), "{host_err}");
    let robot = run_ms(&dir.join("MS"), &["--for", "2s", "--speed", "max"]);
    assert_eq!(robot.code, Some(0), "{}", robot.stderr);
    let sample = |s: &str| -> Vec<String> {
        let mut v: Vec<String> = s.lines().filter(|l| l.starts_with("Sample")).map(str::to_string).collect();
        v.sort();
        v
    };
    let lines = sample(&host_out);
    assert_eq!(lines.iter().filter(|l| l.contains("::Notify()")).count(), 8, "{host_out}");
    assert_eq!(lines.iter().filter(|l| l.starts_with("SampleObserver3::Notify()")).count(), 4, "{host_out}");
    assert_eq!(lines, sample(&robot.stdout));
}

/// IG4.3: calls host programs cannot make return oFAIL under start-rp-openr, reported once.
#[test]
fn rp_host_objects_get_ofail_for_robot_only_calls() {
    let built = build("rp-hostapi");
    let dir = built.dir.path().join("rp-hostapi");
    let host = start_rp(&dir.join("RP/host"), &["--for", "1s", "--speed", "max"]);
    let (stdout, stderr) = text(&host);
    assert!(host.status.success(), "{stderr}");
    let lines: Vec<&str> = stdout.lines().filter(|l| l.starts_with("HostApi:")).collect();
    let host_lines = ["HostApi: GetRobotDesign ok (ERS-7)", "HostApi: NewSoundVectorData oFAIL", "HostApi: IPStack not found"];
    assert_eq!(lines, host_lines, "{stdout}\n{stderr}");
    let note = "OPENR::NewSoundVectorData: not available to Remote Processing OPEN-R host objects; returns oFAIL";
    assert_eq!(stderr.matches(note).count(), 1, "{stderr}");
    assert_eq!(stderr.matches("antStackRef: the ANT network library is not available to Remote Processing OPEN-R host objects").count(), 1, "{stderr}");
    // A host program with a HOSTGW.CFG is a host program under `cargo openr run` too.
    let conf = dir.join("RP/host/MS/OPEN-R/MW/CONF");
    // (No proxy line: with one, GetRobotDesign would ask the robot; rp_gateway tests that.)
    fs::write(conf.join("HOSTGW.CFG"), "# no channels\n").unwrap();
    let run = run_ms(&dir.join("RP/host/MS"), &["--for", "1s", "--speed", "max"]);
    assert_eq!(run.lines_starting("HostApi:"), host_lines, "{}", run.stderr);
    // The robot build of the same source has every call.
    let robot = run_ms(&dir.join("MS"), &["--for", "1s", "--speed", "max"]);
    assert_eq!(
        robot.lines_starting("HostApi:"),
        ["HostApi: GetRobotDesign ok (ERS-7)", "HostApi: NewSoundVectorData ok", "HostApi: IPStack found"],
        "{}",
        robot.stderr
    );
    assert!(!robot.stderr.contains("not available"), "{}", robot.stderr);
}
