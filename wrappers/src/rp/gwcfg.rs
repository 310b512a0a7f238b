//! HOSTGW.CFG / ROBOTGW.CFG (remote-processing 3.1, 3.2): one gateway line per channel.
use std::net::Ipv4Addr;
use std::path::Path;

use crate::error::Error;

/// One line of a gateway configuration file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GwLine {
    /// `!ROBOT_PROXY <port> <addr>` (host) or `TCPGateway.Proxy.AperiosMessage.P <port>` (robot).
    Proxy { line: usize, port: u16, addr: Option<Ipv4Addr> },
    /// `<Obj>.<Svc>.<Type>.S|O <port> [addr] [key=value…]`.
    Service { line: usize, name: String, port: u16, addr: Option<Ipv4Addr>, options: Vec<String> },
}

/// Parses a gateway file's text; errors read `<file>:<line>: <message>`.
pub fn parse(file: &str, text: &str) -> Result<Vec<GwLine>, Error> {
    parse_lines(text).map_err(|(line, m)| Error::usage(format!("{file}:{line}: {m}")))
}

/// As [`parse`], the error as (line, message) for callers that place it themselves
/// (`cargo openr check`).
pub fn parse_lines(text: &str) -> Result<Vec<GwLine>, (usize, String)> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let l = raw.trim_end_matches('\r').trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        let err = |m: String| (line, m);
        let (proxy, rest) = match l.strip_prefix('!') {
            Some(r) => {
                let r = r.trim_start();
                let r = r.strip_prefix("ROBOT_PROXY").ok_or_else(|| err(format!("expected `!ROBOT_PROXY <port> <address>`, found `{l}`")))?;
                (true, r)
            }
            None => (false, l),
        };
        let mut fields = rest.split_whitespace();
        let name = if proxy { None } else { fields.next().map(str::to_string) };
        let port_s = fields.next().ok_or_else(|| err("missing port number".into()))?;
        let port: u16 = port_s.parse().ok().filter(|p| *p != 0).ok_or_else(|| err(format!("`{port_s}` is not a TCP port (1-65535)")))?;
        let mut addr = None;
        let mut options = Vec::new();
        for f in fields {
            if f.contains('=') {
                options.push(f.to_string());
            } else if let Some(a) = f.parse::<Ipv4Addr>().ok().filter(|_| addr.is_none() && options.is_empty()) {
                addr = Some(a);
            } else {
                return Err(err(format!("unexpected field `{f}` (expected an IPv4 address or key=value)")));
            }
        }
        match name {
            None => out.push(GwLine::Proxy { line, port, addr }),
            Some(n) if n.ends_with(".P") => out.push(GwLine::Proxy { line, port, addr }),
            Some(n) => {
                let parts: Vec<&str> = n.split('.').collect();
                if parts.len() != 4 || parts.iter().any(|p| p.is_empty()) || !matches!(parts[3], "S" | "O") {
                    return Err(err(format!("`{n}` is not a gateway service `<Object>.<Service>.<DataType>.S|O`")));
                }
                out.push(GwLine::Service { line, name: n, port, addr, options });
            }
        }
    }
    Ok(out)
}

/// Reads `path`; a missing file is an empty configuration (ObjectComm/RP has none).
pub fn read(path: &Path) -> Result<Vec<GwLine>, Error> {
    match std::fs::read(path) {
        Ok(b) => parse(&path.display().to_string(), &String::from_utf8_lossy(&b)),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Vec::new()),
        Err(e) => Err(Error::io(path, e)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn host_file_with_blank_after_bang_crlf_and_options() {
        let text = "\r\n# host\r\n! ROBOT_PROXY 59001 10.0.1.100\r\nTCPGateway.Cam.Frame.S\t59002  10.0.1.100\r\nCore.Stdin.Expr.O 1094 dmax=8 dmin=1\r\n";
        let v = parse("HOSTGW.CFG", text).unwrap();
        assert_eq!(v[0], GwLine::Proxy { line: 3, port: 59001, addr: Some(Ipv4Addr::new(10, 0, 1, 100)) });
        assert_eq!(
            v[1],
            GwLine::Service { line: 4, name: "TCPGateway.Cam.Frame.S".into(), port: 59002, addr: Some(Ipv4Addr::new(10, 0, 1, 100)), options: vec![] }
        );
        assert_eq!(
            v[2],
            GwLine::Service { line: 5, name: "Core.Stdin.Expr.O".into(), port: 1094, addr: None, options: vec!["dmax=8".into(), "dmin=1".into()] }
        );
    }

    #[test]
    fn robot_file_proxy_suffix() {
        let v = parse("ROBOTGW.CFG", "TCPGateway.Proxy.AperiosMessage.P 59001\nTCPGateway.Cmd.Order.S 59003\n").unwrap();
        assert_eq!(v[0], GwLine::Proxy { line: 1, port: 59001, addr: None });
        assert!(matches!(&v[1], GwLine::Service { name, port: 59003, .. } if name == "TCPGateway.Cmd.Order.S"));
    }

    #[test]
    fn bad_lines_name_file_and_line() {
        assert_eq!(parse("H", "\nTCPGateway.X.T.S 70000 1.2.3.4\n").unwrap_err().to_string(), "H:2: `70000` is not a TCP port (1-65535)");
        assert_eq!(
            parse("H", "TCPGateway.X.T.Q 5 1.2.3.4\n").unwrap_err().to_string(),
            "H:1: `TCPGateway.X.T.Q` is not a gateway service `<Object>.<Service>.<DataType>.S|O`"
        );
        assert_eq!(parse("H", "!PROXY 5\n").unwrap_err().to_string(), "H:1: expected `!ROBOT_PROXY <port> <address>`, found `!PROXY 5`");
        assert_eq!(parse("H", "TCPGateway.X.T.S\n").unwrap_err().to_string(), "H:1: missing port number");
        assert_eq!(parse("H", "TCPGateway.X.T.S 5 robot\n").unwrap_err().to_string(), "H:1: unexpected field `robot` (expected an IPv4 address or key=value)");
    }
}
