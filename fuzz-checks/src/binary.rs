//! The byte protocols and images: the robot peer protocol, control-socket lines and
//! `.BIN` (ELF) images.
use std::io::BufReader;
use std::path::Path;

use openr_peer_protocol::wire;
use sdk_runtime::control::{self, Command, Input};

/// A stream of robot-protocol messages as a peer sends them: each message is read,
/// refused or taken; what was taken prints back to the same bytes.
pub fn wire(data: &[u8]) -> bool {
    let mut rest = data;
    let mut taken = false;
    loop {
        let before = rest;
        match wire::read_message(&mut rest) {
            Ok(None) => {
                assert!(before.is_empty());
                return taken;
            }
            Err(_) => return false, // truncated: the connection ends
            Ok(Some(Err(wire::Refusal(code, message)))) => {
                assert!((wire::E_BAD_MAGIC..=wire::E_OVERFLOW).contains(&code) && !message.is_empty());
                return false; // the runtime answers ERROR and drops the peer
            }
            Ok(Some(Ok((h, payload)))) => {
                assert_eq!(h.length as usize, payload.len());
                let used = before.len() - rest.len();
                assert_eq!(wire::message(h.kind, h.frame, &payload), before[..used], "message prints back");
                taken |= payload_round_trip(h.kind, &payload);
            }
        }
    }
}

/// True when the payload was one the runtime takes (HELLO, READINGS) and it parsed.
fn payload_round_trip(kind: u16, p: &[u8]) -> bool {
    match kind {
        wire::HELLO => {
            if let Ok(h) = wire::parse_hello(p) {
                assert_eq!(wire::parse_hello(&wire::hello(h.roles, h.flags, &h.name)), Ok(h));
                return true;
            }
            false
        }
        wire::READINGS => {
            if let Ok(r) = wire::parse_readings(p) {
                assert_eq!(wire::readings(&r), p, "READINGS prints back");
                return true;
            }
            false
        }
        _ => {
            // Every getter of the reader fails instead of reading past the end.
            let mut i = wire::In::new(p);
            while !i.is_empty() {
                if i.str().is_err() && i.u32().is_err() && i.u8().is_err() {
                    break;
                }
            }
            false
        }
    }
}

/// What a control-socket client sends: lines of at most 1024 bytes, each parsed; a
/// command prints back to a line that parses to it.
pub fn control(data: &[u8]) -> bool {
    let mut taken = false;
    let mut input = BufReader::with_capacity(64, data);
    for _ in 0..=data.len() {
        match control::read_line(&mut input) {
            Input::End | Input::TooLong => return taken,
            Input::NotUtf8(at) => assert!(at <= 1024),
            Input::Line(text) => {
                assert!(text.len() <= 1025 && text.matches('\n').count() <= 1 && (text.ends_with('\n') || !text.contains('\n')));
                match text.trim().parse::<Command>() {
                    Ok(c) => {
                        assert_eq!(c.to_string().parse::<Command>(), Ok(c));
                        taken = true;
                    }
                    Err(e) => assert!(!e.is_empty()),
                }
            }
        }
    }
    panic!("read_line did not consume its input");
}

/// A `.BIN` as `run` and `check` read it: gunzipped when gzip, then validated before
/// `dlopen` would see it.
pub fn elf(data: &[u8]) -> bool {
    let Ok(image) = sdk_runtime::loader::gunzip_if_gzip(data.to_vec()) else { return false };
    let _ = sdk_runtime::elf_check::interpreter(&image);
    match sdk_runtime::elf_check::validate(Path::new("X.BIN"), &image) {
        Ok(()) => true,
        Err(e) => {
            assert!(e.to_string().starts_with("X.BIN: damaged or foreign object file: "), "{e}");
            false
        }
    }
}

/// A DNS server's answer as the robot's resolver reads it (`antDNS` lookups): the first
/// two bytes are taken as the query id, so the id check passes as often as it fails. No
/// read past the datagram, no more addresses than answers; a query the resolver builds
/// reads back to the name it was built from.
pub fn dns(data: &[u8]) -> bool {
    use openr_ipstack::dns;
    let id = u16::from_be_bytes([data.first().copied().unwrap_or(0), data.get(1).copied().unwrap_or(0)]);
    let name: String = data.iter().take(80).map(|&b| if b.is_ascii_alphanumeric() || b == b'-' { b as char } else { '.' }).collect();
    let query = dns::build_query(id, &name, 1);
    let labels: Vec<String> = name.split('.').filter(|l| !l.is_empty()).map(|l| l[..l.len().min(63)].to_string()).collect();
    assert_eq!(dns::read_name(&query, 12).map(|(n, _)| n), Some(labels.join(".")), "query for {name:?}");
    let Some((rcode, answer)) = dns::parse_response(data, id) else { return false };
    let answers = u16::from_be_bytes([data[6], data[7]]) as usize;
    assert!(rcode <= 15 && answer.addrs.len() <= answers);
    true
}

/// The shared-memory vectors an object hands the system objects (effector commands,
/// speaker sound, colour detection tables): read, never past the region, and an
/// accepted command slot plays for exactly the frames it says it lasts.
pub fn vectors(data: &[u8]) -> bool {
    use sdk_runtime::robot::camera::{parse_cdt, CDT_CHANNELS};
    use sdk_runtime::robot::vectors::{parse_command_vector, parse_sound_vector, CommandValues, COMMAND_MAX_FRAMES};
    use sdk_runtime::robot::Design;
    let mut taken = false;
    if let Ok(v) = parse_command_vector(data) {
        taken = true;
        for slot in &v.slots {
            let frames = slot.values.duration_frames();
            if matches!(slot.values, CommandValues::Joint2(_) | CommandValues::Joint3(_)) {
                assert!(frames <= COMMAND_MAX_FRAMES);
            }
            if !matches!(slot.values, CommandValues::Unsupported(_)) {
                assert!(frames > 0, "slot {} lasts no frame", slot.index);
                assert!(slot.values.at(frames - 1).is_some() && slot.values.at(frames).is_none(), "slot {} ends at {frames}", slot.index);
            }
        }
    }
    if let Ok(v) = parse_sound_vector(data) {
        taken = true;
        for slot in &v.slots {
            assert!(data.get(slot.data_offset as usize..(slot.data_offset as usize + slot.data_size as usize)).is_some());
        }
    }
    for design in [Design::Ers7, Design::Ers210] {
        if let Ok(tables) = parse_cdt(data, 0x0100_0000, design) {
            taken = true;
            assert!(tables.len() <= CDT_CHANNELS && tables.iter().all(|t| t.channel < CDT_CHANNELS));
        }
    }
    taken
}

/// A peer's payloads once the wire format has framed them. The first byte picks the
/// message (READINGS, IMAGE, CLOCK), the next four are the peer's roles; the rest is
/// the payload. READINGS are checked against every robot design's model: accepted
/// readings name only the design's primitives, each of a role the peer holds; an
/// IMAGE is accepted only with exactly its picture's bytes; CLOCK reads its flags.
pub fn peer(data: &[u8]) -> bool {
    use openr_peer_protocol::{payload, wire};
    use sdk_runtime::robot::model::RobotModel;
    use sdk_runtime::robot::Design;
    use std::sync::OnceLock;
    static MODELS: OnceLock<Vec<RobotModel>> = OnceLock::new();
    let Some((head, p)) = data.split_first_chunk::<5>() else { return false };
    let roles = u32::from_le_bytes([head[1], head[2], head[3], head[4]]);
    match head[0] % 3 {
        0 => {
            let Ok(r) = wire::parse_readings(p) else { return false };
            let mut taken = false;
            for model in MODELS.get_or_init(|| Design::ALL.into_iter().map(RobotModel::new).collect()) {
                match payload::check_readings(model, roles, &r) {
                    Ok(()) => {
                        taken = true;
                        assert!(r.joints.iter().chain(&r.sensors).all(|&(id, _)| model.primitive(id).is_some()));
                    }
                    Err((code, text)) => assert!((code == wire::E_BAD_PAYLOAD || code == wire::E_ROLE) && text.starts_with("READINGS: ")),
                }
            }
            taken
        }
        1 => {
            // A small picture whose size comes from the roles' bytes.
            let (w, h) = (1 + (roles & 7) as usize, 1 + ((roles >> 3) & 7) as usize);
            let Ok(rgb) = payload::parse_image(p, w, h) else { return false };
            assert_eq!(rgb.len(), w * h * 3);
            assert_eq!(&p[..4], [(w as u16).to_le_bytes(), (h as u16).to_le_bytes()].concat());
            true
        }
        _ => {
            let Ok(flags) = payload::parse_clock(p) else { return false };
            assert_eq!(flags.to_le_bytes(), p[..4]);
            true
        }
    }
}
