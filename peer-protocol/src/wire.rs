//! The byte format of the external robot protocol (docs/robot-protocol.md): the fixed
//! 16-byte header, the message types, and payload builders / parsers. Little-endian
//! throughout; strings are a u16 byte count then UTF-8.
use std::io::Read;

pub const MAGIC: [u8; 4] = *b"ORP1";
/// Protocol version carried in every header; a different one is refused.
pub const VERSION: u16 = 1;
/// Compatible additions (fields appended to payloads, new message types) bump this.
/// 1: FRAME flag `FRAME_CAMERA_NEXT`; 2: WELCOME's table of sensor value ranges and
/// standard gains.
pub const REVISION: u16 = 2;
pub const HEADER_LEN: usize = 16;
/// Largest payload accepted (a camera picture of the ERS-7 is 399 360 bytes).
pub const MAX_PAYLOAD: u32 = 4 << 20;

pub const HELLO: u16 = 1;
pub const WELCOME: u16 = 2;
pub const FRAME: u16 = 3;
pub const READINGS: u16 = 4;
pub const IMAGE: u16 = 5;
pub const MIC: u16 = 6;
pub const SPEAKER: u16 = 7;
pub const CLOCK: u16 = 8;
pub const BYE: u16 = 9;
pub const ERROR: u16 = 10;

/// Roles a peer claims in HELLO (bit mask).
pub const ROLE_JOINTS: u32 = 1;
pub const ROLE_ACCEL: u32 = 2;
pub const ROLE_SWITCHES: u32 = 4;
pub const ROLE_PSD: u32 = 8;
pub const ROLE_CAMERA: u32 = 16;
pub const ROLE_MIC: u32 = 32;
pub const ROLE_SPEAKER: u32 = 64;
pub const ROLE_ALL: u32 = 127;
/// Role bits in order (index = bit position).
pub const ROLE_NAMES: [&str; 7] = ["joints", "accel", "switches", "psd", "camera", "mic", "speaker"];

/// HELLO / WELCOME / CLOCK flag: lockstep clock owner.
pub const FLAG_CLOCK: u32 = 1;

/// FRAME flags.
pub const FRAME_SENSOR_DUE: u8 = 1;
pub const FRAME_CAMERA_DUE: u8 = 2;
pub const FRAME_MIC_DUE: u8 = 4;
pub const FRAME_READINGS_EXPECTED: u8 = 8;
pub const FRAME_CAMERA_NEXT: u8 = 16;

/// Primitive classes of the WELCOME table.
pub const CLASS_JOINT: u16 = 1;
pub const CLASS_EAR: u16 = 2;
pub const CLASS_LED2: u16 = 3;
pub const CLASS_LED3: u16 = 4;
pub const CLASS_ACCEL: u16 = 5;
pub const CLASS_SWITCH: u16 = 6;
pub const CLASS_PSD: u16 = 7;
pub const CLASS_CAMERA: u16 = 8;
pub const CLASS_MIC: u16 = 9;
pub const CLASS_SPEAKER: u16 = 10;
pub const CLASS_OTHER: u16 = 11;

/// ERROR codes.
pub const E_BAD_MAGIC: u16 = 1;
pub const E_BAD_VERSION: u16 = 2;
pub const E_TOO_LONG: u16 = 3;
pub const E_BAD_TYPE: u16 = 4;
pub const E_BAD_PAYLOAD: u16 = 5;
pub const E_BAD_FRAME: u16 = 6;
pub const E_BAD_STATE: u16 = 7;
pub const E_ROLE: u16 = 8;
pub const E_OVERFLOW: u16 = 9;

/// A message header.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    pub version: u16,
    pub kind: u16,
    pub length: u32,
    pub frame: u32,
}

/// Why a header was refused: an ERROR code and a message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal(pub u16, pub String);

impl Header {
    pub fn parse(b: &[u8; HEADER_LEN]) -> Result<Header, Refusal> {
        if b[0..4] != MAGIC {
            return Err(Refusal(E_BAD_MAGIC, format!("bad magic {:02x?} (expected \"ORP1\")", &b[0..4])));
        }
        let h = Header {
            version: u16::from_le_bytes([b[4], b[5]]),
            kind: u16::from_le_bytes([b[6], b[7]]),
            length: u32::from_le_bytes([b[8], b[9], b[10], b[11]]),
            frame: u32::from_le_bytes([b[12], b[13], b[14], b[15]]),
        };
        if h.version != VERSION {
            return Err(Refusal(E_BAD_VERSION, format!("protocol version {} not supported (this runtime speaks {VERSION})", h.version)));
        }
        if h.length > MAX_PAYLOAD {
            return Err(Refusal(E_TOO_LONG, format!("payload of {} bytes (at most {MAX_PAYLOAD})", h.length)));
        }
        Ok(h)
    }
}

/// A whole message: header + payload.
pub fn message(kind: u16, frame: u32, payload: &[u8]) -> Vec<u8> {
    let mut m = Vec::with_capacity(HEADER_LEN + payload.len());
    m.extend_from_slice(&MAGIC);
    m.extend_from_slice(&VERSION.to_le_bytes());
    m.extend_from_slice(&kind.to_le_bytes());
    m.extend_from_slice(&(payload.len() as u32).to_le_bytes());
    m.extend_from_slice(&frame.to_le_bytes());
    m.extend_from_slice(payload);
    m
}

/// Reads one message; `Ok(None)` at a clean end of stream (before a header).
pub fn read_message(r: &mut impl Read) -> std::io::Result<Option<Result<(Header, Vec<u8>), Refusal>>> {
    let mut h = [0u8; HEADER_LEN];
    let mut got = 0;
    while got < HEADER_LEN {
        match r.read(&mut h[got..]) {
            Ok(0) if got == 0 => return Ok(None),
            Ok(0) => return Err(std::io::ErrorKind::UnexpectedEof.into()),
            Ok(n) => got += n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    let header = match Header::parse(&h) {
        Ok(h) => h,
        Err(e) => return Ok(Some(Err(e))),
    };
    let mut payload = vec![0u8; header.length as usize];
    r.read_exact(&mut payload)?;
    Ok(Some(Ok((header, payload))))
}

/// Payload writer.
#[derive(Default)]
pub struct Out(pub Vec<u8>);

impl Out {
    pub fn u8(&mut self, v: u8) -> &mut Self {
        self.0.push(v);
        self
    }
    pub fn u16(&mut self, v: u16) -> &mut Self {
        self.0.extend_from_slice(&v.to_le_bytes());
        self
    }
    pub fn i16(&mut self, v: i16) -> &mut Self {
        self.0.extend_from_slice(&v.to_le_bytes());
        self
    }
    pub fn u32(&mut self, v: u32) -> &mut Self {
        self.0.extend_from_slice(&v.to_le_bytes());
        self
    }
    pub fn i32(&mut self, v: i32) -> &mut Self {
        self.0.extend_from_slice(&v.to_le_bytes());
        self
    }
    pub fn u64(&mut self, v: u64) -> &mut Self {
        self.0.extend_from_slice(&v.to_le_bytes());
        self
    }
    pub fn str(&mut self, s: &str) -> &mut Self {
        let b = &s.as_bytes()[..s.len().min(u16::MAX as usize)];
        self.u16(b.len() as u16);
        self.0.extend_from_slice(b);
        self
    }
    pub fn bytes(&mut self, b: &[u8]) -> &mut Self {
        self.0.extend_from_slice(b);
        self
    }
}

/// Payload reader; every getter fails on a truncated payload.
pub struct In<'a> {
    b: &'a [u8],
    pos: usize,
}

impl<'a> In<'a> {
    pub fn new(b: &'a [u8]) -> In<'a> {
        In { b, pos: 0 }
    }
    pub fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        let end = self
            .pos
            .checked_add(n)
            .filter(|&e| e <= self.b.len())
            .ok_or_else(|| format!("payload truncated: {} more byte(s) needed at offset {}, {} present", n, self.pos, self.b.len()))?;
        let s = &self.b[self.pos..end];
        self.pos = end;
        Ok(s)
    }
    pub fn u8(&mut self) -> Result<u8, String> {
        Ok(self.take(1)?[0])
    }
    pub fn u16(&mut self) -> Result<u16, String> {
        let s = self.take(2)?;
        Ok(u16::from_le_bytes([s[0], s[1]]))
    }
    pub fn u32(&mut self) -> Result<u32, String> {
        let s = self.take(4)?;
        Ok(u32::from_le_bytes([s[0], s[1], s[2], s[3]]))
    }
    pub fn i32(&mut self) -> Result<i32, String> {
        Ok(self.u32()? as i32)
    }
    pub fn str(&mut self) -> Result<String, String> {
        let n = self.u16()? as usize;
        String::from_utf8(self.take(n)?.to_vec()).map_err(|_| "string is not UTF-8".to_string())
    }
    pub fn rest(&mut self) -> &'a [u8] {
        let s = &self.b[self.pos..];
        self.pos = self.b.len();
        s
    }
    pub fn is_empty(&self) -> bool {
        self.pos >= self.b.len()
    }
}

/// HELLO payload.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hello {
    pub roles: u32,
    pub flags: u32,
    pub name: String,
}

pub fn parse_hello(p: &[u8]) -> Result<Hello, String> {
    let mut i = In::new(p);
    let roles = i.u32()?;
    let flags = i.u32()?;
    let name = if i.is_empty() { String::new() } else { i.str()? };
    if roles & !ROLE_ALL != 0 {
        return Err(format!("unknown role bits {:#x}", roles & !ROLE_ALL));
    }
    Ok(Hello { roles, flags, name })
}

pub fn hello(roles: u32, flags: u32, name: &str) -> Vec<u8> {
    let mut o = Out::default();
    o.u32(roles).u32(flags).str(name);
    o.0
}

/// READINGS payload: joints (id, µrad) then sensors (id, value).
pub fn parse_readings(p: &[u8]) -> Result<openr_robot::Readings, String> {
    let mut i = In::new(p);
    let mut r = openr_robot::Readings::default();
    let n = i.u16()?;
    for _ in 0..n {
        r.joints.push((i.u32()?, i.i32()?));
    }
    let n = i.u16()?;
    for _ in 0..n {
        r.sensors.push((i.u32()?, i.i32()?));
    }
    if !i.is_empty() {
        return Err(format!("{} bytes after the sensors (the counts do not match the payload)", i.rest().len()));
    }
    Ok(r)
}

pub fn readings(r: &openr_robot::Readings) -> Vec<u8> {
    let mut o = Out::default();
    o.u16(r.joints.len() as u16);
    for &(id, v) in &r.joints {
        o.u32(id).i32(v);
    }
    o.u16(r.sensors.len() as u16);
    for &(id, v) in &r.sensors {
        o.u32(id).i32(v);
    }
    o.0
}

/// ERROR payload.
pub fn error(code: u16, text: &str) -> Vec<u8> {
    let mut o = Out::default();
    o.u16(code).str(text);
    o.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headers_round_trip_and_bad_ones_are_refused() {
        let m = message(FRAME, 42, &[1, 2, 3]);
        assert_eq!(m.len(), 19);
        let (h, p) = read_message(&mut &m[..]).unwrap().unwrap().unwrap();
        assert_eq!(h, Header { version: 1, kind: FRAME, length: 3, frame: 42 });
        assert_eq!(p, [1, 2, 3]);
        let mut bad = m.clone();
        bad[0] = b'X';
        assert_eq!(read_message(&mut &bad[..]).unwrap().unwrap().unwrap_err().0, E_BAD_MAGIC);
        let mut bad = m.clone();
        bad[4] = 2;
        assert_eq!(read_message(&mut &bad[..]).unwrap().unwrap().unwrap_err().0, E_BAD_VERSION);
        let mut bad = m.clone();
        bad[8..12].copy_from_slice(&(MAX_PAYLOAD + 1).to_le_bytes());
        assert_eq!(read_message(&mut &bad[..]).unwrap().unwrap().unwrap_err().0, E_TOO_LONG);
        assert!(read_message(&mut &m[..5]).is_err(), "truncated header");
        assert!(read_message(&mut &[][..]).unwrap().is_none(), "clean end");
    }

    #[test]
    fn readings_with_trailing_bytes_are_refused() {
        let mut p = readings(&openr_robot::Readings { joints: vec![(1, 2)], sensors: vec![] });
        assert!(parse_readings(&p).is_ok());
        p.push(0);
        assert!(parse_readings(&p).unwrap_err().contains("1 bytes after the sensors"), "{:?}", parse_readings(&p));
    }

    #[test]
    fn payloads_round_trip() {
        let h = parse_hello(&hello(ROLE_JOINTS | ROLE_CAMERA, FLAG_CLOCK, "sim")).unwrap();
        assert_eq!(h, Hello { roles: 17, flags: 1, name: "sim".into() });
        assert!(parse_hello(&hello(1 << 9, 0, "")).is_err());
        assert!(parse_hello(&[1, 0]).is_err());
        let r = openr_robot::Readings { joints: vec![(0x100, -5)], sensors: vec![(0x130, 7)] };
        assert_eq!(parse_readings(&readings(&r)).unwrap(), r);
        assert!(parse_readings(&readings(&r)[..9]).is_err());
    }
}
