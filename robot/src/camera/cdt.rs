//! Colour detection tables (`SetCdtVectorData`, robot-api 6.7): parsing a CDT vector, and
//! the lookup that classifies a pixel into the channels whose table row it falls in.
use crate::model::{Design, PrimitiveId};
use crate::status::*;
use crate::vectors::{odata, rd_u32, VectorHeader, HEADER_SIZE};

pub const CDT_CHANNELS: usize = 8;
pub const CDT_SEGMENTS: usize = 32;
pub const CDT_INFO_SIZE: usize = 144;
const ODATA_CDT: u32 = 21;

/// One parsed `OCdtInfo`: channel index (0..7) and its 32 packed entries.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CdtTable {
    pub channel: usize,
    pub entries: [u32; CDT_SEGMENTS],
}

/// Parses the first `numData` infos of an `OCdtVectorData` (robot-api 6.7). Every info
/// must be type odataCDT, name `camera` and have a single-bit channel (not 0x80 on
/// ERS-7); nothing is loaded unless all are valid. Errors: `oINVALID_DATA_TYPE`
/// (vector type ≠ 1028 or info type ≠ 21), `oINVALID_PRIMITIVE_ID`, `oINVALID_ARG`
/// (bad channel), `oFAIL` (truncated vector, numData > 8 or > maxNumData).
pub fn parse_cdt(bytes: &[u8], camera: PrimitiveId, design: Design) -> Result<Vec<CdtTable>, OStatus> {
    let h = VectorHeader::read(bytes).map_err(|_| O_FAIL)?;
    if h.vector_type != odata::CDT_VECTOR {
        return Err(O_INVALID_DATA_TYPE);
    }
    let n = h.num_data as usize;
    if n > CDT_CHANNELS || h.num_data > h.max_num_data {
        return Err(O_FAIL);
    }
    if bytes.len() < HEADER_SIZE + n * CDT_INFO_SIZE {
        return Err(O_FAIL);
    }
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let o = HEADER_SIZE + i * CDT_INFO_SIZE;
        let rd = |k: usize| rd_u32(bytes, o + k).map_err(|_| O_FAIL);
        if rd(0)? != ODATA_CDT {
            return Err(O_INVALID_DATA_TYPE);
        }
        if rd(4)? != camera {
            return Err(O_INVALID_PRIMITIVE_ID);
        }
        let chan = rd(8)?;
        let max_chan = if design == Design::Ers7 { 0x40 } else { 0x80 };
        if chan == 0 || !chan.is_power_of_two() || chan > max_chan {
            return Err(O_INVALID_ARG);
        }
        let mut entries = [0u32; CDT_SEGMENTS];
        for (s, e) in entries.iter_mut().enumerate() {
            *e = rd(12 + 4 * s)?;
        }
        out.push(CdtTable { channel: chan.trailing_zeros() as usize, entries });
    }
    Ok(out)
}

/// Builds an `OCdtVectorData` (as `NewCdtVectorData` + `Init`/`Set` would) — for tests
/// and tools. `tables`: (channel bit, entries).
pub fn build_cdt_vector(camera: PrimitiveId, tables: &[(u32, [u32; CDT_SEGMENTS])]) -> Vec<u8> {
    let mut b = vec![0u8; 4096];
    let h = VectorHeader {
        total_size: 4096,
        vector_type: odata::CDT_VECTOR,
        info_offset: HEADER_SIZE as u32,
        info_size: CDT_INFO_SIZE as u32,
        max_num_data: CDT_CHANNELS as u32,
        num_data: tables.len() as u32,
        sync_key: 0xFFFF_FFFF,
        ..VectorHeader::default()
    };
    h.write(&mut b).expect("fits");
    for i in 0..CDT_CHANNELS {
        let o = HEADER_SIZE + i * CDT_INFO_SIZE;
        let (chan, entries) = tables.get(i).copied().unwrap_or((0, [0x8080_8080; CDT_SEGMENTS]));
        let id = if i < tables.len() { camera } else { 0xFFFF_FFFF };
        let mut put = |k: usize, v: u32| b[o + k..o + k + 4].copy_from_slice(&v.to_le_bytes());
        put(0, ODATA_CDT);
        put(4, id);
        put(8, chan);
        for (s, e) in entries.iter().enumerate() {
            put(12 + 4 * s, *e);
        }
    }
    b
}

/// Packs one table entry like `OCdtInfo::Set(seg, crMax, crMin, cbMax, cbMin)`.
pub fn cdt_entry(cr_max: u8, cr_min: u8, cb_max: u8, cb_min: u8) -> u32 {
    cr_min as u32 | (cr_max as u32) << 8 | (cb_min as u32) << 16 | (cb_max as u32) << 24
}

/// The tables a [`CdtLut`] was built from (None: channel not loaded).
pub type CdtKey = [Option<[u32; CDT_SEGMENTS]>; CDT_CHANNELS];

/// The loaded tables as two lookup tables: bit k of `cr[seg][cr]` is set when Cr lies
/// in channel k's Cr range for that Y segment (likewise `cb`).
#[derive(Clone, Debug)]
pub struct CdtLut {
    tables: [Option<[u32; CDT_SEGMENTS]>; CDT_CHANNELS],
    cr: Box<[[u8; 256]; CDT_SEGMENTS]>,
    cb: Box<[[u8; 256]; CDT_SEGMENTS]>,
}

impl Default for CdtLut {
    fn default() -> CdtLut {
        CdtLut { tables: [None; CDT_CHANNELS], cr: Box::new([[0; 256]; CDT_SEGMENTS]), cb: Box::new([[0; 256]; CDT_SEGMENTS]) }
    }
}

impl CdtLut {
    pub fn load(&mut self, t: &CdtTable) {
        self.tables[t.channel] = Some(t.entries);
        self.rebuild();
    }

    /// The loaded tables, to tell whether two images were classified alike.
    pub fn key(&self) -> CdtKey {
        self.tables
    }

    pub fn table(&self, channel: usize) -> Option<&[u32; CDT_SEGMENTS]> {
        self.tables.get(channel)?.as_ref()
    }

    fn rebuild(&mut self) {
        *self.cr = [[0; 256]; CDT_SEGMENTS];
        *self.cb = [[0; 256]; CDT_SEGMENTS];
        for (k, t) in self.tables.iter().enumerate() {
            let Some(t) = t else { continue };
            for (seg, &e) in t.iter().enumerate() {
                let [cr_min, cr_max, cb_min, cb_max] = e.to_le_bytes();
                for v in cr_min..=cr_max {
                    self.cr[seg][v as usize] |= 1 << k;
                }
                for v in cb_min..=cb_max {
                    self.cb[seg][v as usize] |= 1 << k;
                }
            }
        }
    }

    /// CDT bits of one pixel (the rule of robot-api 6.7).
    #[inline(always)]
    pub fn classify(&self, y: u8, cr: u8, cb: u8) -> u8 {
        let seg = y as usize >> 3;
        self.cr[seg][cr as usize] & self.cb[seg][cb as usize]
    }
}
