//! The front end: `new` (every template builds and runs unedited), `check` / `ms verify`
//! (every program passes, every broken fixture is reported with its code and place),
//! `doctor`, `env`, `config`.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{cargo_openr, cargo_openr_in, copy_tree, repo, run, run_ms, sdk_root};

fn text(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

fn make_install(dir: &Path) {
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", sdk_root().display())).arg("install").current_dir(dir));
    assert!(ok, "make install in {} failed:\n{log}", dir.display());
}

/// `cargo openr new`, `make install`, `cargo openr check`, `cargo openr run --for 1s`.
fn new_build_run(template: &str) -> (PathBuf, tempfile::TempDir, String) {
    let tmp = tempfile::tempdir().unwrap();
    let out = cargo_openr_in(tmp.path(), &["new", "test-dog", "--template", template], &[]);
    assert!(out.status.success(), "new --template {template}: {}", text(&out));
    let dir = tmp.path().join("test-dog");
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "test-dog");
    for f in ["Makefile", "README.md", "MS/OPEN-R/MW/CONF/OBJECT.CFG", "MS/OPEN-R/MW/CONF/CONNECT.CFG"] {
        assert!(dir.join(f).is_file(), "{template}: {f} missing");
    }
    make_install(&dir);
    let out = cargo_openr(&["check", dir.to_str().unwrap()]);
    assert!(out.status.success(), "check of the new {template} project: {}", text(&out));
    assert!(!text(&out).contains("warning["), "{}", text(&out));
    let r = run_ms(&dir.join("MS"), &["--for", "1s"]);
    assert_eq!(r.code, Some(0), "{template}: {}{}", r.stdout, r.stderr);
    (dir, tmp, r.stdout)
}

#[test]
fn new_hello_builds_and_runs() {
    let (dir, _tmp, stdout) = new_build_run("hello");
    assert!(dir.join("TestDog/stub.cfg").is_file() && dir.join("TestDog/testDog.ocf").is_file());
    assert!(fs::read_to_string(dir.join("MS/OPEN-R/MW/CONF/OBJECT.CFG")).unwrap().contains("/MS/OPEN-R/MW/OBJS/TESTDOG.BIN"));
    assert!(stdout.contains("!!! Hello from TestDog !!!"), "{stdout}");
    assert!(stdout.contains("TestDog : bye"), "{stdout}");
}

#[test]
fn new_subject_observer_builds_and_runs() {
    let (dir, _tmp, stdout) = new_build_run("subject-observer");
    assert!(dir.join("MS/OPEN-R/MW/OBJS/TESTDOGS.BIN").is_file() && dir.join("MS/OPEN-R/MW/OBJS/TESTDOGO.BIN").is_file());
    let received: Vec<&str> = stdout.lines().filter(|l| l.starts_with("TestDogObserver : received")).collect();
    assert_eq!(received, (1..=3).map(|i| format!("TestDogObserver : received \"hello {i} from TestDogSubject\"")).collect::<Vec<_>>(), "{stdout}");
}

#[test]
fn new_walk_builds_and_runs() {
    let (dir, _tmp, stdout) = new_build_run("walk");
    let connect = fs::read_to_string(dir.join("MS/OPEN-R/MW/CONF/CONNECT.CFG")).unwrap();
    assert!(connect.contains("TestDog.Move.OCommandVectorData.S OVirtualRobotComm.Effector.OCommandVectorData.O"));
    // 512 ms a posture: within 1 s the legs start towards the first three.
    for want in ["TestDog : posture 0 (stand)", "TestDog : posture 1 (crouch)"] {
        assert!(stdout.contains(want), "{want}: {stdout}");
    }
}

#[test]
fn new_refuses_bad_names_and_existing_dirs() {
    let tmp = tempfile::tempdir().unwrap();
    for (name, why) in [("9lives", "must start with a letter"), ("my dog", "is not allowed"), ("self", "reserved")] {
        let out = cargo_openr_in(tmp.path(), &["new", name], &[]);
        assert!(!out.status.success(), "{name}");
        assert!(text(&out).contains(why), "{name}: {}", text(&out));
    }
    assert_eq!(fs::read_dir(tmp.path()).unwrap().count(), 0, "a refused name wrote something");
    fs::create_dir(tmp.path().join("taken")).unwrap();
    fs::write(tmp.path().join("taken/keep.txt"), "mine").unwrap();
    let out = cargo_openr_in(tmp.path(), &["new", "dog", "--path", "taken"], &[]);
    assert!(!out.status.success());
    assert!(text(&out).contains("already exists and is not empty"), "{}", text(&out));
    assert_eq!(fs::read_dir(tmp.path().join("taken")).unwrap().count(), 1);
    // An empty directory is fine.
    fs::create_dir(tmp.path().join("empty")).unwrap();
    let out = cargo_openr_in(tmp.path(), &["new", "dog", "--path", "empty", "--template", "walk"], &[]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(tmp.path().join("empty/Dog/Dog.cc").is_file());
}

/// Every program of `testdata/programs` passes `check` (as a project) and `ms verify`
/// (services read from the objects) once built. A Remote Processing program whose robot
/// runs only the gateway (rp-legs) has no `MS/`: its sticks are `RP/robot/MS` (TCPGW.BIN,
/// whose services are ROBOTGW.CFG's lines) and `RP/host/MS` (HOSTGW.CFG's).
#[test]
fn check_passes_on_every_program() {
    let mut programs: Vec<PathBuf> = fs::read_dir(repo().join("testdata/programs"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.join("Makefile").is_file() && (p.join("MS").is_dir() || p.join("RP/robot/MS").is_dir()))
        .collect();
    assert!(programs.iter().any(|p| p.ends_with("rp-legs")), "{programs:?}");
    programs.sort();
    let root = sdk_root();
    let failures: Vec<String> = std::thread::scope(|s| {
        let chunks: Vec<Vec<PathBuf>> = programs.chunks(programs.len().div_ceil(4)).map(|c| c.to_vec()).collect();
        let handles: Vec<_> = chunks
            .into_iter()
            .map(|chunk| {
                s.spawn(move || {
                    let mut failures = Vec::new();
                    for src in chunk {
                        let name = src.file_name().unwrap().to_string_lossy().into_owned();
                        let tmp = tempfile::tempdir().unwrap();
                        let dir = tmp.path().join(&name);
                        copy_tree(&src, &dir);
                        let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", root.display())).arg("install").current_dir(&dir));
                        if !ok {
                            failures.push(format!("{name}: make install failed:\n{log}"));
                            continue;
                        }
                        let sticks: Vec<PathBuf> =
                            if dir.join("MS").is_dir() { vec![dir.join("MS")] } else { ["RP/robot/MS", "RP/host/MS"].iter().map(|s| dir.join(s)).collect() };
                        let mut runs = vec![vec!["check", dir.to_str().unwrap()]];
                        runs.extend(sticks.iter().map(|ms| vec!["ms", "verify", ms.to_str().unwrap()]));
                        for args in runs {
                            let out = cargo_openr(&args);
                            // rp-legs: `check` lints both sides' sticks.
                            let sides = name != "rp-legs" || args[0] != "check" || text(&out).contains("(RP/robot/MS, RP/host/MS)");
                            if !out.status.success() || text(&out).contains("warning[") || !sides {
                                failures.push(format!("{name}: `{}`:\n{}", args.join(" "), text(&out)));
                            }
                        }
                    }
                    failures
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `testdata/broken/<case>`: overlays on a built objcomm; `expect` lists `CODE path[:line]`.
#[test]
fn broken_fixtures_are_reported() {
    let base = tempfile::tempdir().unwrap();
    let built = base.path().join("objcomm");
    copy_tree(&repo().join("testdata/programs/objcomm"), &built);
    make_install(&built);
    let broken = repo().join("testdata/broken");
    let mut cases: Vec<PathBuf> = fs::read_dir(&broken).unwrap().flatten().map(|e| e.path()).filter(|p| p.is_dir()).collect();
    cases.sort();
    assert!(cases.len() >= 8, "{cases:?}");
    for case in cases {
        let name = case.file_name().unwrap().to_string_lossy().into_owned();
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("p");
        copy_tree(&built, &dir);
        copy_tree(&case, &dir);
        let expect = fs::read_to_string(dir.join("expect")).unwrap();
        fs::remove_file(dir.join("expect")).unwrap();
        let d = dir.to_str().unwrap();

        let human = cargo_openr(&["check", d]);
        let stderr = String::from_utf8_lossy(&human.stderr).into_owned();
        assert!(!human.status.success(), "{name}: check passed:\n{stderr}");
        let json = cargo_openr(&["check", d, "--message-format", "json"]);
        assert!(!json.status.success(), "{name}");
        let records: Vec<serde_json::Value> = String::from_utf8_lossy(&json.stdout)
            .lines()
            .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{name}: not one JSON object per line: {l:?}: {e}")))
            .collect();
        for r in &records {
            for field in ["level", "code", "message", "file", "line", "help"] {
                assert!(r.get(field).is_some(), "{name}: {field} missing in {r}");
            }
        }
        for want in expect.lines().filter(|l| !l.trim().is_empty()) {
            let (code, place) = want.split_once(' ').unwrap();
            let (path, line) = match place.rsplit_once(':') {
                Some((p, l)) => (p, Some(l.parse::<u64>().unwrap())),
                None => (place, None),
            };
            let level = if code.starts_with('E') { "error" } else { "warning" };
            let shown = format!("{level}[{code}]");
            let at = match line {
                Some(l) => format!("  --> {}:{l}", dir.join(path).display()),
                None => format!("  --> {}", dir.join(path).display()),
            };
            assert!(stderr.contains(&shown) && stderr.contains(&at), "{name}: want {shown} at {at}:\n{stderr}");
            let hit = records.iter().any(|r| {
                r["code"] == code && r["level"] == level && r["file"].as_str().is_some_and(|f| Path::new(f).ends_with(path)) && r["line"].as_u64() == line
            });
            assert!(hit, "{name}: no JSON record {want}: {records:?}");
        }
    }
}

#[test]
fn env_lists_what_the_build_sees() {
    let root = sdk_root().to_str().unwrap();
    let out = cargo_openr(&["env", "--format", "json", "--sdk", root]);
    assert!(out.status.success(), "{}", text(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["OPENRSDK_ROOT"], root);
    assert_eq!(v["CXX"], format!("{root}/bin/mipsel-linux-g++"));
    let flags: Vec<&str> = v["OPENR_CXXFLAGS"].as_array().unwrap().iter().map(|f| f.as_str().unwrap()).collect();
    assert!(flags.contains(&"-std=gnu++98") && flags.contains(&"-fPIC"), "{flags:?}");
    assert!(v["OPENR_INCLUDE_DIRS"][0].as_str().unwrap().ends_with("OPEN_R/include"));
    assert!(v["OPENR_DEFAULT_LIBS"].as_array().unwrap().iter().any(|l| l == "-lOPENR"));
    let out = cargo_openr(&["env", "--sdk", root]);
    let sh = String::from_utf8_lossy(&out.stdout);
    assert!(sh.contains(&format!("export OPENRSDK_ROOT='{root}'\n")), "{sh}");
    assert!(sh.contains("export OPENR_CXXFLAGS='-std=gnu++98 -fpermissive -fsanitize=unreachable -fPIC -Dasm(...)= -fsanitize=alignment'"), "{sh}");
    // What `sh` evaluates is what the JSON says.
    let (ok, echoed) = run(Command::new("sh").arg("-c").arg(format!("{sh}\nprintf %s \"$OPENR_CXXFLAGS\"")));
    assert!(ok);
    assert_eq!(echoed, flags.join(" "));
}

#[test]
fn config_precedence_cli_env_project_default() {
    let tmp = tempfile::tempdir().unwrap();
    let project = tmp.path();
    let cfg = |args: &[&str], env: &[(&str, &str)]| -> serde_json::Value {
        let mut all = vec!["config", "--format", "json"];
        all.extend_from_slice(args);
        let out = cargo_openr_in(project, &all, env);
        assert!(out.status.success(), "{}", text(&out));
        serde_json::from_slice(&out.stdout).unwrap()
    };
    let clean = [("OPENR_DESIGN", ""), ("OPENR_SPEED", ""), ("OPENRSDK_ROOT", "")];
    let v = cfg(&[], &clean);
    assert_eq!((v["design"]["value"].as_str(), v["design"]["source"].as_str()), (Some("ERS-7"), Some("default")));
    assert_eq!(v["speed"]["value"], "1");

    fs::write(project.join("openr.toml"), "# project settings\ndesign = \"ERS-210\"\nspeed = 4\nsdk = \"sdk\"\n").unwrap();
    let v = cfg(&[], &clean);
    assert_eq!(v["design"]["value"], "ERS-210");
    assert!(v["design"]["source"].as_str().unwrap().starts_with("project file"), "{v}");
    assert_eq!(v["speed"]["value"], "4");
    assert!(v["sdk"]["value"].as_str().unwrap().ends_with("/sdk"), "{v}");

    let root = sdk_root().to_str().unwrap();
    let v = cfg(&[], &[("OPENR_DESIGN", "ERS-220"), ("OPENR_SPEED", "max"), ("OPENRSDK_ROOT", root)]);
    assert_eq!((v["design"]["value"].as_str(), v["design"]["source"].as_str()), (Some("ERS-220"), Some("environment (OPENR_DESIGN)")));
    assert_eq!(v["speed"]["value"], "max");
    assert_eq!(v["sdk"]["value"], root);

    let v = cfg(&["--design", "ERS-7", "--sdk", root], &[("OPENR_DESIGN", "ERS-220")]);
    assert_eq!((v["design"]["value"].as_str(), v["design"]["source"].as_str()), (Some("ERS-7"), Some("command line (--design)")));
    assert_eq!(v["sdk"]["value"], root);

    // The human form names every source; errors in openr.toml carry file:line.
    let out = cargo_openr_in(project, &["config", "--sdk", root], &clean);
    let human = String::from_utf8_lossy(&out.stdout);
    assert!(human.contains(root) && human.contains("# command line (--sdk)") && human.contains("# project file"), "{human}");
    fs::write(project.join("openr.toml"), "design = \"ERS-7\"\ncolour = \"red\"\n").unwrap();
    let out = cargo_openr_in(project, &["config"], &clean);
    assert!(!out.status.success());
    assert!(text(&out).contains("openr.toml:2: unknown key `colour`"), "{}", text(&out));
}

#[test]
fn doctor_reports_the_host_and_the_sdk_root() {
    let root = sdk_root().to_str().unwrap();
    let out = cargo_openr(&["doctor", "--format", "json", "--sdk", root]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", text(&out)));
    assert_eq!(v["sdk"], root);
    let findings = v["findings"].as_array().unwrap();
    let get = |name: &str| findings.iter().find(|f| f["name"] == name).unwrap_or_else(|| panic!("{name} not checked: {v}"));
    for tool in ["g++", "gcc", "make", "ar", "strip", "gzip"] {
        assert_eq!(get(tool)["required"], true);
    }
    for opt in ["gdb", "valgrind", "python3", "MuJoCo + GL"] {
        let f = get(opt);
        assert_eq!(f["required"], false);
        assert!(f["ok"].as_bool().unwrap() || f["fix"].as_str().is_some(), "{f}");
    }
    let sdk = get("SDK root");
    assert_eq!(sdk["ok"], true, "{sdk}");
    assert!(sdk["detail"].as_str().unwrap().contains(root));
    // deps.sh installs gcc's plugin headers: the root has the alignment trap's plugin.
    let plugin = get("alignment trap plugin");
    assert_eq!(plugin["ok"], true, "{plugin}");
    // The tests build programs, so everything required is there: exit 0.
    assert!(out.status.success(), "{}", text(&out));
    let out = cargo_openr(&["doctor", "--sdk", "/nonexistent/sdk"]);
    let human = String::from_utf8_lossy(&out.stdout);
    assert!(human.contains("/nonexistent/sdk is not installed") && human.contains("fix: cargo openr sdk install --prefix /nonexistent/sdk"), "{human}");
}

#[test]
fn net_bind_without_room_for_every_robot_fails_before_the_world_starts() {
    let b = crate::support::build("hello");
    let out = run_ms(&b.ms(), &["--sim", "mujoco", "--net-bind", "127.255.255.255", "--robots", "2", "--for", "1s"]);
    assert_ne!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stderr.contains("--net-bind 127.255.255.255: no room for 2 consecutive robot addresses"), "{}", out.stderr);
    assert!(!out.stderr.contains("Simulating") && !out.stderr.contains("robot 0"), "nothing may start:\n{}", out.stderr);
}

#[test]
fn bench_refuses_a_readme_without_markers_before_measuring_anything() {
    let dir = tempfile::tempdir().unwrap();
    let readme = dir.path().join("README.md");
    fs::write(&readme, "# no table here\n").unwrap();
    // --repo points at an empty directory: had the README check come after the build of
    // bench/programs, the error would be about missing programs instead.
    let out = cargo_openr(&["bench", "--runs", "1", "--repo", dir.path().to_str().unwrap(), "--readme", readme.to_str().unwrap()]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(t.contains("has no `<!-- bench:begin"), "{t}");
    assert_eq!(fs::read_to_string(&readme).unwrap(), "# no table here\n", "nothing written");
    let out = cargo_openr(&["bench", "--runs", "0"]);
    assert_ne!(out.status.code(), Some(0), "{}", text(&out));
    assert!(text(&out).contains("--runs"), "{}", text(&out));
}

#[test]
fn bench_refuses_an_unknown_group() {
    let out = cargo_openr(&["bench", "--only", "camera,frobs"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(t.contains("frobs") && t.contains("camera, jitter"), "names the groups it knows: {t}");
}
