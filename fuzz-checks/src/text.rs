//! The line-based formats: each check parses, and then asserts that an error names a
//! line that exists, and that what was accepted prints back to text that parses to the
//! same values.
use std::path::Path;

use sdk_runtime::cfg;
use sdk_runtime::ErrorKind as RtKind;

/// `cargo-openr` is a binary crate: its `openr.toml` parser is compiled in here from
/// its own source file, unchanged.
#[allow(dead_code)]
#[path = "../../cargo-openr/src/ops/config.rs"]
mod openr_config;

const DESIGNS: [&str; 3] = ["ERS-7", "ERS-210", "ERS-220"];

/// Lines as `text.split('\n')` counts them (the last may be empty).
fn split_lines(text: &str) -> usize {
    text.split('\n').count()
}

/// A runtime configuration error must name a line of the file; `whole_file` lists the
/// messages about the file as a whole, which may have none.
fn assert_config_line(e: &sdk_runtime::Error, lines: usize, whole_file: &[&str]) {
    match e.kind() {
        RtKind::Config { line: Some(l), .. } => assert!((1..=lines).contains(l), "line {l} of {lines}: {e}"),
        RtKind::Config { line: None, message, .. } => {
            assert!(whole_file.iter().any(|m| message.starts_with(m)), "no line: {e}")
        }
        _ => panic!("not a configuration error: {e}"),
    }
}

/// OBJECT.CFG, CONNECT.CFG, DESIGNDB.CFG (read as the runtime reads them: lossy UTF-8).
pub fn ms_cfg(data: &[u8]) -> bool {
    let mut accepted = false;
    let text = String::from_utf8_lossy(data);
    let n = split_lines(&text);
    let path = Path::new("CONF/X.CFG");
    for design in DESIGNS {
        let lines = cfg::lines_for_design(&text, design);
        for w in lines.windows(2) {
            assert!(w[0].number < w[1].number, "line numbers out of order");
        }
        for l in &lines {
            assert!((1..=n).contains(&l.number));
            assert!(!l.fields.is_empty() && l.fields.iter().all(|f| !f.is_empty() && !f.contains(char::is_whitespace)));
        }
        match cfg::parse_object_cfg(path, &text, design) {
            Ok(objs) => {
                let printed: String = objs.iter().map(|(_, p)| format!("{p}\n")).collect();
                let again = cfg::parse_object_cfg(path, &printed, design).expect("printed OBJECT.CFG parses");
                assert_eq!(paths(&again), paths(&objs));
                accepted = true;
            }
            Err(e) => assert_config_line(&e, n, &["lists no object"]),
        }
        match cfg::parse_connect_cfg(path, &text, design) {
            Ok(conns) => {
                let printed: String = conns.iter().map(|c| format!("{} {}\n", c.subject, c.observer)).collect();
                let again = cfg::parse_connect_cfg(path, &printed, design).expect("printed CONNECT.CFG parses");
                let pairs = |v: &[cfg::Connection]| v.iter().map(|c| (c.subject.clone(), c.observer.clone())).collect::<Vec<_>>();
                assert_eq!(pairs(&again), pairs(&conns));
                accepted |= !conns.is_empty();
            }
            Err(e) => assert_config_line(&e, n, &[]),
        }
        match cfg::parse_design_db(path, &text, design) {
            Ok(keys) => {
                let printed: String = keys.iter().map(|(k, p)| format!("{k} {p}\n")).collect();
                assert_eq!(cfg::parse_design_db(path, &printed, design).expect("printed DESIGNDB.CFG parses"), keys);
            }
            Err(e) => assert_config_line(&e, n, &[]),
        }
    }
    accepted
}

fn paths(v: &[(usize, String)]) -> Vec<&str> {
    v.iter().map(|(_, p)| p.as_str()).collect()
}

/// WLANCONF.TXT / WLANDFLT.TXT: `KEY=VALUE` lines; nothing is an error.
pub fn wlan(data: &[u8]) -> bool {
    let text = String::from_utf8_lossy(data);
    let map = openr_ipstack::config::parse_wlan(&text);
    for (k, v) in &map {
        assert!(!k.is_empty() && k.trim() == k && v.trim() == v && !k.contains(['=', '#']) && !v.contains('#'));
    }
    let printed: String = map.iter().map(|(k, v)| format!("{k}={v}\n")).collect();
    assert_eq!(openr_ipstack::config::parse_wlan(&printed), map);
    !map.is_empty()
}

/// stub.cfg: errors carry a line of the file; what is accepted generates, and prints
/// back to a stub.cfg that parses to the same configuration.
pub fn stub_cfg(data: &[u8]) -> bool {
    let text = String::from_utf8_lossy(data);
    let n = text.strip_suffix('\n').unwrap_or(&text).split('\n').count();
    let cfg = match stubgen::parse_str("stub.cfg", &text) {
        Ok(c) => c,
        Err(e) => {
            let l = e.line().unwrap_or_else(|| panic!("no line: {e}"));
            assert!((1..=n.max(1)).contains(&l), "line {l} of {n}: {e}");
            return false;
        }
    };
    let files = stubgen::generate(&cfg).unwrap_or_else(|e| panic!("accepted but not generated: {e}"));
    assert_eq!(files.len(), 4);
    let _ = stubgen::warnings(&cfg);
    let printed = print_stub_cfg(&cfg);
    let again = stubgen::parse_str("printed.cfg", &printed).unwrap_or_else(|e| panic!("printed stub.cfg: {e}\n{printed}"));
    assert_eq!(services(&again), services(&cfg), "{printed}");
    assert_eq!((&again.object_name, &again.extras), (&cfg.object_name, &cfg.extras));
    true
}

fn print_stub_cfg(c: &stubgen::StubCfg) -> String {
    let f = |x: &Option<String>| x.as_ref().map_or("null".to_string(), |n| format!("{n}()"));
    let mut s = format!("ObjectName : {}\nNumOfOSubject : {}\nNumOfOObserver : {}\n", c.object_name, c.subjects.len(), c.observers.len());
    for svc in c.subjects.iter().chain(&c.observers) {
        s += &format!("Service : \"{}\", {}, {}\n", svc.name, f(&svc.func1), f(&svc.func2));
    }
    for e in &c.extras {
        s += &format!("Extra : {e}()\n");
    }
    s
}

type ServiceView = (String, String, String, Option<String>, Option<String>, stubgen::ServiceKind);

fn services(c: &stubgen::StubCfg) -> Vec<ServiceView> {
    c.subjects.iter().chain(&c.observers).map(|s| (s.name.clone(), s.sub_name.clone(), s.data_name.clone(), s.func1.clone(), s.func2.clone(), s.kind)).collect()
}

/// `.ocf` as mkbin reads it: bytes decoded (error at the line of a bad byte), parsed.
pub fn ocf(data: &[u8]) -> bool {
    use openr_wrappers::ocf;
    let path = Path::new("x.ocf");
    let line_of = |e: &openr_wrappers::Error| match e.kind() {
        openr_wrappers::ErrorKind::Ocf { line, .. } => *line,
        _ => panic!("not an ocf error: {e}"),
    };
    let text = match ocf::decode(path, data) {
        Ok(t) => t,
        Err(e) => {
            let l = line_of(&e);
            assert!((1..=split_lines(&String::from_utf8_lossy(data))).contains(&l), "{e}");
            return false;
        }
    };
    match ocf::parse(path, text) {
        Ok(o) => {
            let pick = |b: bool, yes: &'static str, no: &'static str| if b { yes } else { no };
            let printed = format!(
                "object {} {} {} {} {} {} {}\n",
                o.name,
                o.stack,
                o.heap,
                o.priority,
                pick(o.cache, "cache", "nocache"),
                pick(o.tlb, "tlb", "notlb"),
                pick(o.user_mode, "user", "kernel")
            );
            assert_eq!(ocf::parse(path, &printed).unwrap_or_else(|e| panic!("printed ocf: {e}")), o);
            true
        }
        Err(e) => {
            let l = line_of(&e);
            assert!((1..=text.lines().count().max(1)).contains(&l), "line {l}: {e}");
            false
        }
    }
}

/// `<file>:<line>: ` at the start of a message: the line, which must exist.
fn assert_message_line(message: &str, file: &str, lines: usize) {
    let rest = message.strip_prefix(file).and_then(|r| r.strip_prefix(':')).unwrap_or_else(|| panic!("no file: {message}"));
    let (l, _) = rest.split_once(": ").unwrap_or_else(|| panic!("no line: {message}"));
    let l: usize = l.parse().unwrap_or_else(|_| panic!("no line: {message}"));
    assert!((1..=lines).contains(&l), "line {l} of {lines}: {message}");
}

/// HOSTGW.CFG / ROBOTGW.CFG.
pub fn hostgw(data: &[u8]) -> bool {
    use openr_wrappers::rp::gwcfg::{parse, GwLine};
    let text = String::from_utf8_lossy(data);
    let gw = match parse("HOSTGW.CFG", &text) {
        Ok(g) => g,
        Err(e) => {
            assert_message_line(&e.to_string(), "HOSTGW.CFG", text.lines().count());
            return false;
        }
    };
    let mut printed = String::new();
    let mut want = Vec::new();
    for (i, g) in gw.iter().enumerate() {
        let addr = |a: &Option<std::net::Ipv4Addr>| a.as_ref().map_or(String::new(), |a| format!(" {a}"));
        match g {
            GwLine::Proxy { port, addr: a, .. } => {
                printed += &format!("!ROBOT_PROXY {port}{}\n", addr(a));
                want.push(GwLine::Proxy { line: i + 1, port: *port, addr: a.clone() });
            }
            GwLine::Service { name, port, addr: a, options, .. } => {
                printed += &format!("{name} {port}{}{}\n", addr(a), options.iter().map(|o| format!(" {o}")).collect::<String>());
                want.push(GwLine::Service { line: i + 1, name: name.clone(), port: *port, addr: a.clone(), options: options.clone() });
            }
        }
    }
    assert_eq!(parse("printed", &printed).unwrap_or_else(|e| panic!("printed HOSTGW.CFG: {e}\n{printed}")), want, "{printed}");
    !gw.is_empty()
}

/// A TOML basic string: quoted; `\`, `"` and control characters escaped.
fn toml_string(v: &str) -> String {
    let mut s = String::from("\"");
    for c in v.chars() {
        match c {
            '"' | '\\' => s.extend(['\\', c]),
            c if c.is_control() => s += &format!("\\u{:04X}", c as u32),
            c => s.push(c),
        }
    }
    s + "\""
}

/// `openr.toml` (the TOML subset of cargo-openr's project file).
pub fn openr_toml(data: &[u8]) -> bool {
    let text = String::from_utf8_lossy(data);
    let path = Path::new("openr.toml");
    // Any one-line value can be written: the first line, as a flag string.
    let value = text.lines().next().unwrap_or("").trim();
    let line = format!("cxxflags = {} # a comment\n", toml_string(value));
    let got = openr_config::parse_project_file(path, &line).unwrap_or_else(|e| panic!("{line}: {e}"));
    assert_eq!(got.cxxflags.map(|(v, _)| v).as_deref(), Some(value), "{line}");
    let pf = match openr_config::parse_project_file(path, &text) {
        Ok(p) => p,
        Err(e) => {
            // An error at the end of the file may name the line after a final line end.
            assert_message_line(&e.to_string(), "openr.toml", split_lines(&text));
            return false;
        }
    };
    let keys = [("sdk", &pf.sdk), ("design", &pf.design), ("speed", &pf.speed), ("cxxflags", &pf.cxxflags), ("ldflags", &pf.ldflags), ("base", &pf.base)];
    let mut printed = String::new();
    for (key, v) in keys {
        if let Some((v, _)) = v {
            printed += &format!("{key} = {}\n", toml_string(v));
        }
    }
    let again = openr_config::parse_project_file(path, &printed).unwrap_or_else(|e| panic!("printed openr.toml: {e}\n{printed}"));
    let values = |p: &openr_config::ProjectFile| [&p.sdk, &p.design, &p.speed, &p.cxxflags, &p.ldflags, &p.base].map(|v| v.as_ref().map(|(s, _)| s.clone()));
    assert_eq!(values(&again), values(&pf), "{printed}");
    !printed.is_empty()
}
