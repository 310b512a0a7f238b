//! The Memory Stick configuration files of `/MS/OPEN-R/MW/CONF` (object-model 1.4):
//! CRLF or LF, `#` comment lines, blank lines, fields separated by blanks or tabs, and
//! robot-design sections (`[ERS-7]`) whose lines apply only to that design.
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::ms::MsDir;

/// One meaningful line: its number (1-based) and its fields.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Line {
    pub number: usize,
    pub fields: Vec<String>,
}

/// The lines of `text` that apply to `design` (lines before the first section apply to
/// every design).
pub fn lines_for_design(text: &str, design: &str) -> Vec<Line> {
    let mut applies = true;
    let mut out = Vec::new();
    for (i, raw) in text.split('\n').enumerate() {
        let line = raw.trim_end_matches('\r').trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(section) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            applies = section.trim() == design;
            continue;
        }
        if applies {
            out.push(Line { number: i + 1, fields: line.split_whitespace().map(str::to_string).collect() });
        }
    }
    out
}

/// A configuration file found on the stick, with its text.
#[derive(Debug, Clone)]
pub struct CfgFile {
    pub path: PathBuf,
    pub text: String,
}

impl CfgFile {
    /// Reads `/MS/OPEN-R/MW/CONF/<name>` (any case). `None` if it does not exist.
    pub fn find(ms: &MsDir, name: &str) -> Result<Option<CfgFile>> {
        // The base tree's comment-only CFGs never stand in for the program's own.
        let Some(path) = ms.existing_in_program(&format!("/MS/OPEN-R/MW/CONF/{name}")) else { return Ok(None) };
        let bytes = std::fs::read(&path).map_err(|e| Error::io(&path, e))?;
        let text = String::from_utf8_lossy(&bytes).into_owned();
        Ok(Some(CfgFile { path, text }))
    }
}

/// An OBJECT.CFG entry: the `.BIN` to load, as written and as found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ObjectEntry {
    pub line: usize,
    pub ms_path: String,
    pub host_path: PathBuf,
}

/// The objects OBJECT.CFG lists for `design`, in order; each must exist.
pub fn object_cfg(ms: &MsDir, design: &str) -> Result<(PathBuf, Vec<ObjectEntry>)> {
    let expected = ms.root().join("OPEN-R/MW/CONF/OBJECT.CFG");
    let cfg = CfgFile::find(ms, "OBJECT.CFG")?.ok_or_else(|| {
        Error::config(
            &expected,
            None,
            format!("not found: `{}` is not a Memory Stick tree (expected OPEN-R/MW/CONF/OBJECT.CFG listing the objects to load)", ms.root().display()),
        )
    })?;
    let mut out = Vec::new();
    // An RP host program may run its gateway alone (a relay; remote-processing 4).
    let listed = object_lines(&cfg.path, &cfg.text, design)?;
    if listed.is_empty() && !is_rp(ms, "HOSTGW.CFG") {
        return Err(no_object(&cfg.path, design));
    }
    for (line, ms_path) in listed {
        let host_path = ms
            .existing(&ms_path)
            .filter(|p| p.is_file())
            .ok_or_else(|| Error::config(&cfg.path, Some(line), format!("object `{ms_path}` not found on the Memory Stick (is it built and installed?)")))?;
        out.push(ObjectEntry { line, ms_path, host_path });
    }
    Ok((cfg.path, out))
}

/// The `(line, /MS path)` entries of an OBJECT.CFG text (`path` names it in errors).
pub fn parse_object_cfg(path: &Path, text: &str, design: &str) -> Result<Vec<(usize, String)>> {
    let out = object_lines(path, text, design)?;
    if out.is_empty() {
        return Err(no_object(path, design));
    }
    Ok(out)
}

fn no_object(path: &Path, design: &str) -> Error {
    Error::config(path, None, format!("lists no object for robot design {design}"))
}

/// As `parse_object_cfg`, none at all included.
fn object_lines(path: &Path, text: &str, design: &str) -> Result<Vec<(usize, String)>> {
    let mut out = Vec::new();
    for line in lines_for_design(text, design) {
        if line.fields.len() > 1 {
            return Err(Error::config(
                path,
                Some(line.number),
                format!("expected one path per line (/MS/OPEN-R/MW/OBJS/XXXXXXXX.BIN), found `{}`", line.fields.join(" ")),
            ));
        }
        out.push((line.number, line.fields[0].clone()));
    }
    Ok(out)
}

/// A CONNECT.CFG line: subject service name, observer service name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Connection {
    pub line: usize,
    pub subject: String,
    pub observer: String,
}

/// Whether the program's MS has MW/CONF/`file` (HOSTGW.CFG, ROBOTGW.CFG): a Remote
/// Processing program.
pub(crate) fn is_rp(ms: &MsDir, file: &str) -> bool {
    ms.existing_in_program(&format!("/MS/OPEN-R/MW/CONF/{file}")).is_some()
}

/// The connections of CONNECT.CFG for `design` (an absent file means none), and the
/// lines left out as duplicates (line, first line): allowed in Remote Processing
/// programs only, whose `-BAD` samples have them (remote-processing 3.3).
pub fn connect_cfg(ms: &MsDir, design: &str) -> Result<(PathBuf, Vec<Connection>, Vec<(usize, usize)>)> {
    let Some(cfg) = CfgFile::find(ms, "CONNECT.CFG")? else {
        return Ok((ms.root().join("OPEN-R/MW/CONF/CONNECT.CFG"), Vec::new(), Vec::new()));
    };
    let mut dups = Vec::new();
    let rp = is_rp(ms, "HOSTGW.CFG") || is_rp(ms, "ROBOTGW.CFG");
    let out = parse_connect_cfg_with(&cfg.path, &cfg.text, design, rp.then_some(&mut dups))?;
    Ok((cfg.path, out, dups))
}

/// The connections of a CONNECT.CFG text (`path` names it in errors).
pub fn parse_connect_cfg(path: &Path, text: &str, design: &str) -> Result<Vec<Connection>> {
    parse_connect_cfg_with(path, text, design, None)
}

/// As `parse_connect_cfg`; with `dups`, a duplicate line is put there instead of failing.
fn parse_connect_cfg_with(path: &Path, text: &str, design: &str, mut dups: Option<&mut Vec<(usize, usize)>>) -> Result<Vec<Connection>> {
    let mut out: Vec<Connection> = Vec::new();
    for line in lines_for_design(text, design) {
        let [subject, observer] = &line.fields[..] else {
            return Err(Error::config(
                path,
                Some(line.number),
                format!("expected `<subject service> <observer service>`, found {} field(s): `{}`", line.fields.len(), line.fields.join(" ")),
            ));
        };
        for (name, kind) in [(subject, "S"), (observer, "O")] {
            if name.rsplit('.').next() != Some(kind) || name.split('.').count() != 4 {
                let what = if kind == "S" { "subject" } else { "observer" };
                return Err(Error::config(
                    path,
                    Some(line.number),
                    format!("`{name}` is not a {what} service name (expected Object.Sub.Data.{kind}; the subject comes first)"),
                ));
            }
        }
        if let Some(first) = out.iter().find(|c| &c.subject == subject && &c.observer == observer) {
            if let Some(d) = dups.as_deref_mut() {
                d.push((line.number, first.line));
                continue;
            }
            return Err(Error::config(path, Some(line.number), format!("duplicate connection `{subject} {observer}` (first on line {})", first.line)));
        }
        out.push(Connection { line: line.number, subject: subject.clone(), observer: observer.clone() });
    }
    Ok(out)
}

/// DESIGNDB.CFG: `KEYWORD /MS/path` lines of the current design.
pub fn design_db(ms: &MsDir, design: &str) -> Result<Vec<(String, String)>> {
    let Some(cfg) = CfgFile::find(ms, "DESIGNDB.CFG")? else { return Ok(Vec::new()) };
    parse_design_db(&cfg.path, &cfg.text, design)
}

/// The `(KEYWORD, path)` lines of a DESIGNDB.CFG text (`path` names it in errors).
pub fn parse_design_db(path: &Path, text: &str, design: &str) -> Result<Vec<(String, String)>> {
    let mut out = Vec::new();
    for line in lines_for_design(text, design) {
        let [key, value] = &line.fields[..] else {
            return Err(Error::config(path, Some(line.number), format!("expected `<KEYWORD> <absolute path>`, found `{}`", line.fields.join(" "))));
        };
        out.push((key.clone(), value.clone()));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sections_comments_and_crlf() {
        let text = "# c\r\n/MS/A.BIN\r\n\r\n[ERS-210]\r\n/MS/B.BIN\r\n[ERS-7]\r\n  /MS/C.BIN  \r\n";
        let l = lines_for_design(text, "ERS-7");
        assert_eq!(l.iter().map(|l| (l.number, l.fields[0].as_str())).collect::<Vec<_>>(), [(2, "/MS/A.BIN"), (7, "/MS/C.BIN")]);
        let l = lines_for_design(text, "ERS-210");
        assert_eq!(l.iter().map(|l| l.fields[0].as_str()).collect::<Vec<_>>(), ["/MS/A.BIN", "/MS/B.BIN"]);
    }

    fn stick(files: &[(&str, &str)]) -> (tempfile::TempDir, MsDir) {
        let d = tempfile::tempdir().unwrap();
        for (p, t) in files {
            let p = d.path().join(p);
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(p, t).unwrap();
        }
        let ms = MsDir::new(d.path()).unwrap();
        (d, ms)
    }

    #[test]
    fn object_cfg_errors_name_file_and_line() {
        let (_d, ms) = stick(&[]);
        let e = object_cfg(&ms, "ERS-7").unwrap_err().to_string();
        assert!(e.contains("OBJECT.CFG: not found"), "{e}");
        let (_d, ms) = stick(&[("OPEN-R/MW/CONF/object.cfg", "# x\n/MS/OPEN-R/MW/OBJS/NOPE.BIN\n")]);
        let e = object_cfg(&ms, "ERS-7").unwrap_err().to_string();
        assert!(e.ends_with("object.cfg:2: object `/MS/OPEN-R/MW/OBJS/NOPE.BIN` not found on the Memory Stick (is it built and installed?)"), "{e}");
        let (_d, ms) = stick(&[("OPEN-R/MW/CONF/OBJECT.CFG", "/MS/A.BIN\n"), ("a.bin", "")]);
        let (_, objs) = object_cfg(&ms, "ERS-7").unwrap();
        assert_eq!(objs[0].host_path, ms.root().join("a.bin"));
        // more than one field on a line (the line number counts comments, sections, CRLF)
        for (text, want) in [
            ("# x\n/MS/A.BIN /MS/B.BIN\n", ":2: expected one path per line (/MS/OPEN-R/MW/OBJS/XXXXXXXX.BIN), found `/MS/A.BIN /MS/B.BIN`"),
            ("/MS/A.BIN\r\n\r\n[ERS-7]\r\n/MS/A.BIN\tERS7\r\n", ":4: expected one path per line (/MS/OPEN-R/MW/OBJS/XXXXXXXX.BIN), found `/MS/A.BIN ERS7`"),
        ] {
            let (_d, ms) = stick(&[("OPEN-R/MW/CONF/OBJECT.CFG", text), ("a.bin", "")]);
            let e = object_cfg(&ms, "ERS-7").unwrap_err().to_string();
            assert_eq!(e, format!("{}{want}", ms.root().join("OPEN-R/MW/CONF/OBJECT.CFG").display()));
        }
        // nothing for this design: names the file (no line: the whole file is at fault)
        for text in ["# only comments\n\n", "[ERS-210]\n/MS/A.BIN\n"] {
            let (_d, ms) = stick(&[("OPEN-R/MW/CONF/OBJECT.CFG", text), ("a.bin", "")]);
            let e = object_cfg(&ms, "ERS-7").unwrap_err().to_string();
            assert_eq!(e, format!("{}: lists no object for robot design ERS-7", ms.root().join("OPEN-R/MW/CONF/OBJECT.CFG").display()));
        }
        let (_d, ms) = stick(&[("OPEN-R/MW/CONF/OBJECT.CFG", "[ERS-210]\n/MS/A.BIN\n"), ("a.bin", "")]);
        assert_eq!(object_cfg(&ms, "ERS-210").unwrap().1.len(), 1);
    }

    #[test]
    fn connect_cfg_checks_names_and_duplicates() {
        let good = "A.Out.char.S B.In.char.O\n";
        let (_d, ms) = stick(&[("OPEN-R/MW/CONF/CONNECT.CFG", good)]);
        assert_eq!(connect_cfg(&ms, "ERS-7").unwrap().1.len(), 1);
        // In a Remote Processing program a duplicate is left out and reported.
        let dup = "A.Out.char.S B.In.char.O\nA.Out.char.S B.In.char.O\n";
        let (_d, ms) = stick(&[("OPEN-R/MW/CONF/CONNECT.CFG", dup), ("OPEN-R/MW/CONF/ROBOTGW.CFG", "")]);
        let (_, conns, dups) = connect_cfg(&ms, "ERS-7").unwrap();
        assert_eq!((conns.len(), dups), (1, vec![(2, 1)]));
        for (text, want) in [
            ("A.Out.char.S\n", ":1: expected `<subject service> <observer service>`, found 1 field(s)"),
            ("B.In.char.O A.Out.char.S\n", ":1: `B.In.char.O` is not a subject service name"),
            ("#\nA.Out.char.S B.In.char.O\nA.Out.char.S B.In.char.O\n", ":3: duplicate connection `A.Out.char.S B.In.char.O` (first on line 2)"),
        ] {
            let (_d, ms) = stick(&[("OPEN-R/MW/CONF/CONNECT.CFG", text)]);
            let e = connect_cfg(&ms, "ERS-7").unwrap_err().to_string();
            assert!(e.contains(&format!("CONNECT.CFG{want}")), "{e}");
        }
    }
}
