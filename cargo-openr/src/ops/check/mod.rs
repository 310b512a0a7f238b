//! `cargo openr check` and `cargo openr ms verify`: lint the wiring that causes most AIBO
//! failures before anything boots — 8.3 names, OBJECT.CFG entries that are not loadable
//! objects, CONNECT.CFG lines naming services nobody registers, in the wrong order, with
//! different DataNames or listed twice, stub.cfg files stubgen2 rejects, bad `.ocf`s.
//!
//! Where the services come from:
//! * in a project (`check`), from its `stub.cfg` files, parsed by the `stubgen` crate;
//! * in a bare Memory Stick tree (`ms verify`), and for objects with hand-written stubs,
//!   from the objects themselves: stubgen2 writes the service names into `def.h` as
//!   string literals, so every 4-part name ending `.S` or `.O` in an object's read-only
//!   data is taken as one of its services. An object that builds names at run time
//!   escapes this heuristic (its connections are then reported as unknown services).
//!
//! The system services of `OVirtualRobotComm` and `OVirtualRobotAudioComm` are known, and
//! on a Remote Processing stick those of its TCP gateway, read from ROBOTGW.CFG or
//! HOSTGW.CFG ([`rp`]).
use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::{Path, PathBuf};

use sdk_runtime::cfg::{lines_for_design, CfgFile};
use sdk_runtime::ms::{is_eight_dot_three, MsDir};

use crate::ops::diag::{Diagnostic, Report};

mod rp;

/// The services the system objects register (object-model 1.4).
pub const SYSTEM_SERVICES: &[&str] = &[
    "OVirtualRobotComm.Effector.OCommandVectorData.O",
    "OVirtualRobotComm.Sensor.OSensorFrameVectorData.S",
    "OVirtualRobotComm.FbkImageSensor.OFbkImageVectorData.S",
    "OVirtualRobotAudioComm.Speaker.OSoundVectorData.O",
    "OVirtualRobotAudioComm.Mic.OSoundVectorData.S",
];

/// DataName of the dummy services stubgen2 forces on objects that need none.
const DO_NOT_CONNECT: &str = "DoNotConnect";

/// What to lint.
#[derive(Debug, Clone)]
pub struct CheckOptions {
    /// The Memory Stick directory (holds `OPEN-R/`).
    pub ms: PathBuf,
    /// `stub.cfg` files giving the services (empty: take them from the objects).
    pub stubs: Vec<PathBuf>,
    /// `.ocf` files to check.
    pub ocfs: Vec<PathBuf>,
    /// Robot design whose CFG sections apply.
    pub design: String,
    /// Take a stub's services only if its object is loaded: the stubs are shared by the
    /// sticks of a Remote Processing program's sides (`RP/robot`, `RP/host`).
    pub loaded_stubs_only: bool,
}

/// The sides of a Remote Processing program without a stick of its own (Sony's layout
/// when the robot runs only the gateway, as in LMasterRSlave7/RP).
const RP_SIDES: [&str; 2] = ["RP/robot/MS", "RP/host/MS"];

/// Finds what `check` lints in the project at `dir`: its `MS/` tree — or, for a Remote
/// Processing program with none, the sticks of its sides ([`RP_SIDES`]) — and every
/// `stub.cfg` and `.ocf` outside them (hidden directories and `target/` skipped).
pub fn project_inputs(dir: &Path, design: &str) -> anyhow::Result<Vec<CheckOptions>> {
    let own = dir.join("MS");
    let sides = !own.join("OPEN-R").is_dir();
    let sticks: Vec<PathBuf> = if sides { RP_SIDES.iter().map(|s| dir.join(s)).filter(|ms| ms.join("OPEN-R").is_dir()).collect() } else { vec![own] };
    if sticks.is_empty() {
        anyhow::bail!(
            "`{}` is not an OPEN-R project: no MS/OPEN-R directory, nor RP/robot/MS or RP/host/MS (for a bare Memory Stick tree use `cargo openr ms verify`)",
            dir.display()
        );
    }
    let mut stubs = Vec::new();
    let mut ocfs = Vec::new();
    collect_sources(dir, &sticks, &mut stubs, &mut ocfs, 0);
    stubs.sort();
    ocfs.sort();
    Ok(sticks
        .into_iter()
        .map(|ms| CheckOptions { ms, stubs: stubs.clone(), ocfs: ocfs.clone(), design: design.to_string(), loaded_stubs_only: sides })
        .collect())
}

fn collect_sources(dir: &Path, ms: &[PathBuf], stubs: &mut Vec<PathBuf>, ocfs: &mut Vec<PathBuf>, depth: usize) {
    let Ok(rd) = std::fs::read_dir(dir) else { return };
    for e in rd.flatten() {
        let path = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if name.starts_with('.') || ms.contains(&path) {
            continue;
        }
        let Ok(ft) = e.file_type() else { continue };
        if ft.is_dir() {
            if depth < 8 && name != "target" {
                collect_sources(&path, ms, stubs, ocfs, depth + 1);
            }
        } else if name == "stub.cfg" {
            stubs.push(path);
        } else if name.ends_with(".ocf") {
            ocfs.push(path);
        }
    }
}

/// Where a service was found.
#[derive(Debug, Clone)]
struct Origin {
    file: PathBuf,
    line: Option<usize>,
    /// A line of the gateway's CFG file.
    gateway: bool,
}

/// Lints a Memory Stick tree (and the sources given with it).
pub fn check(opts: &CheckOptions) -> anyhow::Result<Report> {
    let mut report = Report::default();
    let ms = MsDir::new(&opts.ms).map_err(|e| anyhow::anyhow!("cannot open the Memory Stick tree `{}`: {e}", opts.ms.display()))?;
    // Paths in diagnostics are shown under the directory as the user named it.
    let shown = |p: &Path| -> PathBuf { p.strip_prefix(ms.root()).map_or_else(|_| p.to_path_buf(), |rel| opts.ms.join(rel)) };
    let Some(open_r) = ms.existing("/MS/OPEN-R") else {
        anyhow::bail!("`{}` is not a Memory Stick tree: no OPEN-R directory", opts.ms.display());
    };
    check_names(&open_r, &shown, &mut report);

    let mut services: BTreeMap<String, Origin> = BTreeMap::new();
    let mut stub_services = Vec::new();
    for stub in &opts.stubs {
        match stubgen::parse_files(std::slice::from_ref(stub)) {
            Ok(cfg) => {
                for s in cfg.subjects.iter().chain(&cfg.observers) {
                    stub_services.push((s.name.clone(), Origin { file: s.file.clone(), line: Some(s.line), gateway: false }));
                }
            }
            Err(e) => {
                let file = e.file().map_or_else(|| stub.clone(), Path::to_path_buf);
                report.push(Diagnostic::error("E0008", format!("stub.cfg rejected by stubgen2: {}", e.message())).at(file, e.line()).help(
                    "NumOfOSubject / NumOfOObserver must equal the number of `Service : \"Obj.Sub.Data.S|O\", …` lines of each kind (at least one each)",
                ));
            }
        }
    }
    for ocf in &opts.ocfs {
        if let Err(e) = openr_wrappers::ocf::read(ocf) {
            let d = match e.kind() {
                openr_wrappers::ErrorKind::Ocf { path, line, message } => {
                    Diagnostic::error("E0009", format!("malformed .ocf: {message}")).at(path, Some(*line))
                }
                _ => Diagnostic::error("E0009", format!("unreadable .ocf: {e}")).at(ocf, None),
            };
            report.push(d.help("the form is `object NAME STACK HEAP PRIO CACHE TLB MODE`, e.g. `object myObject 3072 16384 128 cache tlb user`"));
        }
    }

    let loaded = check_objects(&ms, &opts.design, &shown, &mut report);
    let object_of = |name: &str| name.split('.').next().unwrap_or("").to_string();
    let loaded_objects: HashSet<String> = loaded.objects.iter().flat_map(|(_, found)| found.iter().map(|n| object_of(n))).collect();
    for (name, origin) in stub_services {
        if !opts.loaded_stubs_only || loaded_objects.contains(&object_of(&name)) {
            services.entry(name).or_insert(origin);
        }
    }
    for (bin, found) in loaded.objects {
        for name in found {
            services.entry(name).or_insert(Origin { file: bin.clone(), line: None, gateway: false });
        }
    }
    let robot_gateway = loaded.robot_gateway.map(|line| (loaded.object_cfg.as_path(), line));
    let gateway = rp::services(&ms, robot_gateway, &shown, &mut report);
    for g in &gateway {
        services.entry(g.name.clone()).or_insert(Origin { file: g.file.clone(), line: Some(g.line), gateway: true });
    }
    let unknown = |name: &str| rp::unknown_help(&ms, name, &gateway, robot_gateway.is_some());
    check_connections(&ms, &opts.design, &services, &unknown, &shown, &mut report);
    Ok(report)
}

/// Every name under `MS/OPEN-R` (dot files, host-only placeholders such as `.keep`, are
/// skipped).
fn check_names(dir: &Path, shown: &dyn Fn(&Path) -> PathBuf, report: &mut Report) {
    let Ok(rd) = std::fs::read_dir(dir) else { return };
    let mut entries: Vec<_> = rd.flatten().collect();
    entries.sort_by_key(|e| e.file_name());
    for e in entries {
        let name = e.file_name().to_string_lossy().into_owned();
        if name.starts_with('.') {
            continue;
        }
        let path = e.path();
        if !is_eight_dot_three(&name) {
            report.push(
                Diagnostic::error("E0001", format!("`{name}` is not an 8.3 file name"))
                    .at(shown(&path), None)
                    .help("names on the Memory Stick are FAT 8.3: at most 8 characters, optionally `.` and at most 3 (letters, digits, $&#{}~%'()-@^`!_)"),
            );
        } else if name.chars().any(|c| c.is_ascii_lowercase()) {
            report.push(
                Diagnostic::warning("W0001", format!("`{name}` has lower-case letters"))
                    .at(shown(&path), None)
                    .help(format!("FAT stores names upper case; call it `{}`", name.to_ascii_uppercase())),
            );
        }
        if e.file_type().is_ok_and(|t| t.is_dir()) {
            check_names(&path, shown, report);
        }
    }
}

/// What OBJECT.CFG loads.
#[derive(Default)]
struct Loaded {
    /// OBJECT.CFG as shown.
    object_cfg: PathBuf,
    /// Per loadable object, the service names found in its read-only data.
    objects: Vec<(PathBuf, Vec<String>)>,
    /// The line listing the robot's TCP gateway, if one does.
    robot_gateway: Option<usize>,
}

/// OBJECT.CFG: every entry exists and is a loadable object.
fn check_objects(ms: &MsDir, design: &str, shown: &dyn Fn(&Path) -> PathBuf, report: &mut Report) -> Loaded {
    let cfg = match CfgFile::find(ms, "OBJECT.CFG") {
        Ok(Some(cfg)) => cfg,
        Ok(None) => {
            report.push(
                Diagnostic::error("E0002", "OBJECT.CFG not found")
                    .at(shown(&ms.root().join("OPEN-R/MW/CONF/OBJECT.CFG")), None)
                    .help("list the objects to load, one `/MS/OPEN-R/MW/OBJS/NAME.BIN` a line"),
            );
            return Loaded::default();
        }
        Err(e) => {
            report.push(Diagnostic::error("E0002", e.to_string()));
            return Loaded::default();
        }
    };
    let file = shown(&cfg.path);
    let mut out = Loaded { object_cfg: file.clone(), ..Loaded::default() };
    let lines = lines_for_design(&cfg.text, design);
    // A host stick may run its gateway alone (a relay; remote-processing 4).
    if lines.is_empty() && ms.existing_in_program("/MS/OPEN-R/MW/CONF/HOSTGW.CFG").is_none() {
        report.push(Diagnostic::error("E0002", format!("OBJECT.CFG lists no object for robot design {design}")).at(&file, None));
    }
    for line in lines {
        let ms_path = &line.fields[0];
        if line.fields.len() > 1 {
            report.push(
                Diagnostic::error("E0002", format!("expected one path per line, found `{}`", line.fields.join(" ")))
                    .at(&file, Some(line.number))
                    .help("one absolute path a line: /MS/OPEN-R/MW/OBJS/NAME.BIN"),
            );
            continue;
        }
        let found = ms.existing(ms_path).filter(|p| p.is_file());
        let image = found.as_deref().and_then(|p| std::fs::read(p).ok());
        if rp::is_robot_gateway(ms_path, found.as_ref().and(image.as_deref())) {
            out.robot_gateway = Some(line.number);
            continue;
        }
        let Some(host) = found else {
            report.push(
                Diagnostic::error("E0002", format!("object `{ms_path}` not found on the Memory Stick"))
                    .at(&file, Some(line.number))
                    .help("build and install it (`make OPENRSDK_ROOT=… install`), or fix the path (absolute, starting with /MS/)"),
            );
            continue;
        };
        let elf = match sdk_runtime::loader::read_bin(&host) {
            Ok(elf) => elf,
            Err(e) => {
                report.push(
                    Diagnostic::error("E0003", format!("`{ms_path}` is not a loadable object: {e}"))
                        .at(&file, Some(line.number))
                        .help("install the output of mkbin (`gzip -c x.bin > …` or gzcp)"),
                );
                continue;
            }
        };
        if let Some(problem) = object_problem(&host, &elf) {
            report.push(
                Diagnostic::error("E0003", format!("`{ms_path}` is not a loadable object: {problem}"))
                    .at(&file, Some(line.number))
                    .help("build it with the SDK root's mkbin from a stub (stubgen2 output or a hand-written stub)"),
            );
            continue;
        }
        if let Some(problems) = load_problems(&host, &elf) {
            report.push(
                Diagnostic::error("E0003", format!("`{ms_path}` ({}) would not load: {problems}", shown(&host).display()))
                    .at(&file, Some(line.number))
                    .help("every symbol an object uses must be defined by it, its archives, the OPEN-R libraries or the C/C++ runtime: rebuild it with this SDK root's mkbin, which reports such symbols when linking"),
            );
            continue;
        }
        out.objects.push((shown(&host), services_in_rodata(&elf)));
    }
    out
}

/// Test-loads `elf` the way `run` will (sdk_runtime::link_check: the system's dynamic
/// loader binds every symbol, in a child, running none of the object's code); the
/// problems, joined, if any.
fn load_problems(host: &Path, elf: &[u8]) -> Option<String> {
    let problems = tempfile::Builder::new()
        .suffix(".so")
        .tempfile()
        .and_then(|mut f| std::io::Write::write_all(&mut f, elf).map(|()| f))
        .map_err(|e| format!("cannot write a copy to test-load: {e}"))
        .and_then(|f| sdk_runtime::link_check::load_problems(host, f.path()).map_err(|e| e.to_string()));
    match problems {
        Ok(p) if p.is_empty() => None,
        Ok(p) => Some(p.join("; ")),
        Err(e) => Some(e),
    }
}

/// Why an ELF image (already checked by `read_bin`'s validation) is not an OPEN-R object
/// the runtime can start, if it is not.
fn object_problem(path: &Path, elf: &[u8]) -> Option<String> {
    match openr_wrappers::mkbin::missing_dynamic_symbols_in(path, elf, openr_wrappers::mkbin::ENTRY_SYMBOLS) {
        Ok(missing) if missing.is_empty() => None,
        Ok(missing) => Some(format!("{} missing from the dynamic symbol table", missing.join(", "))),
        Err(e) => Some(e.to_string()),
    }
}

/// The 4-part service names (`Obj.Sub.Data.S|O`) among the strings of the object's
/// read-only data: the literals of its `def.h`.
pub fn services_in_rodata(elf: &[u8]) -> Vec<String> {
    use object::{Object, ObjectSection};
    let Ok(file) = object::File::parse(elf) else { return Vec::new() };
    let mut out = Vec::new();
    for section in file.sections() {
        if !section.name().is_ok_and(|n| n.starts_with(".rodata")) {
            continue;
        }
        let Ok(data) = section.data() else { continue };
        // Split on every byte a service name cannot hold: a literal may directly follow
        // other constant data, with no NUL in between.
        let name_byte = |b: &u8| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'_' | b'-');
        for s in data.split(|b| !name_byte(b)) {
            let Ok(s) = std::str::from_utf8(s) else { continue };
            if is_service_name(s) && !out.iter().any(|o| o == s) {
                out.push(s.to_string());
            }
        }
    }
    out
}

fn is_service_name(s: &str) -> bool {
    let parts: Vec<&str> = s.split('.').collect();
    parts.len() == 4
        && (parts[3] == "S" || parts[3] == "O")
        && parts[..3].iter().all(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-'))
}

fn kind(name: &str) -> Option<char> {
    is_service_name(name).then(|| name.chars().last().unwrap())
}

fn data_name(name: &str) -> &str {
    name.split('.').nth(2).unwrap_or("")
}

fn check_connections(
    ms: &MsDir,
    design: &str,
    services: &BTreeMap<String, Origin>,
    unknown_help: &dyn Fn(&str) -> Option<String>,
    shown: &dyn Fn(&Path) -> PathBuf,
    report: &mut Report,
) {
    let cfg = match CfgFile::find(ms, "CONNECT.CFG") {
        Ok(cfg) => cfg,
        Err(e) => {
            report.push(Diagnostic::error("E0004", e.to_string()));
            None
        }
    };
    let rp = ["HOSTGW.CFG", "ROBOTGW.CFG"].iter().any(|f| ms.existing_in_program(&format!("/MS/OPEN-R/MW/CONF/{f}")).is_some());
    let mut connected: HashSet<String> = HashSet::new();
    // Per gateway service, the lines of the connections it is in.
    let mut gateway_uses: HashMap<String, Vec<usize>> = HashMap::new();
    if let Some(cfg) = &cfg {
        let file = shown(&cfg.path);
        let mut seen: Vec<(String, String, usize)> = Vec::new();
        for line in lines_for_design(&cfg.text, design) {
            let at = |d: Diagnostic| d.at(&file, Some(line.number));
            let [subject, observer] = &line.fields[..] else {
                report.push(at(Diagnostic::error("E0004", format!("expected `<subject service> <observer service>`, found {} field(s)", line.fields.len()))
                    .help("one connection a line: `Obj.Sub.Data.S Other.Sub.Data.O`")));
                continue;
            };
            connected.insert(subject.clone());
            connected.insert(observer.clone());
            let Some(diags) = check_line(subject, observer, services, unknown_help) else {
                for name in [subject, observer].into_iter().filter(|n| kind(n).is_none()) {
                    report.push(at(Diagnostic::error("E0004", format!("`{name}` is not a service name"))
                        .help("a service name has four parts, `Object.SubName.DataName.S` (subject) or `.O` (observer), written without quotes")));
                }
                continue;
            };
            for d in diags {
                report.push(at(d));
            }
            let (ks, ko) = (kind(subject), kind(observer));
            let (a, b) = if ks == Some('O') && ko == Some('S') { (observer, subject) } else { (subject, observer) };
            if let Some((_, _, first)) = seen.iter().find(|(s, o, _)| s == a && o == b) {
                let message = format!("duplicate connection `{a} {b}` (first on line {first})");
                // Sony's RP -BAD samples have such lines; the runtime leaves them out there.
                let d = if rp {
                    Diagnostic::warning("W0004", message).help("left out; remove this line")
                } else {
                    Diagnostic::error("E0010", message).help("remove this line")
                };
                report.push(at(d));
            } else {
                seen.push((a.clone(), b.clone(), line.number));
                for name in [a, b].into_iter().filter(|n| services.get(n.as_str()).is_some_and(|o| o.gateway)) {
                    gateway_uses.entry(name.clone()).or_default().push(line.number);
                }
            }
        }
    }
    if let Some(cfg) = &cfg {
        report_shared_gateway_services(&gateway_uses, &shown(&cfg.path), report);
    }
    report_unconnected(services, &connected, report);
}

/// A well-formed connection line's problems: swapped or wrong kinds, a DataName that
/// differs, services nobody registers. None when a name is not a service name at all.
fn check_line(subject: &str, observer: &str, services: &BTreeMap<String, Origin>, unknown_help: &dyn Fn(&str) -> Option<String>) -> Option<Vec<Diagnostic>> {
    let (ks, ko) = (kind(subject)?, kind(observer)?);
    let mut out = Vec::new();
    if ks == 'O' && ko == 'S' {
        out.push(Diagnostic::error("E0005", "subject and observer are swapped").help(format!("the subject (`.S`) comes first: `{observer} {subject}`")));
    } else if ks != 'S' {
        out.push(Diagnostic::error("E0005", format!("`{subject}` is an observer, but the first name of a connection must be a subject (`.S`)")));
    } else if ko != 'O' {
        out.push(Diagnostic::error("E0005", format!("`{observer}` is a subject, but the second name of a connection must be an observer (`.O`)")));
    }
    if data_name(subject) != data_name(observer) {
        out.push(
            Diagnostic::error("E0006", format!("DataName differs: `{}` (subject) vs `{}` (observer)", data_name(subject), data_name(observer)))
                .help("both ends of a connection must carry the same data type; the third parts of the names must be identical"),
        );
    }
    for name in [subject, observer] {
        if !services.contains_key(name) && !SYSTEM_SERVICES.contains(&name) {
            let help = unknown_help(name).unwrap_or_else(|| suggest(name, services));
            let what = if help.contains("gateway") { "neither an object nor the gateway registers it" } else { "no object registers it" };
            out.push(Diagnostic::error("E0007", format!("unknown service `{name}`: {what}")).help(help));
        }
    }
    Some(out)
}

/// W0003 for each gateway service in more than one connection.
fn report_shared_gateway_services(gateway_uses: &HashMap<String, Vec<usize>>, file: &Path, report: &mut Report) {
    for (name, uses) in gateway_uses.iter().filter(|(_, uses)| uses.len() > 1) {
        let lines: Vec<String> = uses.iter().map(usize::to_string).collect();
        report.push(
            Diagnostic::warning("W0003", format!("gateway service `{name}` is in {} connections (lines {})", uses.len(), lines.join(", ")))
                .at(file, Some(uses[0]))
                .help("one gateway channel carries one subject-observer connection: give each connection a service and port of its own (Sony's ObjectComm-multi RP2, not RP2-BAD)"),
        );
    }
}

/// W0002 for each registered service no connection names (a dummy's DataName excepted).
fn report_unconnected(services: &BTreeMap<String, Origin>, connected: &HashSet<String>, report: &mut Report) {
    for (name, origin) in services {
        if data_name(name) == DO_NOT_CONNECT || connected.contains(name) {
            continue;
        }
        if origin.gateway {
            report.push(
                Diagnostic::warning("W0002", format!("gateway service `{name}` is never connected"))
                    .at(&origin.file, origin.line)
                    .help("connect it in MS/OPEN-R/MW/CONF/CONNECT.CFG, or remove the line"),
            );
            continue;
        }
        let what = if name.ends_with(".S") { "subject" } else { "observer" };
        report.push(
            Diagnostic::warning("W0002", format!("{what} `{name}` is never connected"))
                .at(&origin.file, origin.line)
                .help(format!("connect it in MS/OPEN-R/MW/CONF/CONNECT.CFG, or give it DataName `{DO_NOT_CONNECT}` if it is a dummy")),
        );
    }
}

/// A help line for an unknown service: the nearest known name, else where names come from.
fn suggest(name: &str, services: &BTreeMap<String, Origin>) -> String {
    let known = services.keys().map(String::as_str).chain(SYSTEM_SERVICES.iter().copied());
    let prefix = |s: &str| s.rsplitn(3, '.').nth(2).map(str::to_string);
    let same_object_sub = |s: &&str| prefix(s) == prefix(name);
    let candidates: Vec<&str> = known.clone().filter(|s| s.eq_ignore_ascii_case(name)).chain(known.filter(same_object_sub)).collect();
    match candidates.first() {
        Some(c) => format!("did you mean `{c}`?"),
        None => "services are declared in stub.cfg (`Service : \"Obj.Sub.Data.S\", …`) or are system services such as `OVirtualRobotComm.Effector.OCommandVectorData.O`".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn service_names() {
        assert!(is_service_name("SampleSubject.SendString.char.S"));
        assert!(!is_service_name("a.b.c.s"));
        assert!(!is_service_name("a.b.S"));
        assert!(!is_service_name("a..c.O"));
    }
}
