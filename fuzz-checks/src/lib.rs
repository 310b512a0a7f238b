//! The properties each parser of outside input must keep, one function per fuzz target:
//! no panic, errors that name a line where the format has lines, and parse → print →
//! parse round trips where the data can be printed back. `fuzz/` drives them with
//! libFuzzer (nightly); `tests/bounded.rs` drives them on stable with a few thousand
//! deterministic inputs each ([`gen`]), seeded from the repository's own files.
use std::path::{Path, PathBuf};

mod binary;
pub mod gen;
mod text;

pub use binary::{control, dns, elf, peer, vectors, wire};
pub use text::{hostgw, ms_cfg, ocf, openr_toml, stub_cfg, wlan};

/// A fuzz target: its name (as in `fuzz/fuzz_targets/<name>.rs`) and its check.
pub struct Target {
    pub name: &'static str,
    /// Panics when a property fails; true when the input was accepted.
    pub check: fn(&[u8]) -> bool,
    /// Words the mutator inserts (keywords, separators of the format).
    pub dict: &'static [&'static [u8]],
}

pub const TARGETS: &[Target] = &[
    Target { name: "ms_cfg", check: ms_cfg, dict: &[b"[ERS-7]", b"[ERS-210]", b"/MS/OPEN-R/MW/OBJS/", b".BIN", b".S ", b".O", b"\r\n", b"# "] },
    Target { name: "wlan", check: wlan, dict: &[b"ESSID=", b"WEPENABLE=", b"HOSTNAME=", b"=", b"\r\n", b"# "] },
    Target {
        name: "stub_cfg",
        check: stub_cfg,
        dict: &[
            b"ObjectName : ",
            b"NumOfOSubject : ",
            b"NumOfOObserver : ",
            b"Service : \"",
            b".char.S\"",
            b".char.O\"",
            b", null",
            b"()",
            b"Extra : ",
            b"\r\n",
        ],
    },
    Target {
        name: "ocf",
        check: ocf,
        dict: &[b"object ", b" cache", b" nocache", b" tlb", b" notlb", b" user", b" kernel", b"K ", b"18446744073709551615", b"# "],
    },
    Target {
        name: "hostgw",
        check: hostgw,
        dict: &[b"!ROBOT_PROXY ", b"TCPGateway.Proxy.AperiosMessage.P ", b".S ", b".O ", b" 10.0.1.100", b" dmax=8", b"65535", b"65536", b"\r\n", b"# "],
    },
    Target {
        name: "openr_toml",
        check: openr_toml,
        dict: &[b"sdk = ", b"design = \"ERS-210\"", b"speed = ", b"cxxflags = ", b"ldflags = ", b"base = ", b"\"", b"\\\"", b"\\\\", b"# "],
    },
    Target { name: "wire", check: wire, dict: &[b"ORP1\x01\x00", b"\x00\x00\x40\x00", b"\xff\xff"] },
    Target { name: "control", check: control, dict: &[b"status", b"pause", b"resume", b"step ", b"speed ", b"max", b"shutdown", b"1e-300", b"1000000", b"\n"] },
    Target { name: "dns", check: dns, dict: &[b"\x81\x80", b"\x00\x01", b"\xc0\x0c", b"\x00\x05\x00\x01", b"\x00\x0c\x00\x01", b"\x00\x04", b"\x3f"] },
    Target {
        name: "vectors",
        check: vectors,
        dict: &[b"\x03\x01\x00\x00", b"\x07\x01\x00\x00", b"\x10\x00\x00\x00", b"\x15\x00\x00\x00", b"\x00\x00\x00\x01", b"\x10\x00", b"\xff\xff\xff\xff"],
    },
    Target { name: "peer", check: peer, dict: &[b"\x00\xff\xff\xff\xff", b"\x01\x00\x00\x00\x00", b"\x02\x01\x00\x00\x00", b"\x00\x01\x00\x00"] },
    Target { name: "elf", check: elf, dict: &[b"\x7fELF\x02\x01\x01", b"\x3e\x00", b"\x03\x00", b"\x38\x00", b"\x1f\x8b\x08"] },
];

/// The repository root (this crate sits in it).
pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// The seed inputs of `target`: the repository's files of that format, or (for the
/// formats no file of the repository holds) messages the project's own writers build.
pub fn seeds(target: &str) -> Vec<Vec<u8>> {
    let wanted = |name: &str| -> bool {
        let upper = name.to_ascii_uppercase();
        match target {
            "ms_cfg" => ["OBJECT.CFG", "CONNECT.CFG", "DESIGNDB.CFG"].contains(&upper.as_str()),
            "wlan" => upper.starts_with("WLAN") && upper.ends_with(".TXT"),
            "stub_cfg" => upper.ends_with(".CFG") && !upper.ends_with("GW.CFG") && !["OBJECT.CFG", "CONNECT.CFG", "DESIGNDB.CFG"].contains(&upper.as_str()),
            "ocf" => upper.ends_with(".OCF"),
            _ => false,
        }
    };
    let mut out = Vec::new();
    walk(&repo(), &mut |p| {
        if p.file_name().and_then(|n| n.to_str()).is_some_and(wanted) {
            if let Ok(b) = std::fs::read(p) {
                out.push(b);
            }
        }
    });
    out.extend(built_seeds(target));
    out.sort();
    out.dedup();
    out
}

fn walk(dir: &Path, f: &mut dyn FnMut(&Path)) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    let mut entries: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
    entries.sort();
    for p in entries {
        let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
        // Skips build output and the libFuzzer corpora (fuzz/corpus grows by thousands).
        if p.is_symlink() || name.starts_with('.') || ["target", "corpus", "artifacts"].contains(&name) {
            continue;
        }
        if p.is_dir() {
            walk(&p, f);
        } else {
            f(&p);
        }
    }
}

fn built_seeds(target: &str) -> Vec<Vec<u8>> {
    use openr_peer_protocol::wire;
    let text = |v: &[&str]| v.iter().map(|s| s.as_bytes().to_vec()).collect();
    match target {
        "wlan" => text(&["# wireless\nESSID=AIBONET\r\nWEPENABLE=0\nIPADDRESS = 10.0.1.100 # robot\n=x\nbare line\n"]),
        "hostgw" => text(&[
            "\r\n# host\r\n! ROBOT_PROXY 59001 10.0.1.100\r\nTCPGateway.Cam.Frame.S\t59002  10.0.1.100\r\nCore.Stdin.Expr.O 1094 dmax=8 dmin=1\r\n",
            "TCPGateway.Proxy.AperiosMessage.P 59001\nSampleSubject.SendString.char.S 59100\n",
        ]),
        "openr_toml" => text(&[
            "# c\nsdk = \"../sdk\" # root\n\ndesign = \"ERS-210\"\nspeed = 4\nbase = \"WLAN\"\n",
            "speed = \"max\"\ncxxflags = \"-O2 -DX=\\\"a b\\\"\"\nldflags = \"-lm\"\n",
        ]),
        "control" => text(&["status\npause\nstep\nstep 3\nspeed 2.5\nspeed max\nresume\nshutdown\n", "speed 1e-300\r\nstep 0\n\n  status  \n"]),
        "wire" => {
            let r = sdk_runtime::robot::Readings { joints: vec![(0x100, -5), (0x101, 7)], sensors: vec![(0x130, 1)] };
            let hello = wire::message(wire::HELLO, 0, &wire::hello(wire::ROLE_ALL, wire::FLAG_CLOCK, "sim"));
            let readings = wire::message(wire::READINGS, 3, &wire::readings(&r));
            let clock = wire::message(wire::CLOCK, 4, &1u32.to_le_bytes());
            let bye = wire::message(wire::BYE, 5, &[]);
            vec![[hello.clone(), readings.clone(), clock, bye].concat(), hello, readings]
        }
        "dns" => {
            // A response to `aibo.example` with a CNAME and an A record, compressed names.
            let mut r = openr_ipstack::dns::build_query(0x0a1b, "aibo.example", 1);
            r[2] = 0x81;
            r[3] = 0x80;
            r[7] = 2;
            r.extend_from_slice(&[0xc0, 12, 0, 5, 0, 1, 0, 0, 0, 60, 0, 6, 3, b'd', b'o', b'g', 0xc0, 17]);
            r.extend_from_slice(&[0xc0, 30, 0, 1, 0, 1, 0, 0, 0, 60, 0, 4, 10, 0, 1, 2]);
            vec![r]
        }
        "vectors" => {
            use sdk_runtime::robot::camera::{build_cdt_vector, cdt_entry};
            use sdk_runtime::robot::vectors::*;
            let mut cmd = vec![0u8; command_vector_size(3)];
            command_vector_init(&mut cmd, 3).unwrap();
            command_vector_push(&mut cmd, odata::JOINT_COMMAND2, 0x0101, &[joint2_frame(-5000), joint2_frame(7000)]).unwrap();
            command_vector_push(&mut cmd, odata::LED_COMMAND3, 0x0202, &[led3_frame(255, 1, 4), led3_frame(0, 0, 0)]).unwrap();
            command_vector_push(&mut cmd, odata::JOINT_COMMAND4, 0x0303, &[held_frame(1, 3)]).unwrap();
            let mic = build_mic_vector(0x0404, 9, &[1, 2, 3, 4, 5, 6, 7, 8]).unwrap();
            let cdt = build_cdt_vector(0x0100_0000, &[(1, [cdt_entry(200, 100, 180, 90); 32]), (0x40, [0; 32])]);
            vec![cmd, mic, cdt]
        }
        "peer" => {
            let payload = |kind: u8, roles: u32, p: &[u8]| [&[kind][..], &roles.to_le_bytes(), p].concat();
            let ers7 = sdk_runtime::robot::model::RobotModel::new(sdk_runtime::robot::Design::Ers7);
            let joint = ers7.open_primitive("PRM:/r2/c1-Joint2:21").expect("the ERS-7 has LF J1");
            let r = sdk_runtime::robot::Readings { joints: vec![(joint, 7_000)], sensors: vec![] };
            // A 2 x 3 picture (roles 0b010_001), CLOCK taking the clock.
            let image = [&2u16.to_le_bytes()[..], &3u16.to_le_bytes(), &[9u8; 18]].concat();
            vec![payload(0, wire::ROLE_ALL, &wire::readings(&r)), payload(1, 0b010_001, &image), payload(2, 0, &wire::FLAG_CLOCK.to_le_bytes())]
        }
        "elf" => {
            // Shared objects of the system (the tests of elf_check use them too), plain
            // and gzipped as mkbin writes a .BIN.
            let mut v: Vec<Vec<u8>> =
                ["/lib/x86_64-linux-gnu/libdl.so.2", "/usr/lib/x86_64-linux-gnu/libdl.so.2"].iter().filter_map(|p| std::fs::read(p).ok()).take(1).collect();
            if let Some(so) = v.first().cloned() {
                use std::io::Write;
                let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
                gz.write_all(&so).unwrap();
                v.push(gz.finish().unwrap());
            }
            v
        }
        _ => Vec::new(),
    }
}
