//! Remote Processing sticks (remote-processing 3, 7.2, 7.3): the services of the TCP
//! gateway. On the robot, `TCPGW.BIN` in OBJECT.CFG registers one service per ROBOTGW.CFG
//! line; on the host (a stick with HOSTGW.CFG) the gateway is started without an
//! OBJECT.CFG line and registers HOSTGW.CFG's lines. Each line's name is taken verbatim,
//! the proxy line (`.P`, `!ROBOT_PROXY`) is no service.
use std::path::{Path, PathBuf};

use openr_wrappers::rp::gwcfg::{self, GwLine};
use sdk_runtime::cfg::CfgFile;
use sdk_runtime::ms::MsDir;

use crate::ops::diag::{Diagnostic, Report};

/// Where OBJECT.CFG lists the robot gateway; the runtime provides it (the SDK root's base
/// trees hold a `TCPGW.BIN` naming it), so a program's own tree need not.
pub const TCPGW: &str = "/MS/OPEN-R/SYSTEM/OBJS/TCPGW.BIN";

/// Whether OBJECT.CFG's `ms_path` is the robot gateway: the built-in object `image`
/// names it, or the path is TCPGW's and the program's tree has no such file.
pub fn is_robot_gateway(ms_path: &str, image: Option<&[u8]>) -> bool {
    match image {
        Some(image) => sdk_runtime::gateway::builtin_name(image) == Some(sdk_runtime::gateway::ROBOT_GATEWAY),
        None => ms_path.eq_ignore_ascii_case(TCPGW),
    }
}

/// A gateway service: its name and the line of the CFG file declaring it.
pub struct GwService {
    pub name: String,
    pub file: PathBuf,
    pub line: usize,
}

/// The gateway services of the stick: ROBOTGW.CFG's when `robot_gateway` (OBJECT.CFG's line
/// of TCPGW.BIN) is loaded, HOSTGW.CFG's on a host stick. Malformed files are E0011.
pub fn services(ms: &MsDir, robot_gateway: Option<(&Path, usize)>, shown: &dyn Fn(&Path) -> PathBuf, report: &mut Report) -> Vec<GwService> {
    let host = read(ms, "HOSTGW.CFG", shown, report);
    if let (Some(_), Some((object_cfg, line))) = (&host, robot_gateway) {
        report.push(
            Diagnostic::error("E0011", "TCPGW.BIN on a host stick: this stick has a HOSTGW.CFG, whose gateway the host starts itself")
                .at(object_cfg, Some(line))
                .help("one gateway per side: remove this line (host), or the HOSTGW.CFG (robot)"),
        );
    }
    if let Some(host) = host {
        return host;
    }
    let Some((object_cfg, line)) = robot_gateway else { return Vec::new() };
    match read(ms, "ROBOTGW.CFG", shown, report) {
        Some(s) => s,
        None => {
            report.push(
                Diagnostic::warning("W0003", "TCPGW.BIN is loaded but there is no MS/OPEN-R/MW/CONF/ROBOTGW.CFG: the gateway has no channels")
                    .at(object_cfg, Some(line))
                    .help("list the gateway's services in ROBOTGW.CFG, one `TCPGateway.<Service>.<DataType>.S|O <port>` a line"),
            );
            Vec::new()
        }
    }
}

/// `MW/CONF/<name>`'s service lines; `None` if the stick has no such file.
fn read(ms: &MsDir, name: &str, shown: &dyn Fn(&Path) -> PathBuf, report: &mut Report) -> Option<Vec<GwService>> {
    let cfg = match CfgFile::find(ms, name) {
        Ok(cfg) => cfg?,
        Err(e) => {
            report.push(Diagnostic::error("E0011", e.to_string()));
            return Some(Vec::new());
        }
    };
    let file = shown(&cfg.path);
    let host = name == "HOSTGW.CFG";
    let lines = match gwcfg::parse_lines(&cfg.text) {
        Ok(lines) => lines,
        Err((line, message)) => {
            let form = if host {
                "`!ROBOT_PROXY <port> <robot IPv4>` or `<Obj>.<Service>.<DataType>.S|O <port> [<robot IPv4>] [key=value…]`"
            } else {
                "`TCPGateway.Proxy.AperiosMessage.P <port>` or `TCPGateway.<Service>.<DataType>.S|O <port>`"
            };
            report.push(Diagnostic::error("E0011", format!("malformed {name}: {message}")).at(&file, Some(line)).help(format!("a line is {form}")));
            return Some(Vec::new());
        }
    };
    // What the run would refuse of the lines as a whole (one channel per port, …); the
    // services are the lines all the same, so connections to them are not unknown too.
    match sdk_runtime::gateway::channels(&lines, host) {
        Ok(channels) => {
            for c in &channels {
                for w in c.warnings() {
                    report.push(Diagnostic::warning("W0003", w).at(&file, Some(c.line)).help("the run says so too, and goes on"));
                }
            }
        }
        Err((line, message)) => report.push(
            Diagnostic::error("E0011", format!("the gateway would not start: {message}"))
                .at(&file, Some(line))
                .help("each line is one service and one channel: its own name and port (on the host, its robot's address or the `!ROBOT_PROXY` line's); one proxy line at most"),
        ),
    }
    let mut out: Vec<GwService> = Vec::new();
    for l in lines {
        match l {
            GwLine::Service { line, name, .. } if !out.iter().any(|s| s.name == name) => out.push(GwService { name, file: file.clone(), line }),
            _ => {}
        }
    }
    Some(out)
}

/// Why CONNECT.CFG's `name` may be unknown on an RP stick, if the gateway explains it.
pub fn unknown_help(ms: &MsDir, name: &str, gateway: &[GwService], robot_gateway: bool) -> Option<String> {
    let object = name.split('.').next().unwrap_or("");
    let host = ms.existing_in_program("/MS/OPEN-R/MW/CONF/HOSTGW.CFG").is_some();
    let robot_cfg = ms.existing_in_program("/MS/OPEN-R/MW/CONF/ROBOTGW.CFG").is_some();
    if host || robot_gateway {
        let file = if host { "HOSTGW.CFG" } else { "ROBOTGW.CFG" };
        if gateway.iter().any(|g| g.name.split('.').next() == Some(object)) || object == "TCPGateway" {
            let example = if host { format!("{name} <port> <robot IPv4>") } else { format!("{name} <port>") };
            return Some(format!("no line of {file} declares it; the gateway's services are that file's lines, e.g. `{example}`"));
        }
    } else if robot_cfg || object == "TCPGateway" {
        return Some(format!(
            "`{object}` looks like the Remote Processing gateway, which this stick does not load: list {TCPGW} in OBJECT.CFG and the service in ROBOTGW.CFG"
        ));
    }
    None
}
