//! Frames of the gateway channels (docs/rp-protocol.md "Wire protocol"): little-endian
//! `type:u8, length:u32, payload`, one TCP connection per channel.
use std::io::{self, Read, Write};

// The payloads' integers and u16-length strings are the robot protocol's.
pub use openr_peer_protocol::wire::{In, Out};

pub const HELLO: u8 = 1;
pub const DATA: u8 = 2;
pub const READY_ASSERT: u8 = 3;
pub const READY_DEASSERT: u8 = 4;
pub const PROXY_CALL: u8 = 5;
pub const PROXY_REPLY: u8 = 6;
/// The far side refuses the channel; the payload says why (UTF-8).
pub const ERROR: u8 = 7;

/// Protocol version carried by HELLO.
pub const VERSION: u8 = 1;
/// A frame longer than this is a protocol error (the robot has 64 MB).
pub const MAX_FRAME: usize = 64 << 20;

pub fn write_frame(w: &mut impl Write, kind: u8, payload: &[u8]) -> io::Result<()> {
    let mut buf = Vec::with_capacity(5 + payload.len());
    buf.push(kind);
    buf.extend_from_slice(&(payload.len() as u32).to_le_bytes());
    buf.extend_from_slice(payload);
    w.write_all(&buf)
}

/// The next frame; `UnexpectedEof` when the peer closed between frames.
pub fn read_frame(r: &mut impl Read) -> io::Result<(u8, Vec<u8>)> {
    let mut head = [0u8; 5];
    r.read_exact(&mut head)?;
    let len = u32::from_le_bytes([head[1], head[2], head[3], head[4]]) as usize;
    if len > MAX_FRAME {
        return Err(io::Error::new(io::ErrorKind::InvalidData, format!("a frame of {len} bytes (more than {MAX_FRAME})")));
    }
    let mut payload = vec![0u8; len];
    r.read_exact(&mut payload)?;
    Ok((head[0], payload))
}

/// What each end says about its line first (HELLO).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Hello {
    /// `b'S'`, `b'O'` or `b'P'` (the proxy).
    pub suffix: u8,
    pub port: u16,
    /// The line's service name (`TCPGateway.Sensor.OSensorFrameVectorData.O`).
    pub name: String,
    /// Where the line is, `ROBOTGW.CFG:3`, for the far side's messages.
    pub place: String,
}

impl Hello {
    pub fn encode(&self) -> Vec<u8> {
        let mut b = Out::default();
        b.u8(VERSION).u8(self.suffix).u16(self.port).str(&self.name).str(&self.place);
        b.0
    }

    pub fn decode(b: &[u8]) -> Result<Hello, String> {
        let bad = |_| "a malformed HELLO (not a cargo-openr gateway?)".to_string();
        let mut i = In::new(b);
        let (version, suffix, port) = (i.u8().map_err(bad)?, i.u8().map_err(bad)?, i.u16().map_err(bad)?);
        if version != VERSION {
            return Err(format!("gateway protocol version {version} (this side speaks {VERSION})"));
        }
        Ok(Hello { suffix, port, name: i.str().map_err(bad)?, place: i.str().map_err(bad)? })
    }

    /// The DataType part of the name (`char` of `TCPGateway.Send.char.S`).
    pub fn data_type(&self) -> &str {
        self.name.rsplit('.').nth(1).unwrap_or("")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_and_hello_round_trip() {
        let mut buf = Vec::new();
        write_frame(&mut buf, DATA, b"abc").unwrap();
        assert_eq!(buf, [2, 3, 0, 0, 0, b'a', b'b', b'c']);
        assert_eq!(read_frame(&mut &buf[..]).unwrap(), (DATA, b"abc".to_vec()));
        let h = Hello { suffix: b'O', port: 59002, name: "TCPGateway.S1.char.O".into(), place: "ROBOTGW.CFG:2".into() };
        assert_eq!(Hello::decode(&h.encode()).unwrap(), h);
        assert_eq!(h.data_type(), "char");
        assert!(Hello::decode(&[1, b'S', 0]).is_err());
        assert!(Hello::decode(&[9, b'S', 0, 0]).unwrap_err().contains("version 9"));
        let huge = [DATA, 0xff, 0xff, 0xff, 0x7f];
        assert_eq!(read_frame(&mut &huge[..]).unwrap_err().kind(), io::ErrorKind::InvalidData);
    }
}
