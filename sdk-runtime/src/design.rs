//! Robot design data (object-model 4.5, robot-api 12): `FindDesignData` loads the file
//! DESIGNDB.CFG names for a keyword, gunzipped, into shared memory.

use crate::runtime::Runtime;
use openr_sys::DesignDataId;

pub const O_FAIL: u32 = 2;
pub const O_INVALID_ARG: u32 = 4;
pub const O_NO_MEMORY: u32 = 5;
pub const O_NOT_FOUND: u32 = 6;
pub const O_DESIGNDATA_SIZE_ZERO: u32 = 4110;

/// Returns (id, base, size) or an OStatus error code.
pub fn find(rt: &Runtime, keyword: &str) -> Result<(DesignDataId, *mut u8, usize), u32> {
    let content = if keyword == "SYS_CPUINFO" {
        cpu_info()
    } else {
        let path = rt.design_db.iter().find(|(k, _)| k == keyword).map(|(_, p)| p).ok_or(O_NOT_FOUND)?;
        let host = rt.ms.existing(path).ok_or(O_NOT_FOUND)?;
        let raw = std::fs::read(host).map_err(|_| O_NOT_FOUND)?;
        crate::loader::gunzip_if_gzip(raw).map_err(|_| O_FAIL)?
    };
    if content.is_empty() {
        return Err(O_DESIGNDATA_SIZE_ZERO);
    }
    let (id, base) = rt.shm.alloc(content.len()).ok_or(O_NO_MEMORY)?;
    // SAFETY: freshly allocated region of content.len() bytes.
    unsafe { std::ptr::copy_nonoverlapping(content.as_ptr(), base, content.len()) };
    // The design-data id is the region's number; the pair keeps which region it names.
    let data_id = DesignDataId(id.0);
    rt.design_data.lock().unwrap_or_else(|p| p.into_inner()).push((data_id, id));
    Ok((data_id, base, content.len()))
}

pub fn delete(rt: &Runtime, id: DesignDataId) -> u32 {
    let mut ids = rt.design_data.lock().unwrap_or_else(|p| p.into_inner());
    match ids.iter().position(|(i, _)| *i == id) {
        Some(pos) => {
            let (_, mem) = ids.swap_remove(pos);
            rt.shm.unref(mem);
            0
        }
        None => O_INVALID_ARG,
    }
}

/// `OCPUInfo` (256 bytes): sclk, pclk, processorID, reserved. The values are the
/// commonly quoted ERS-7 figures (robot-api 12.3: unverified, no sample reads them).
fn cpu_info() -> Vec<u8> {
    let mut v = vec![0u8; 256];
    v[0..4].copy_from_slice(&96_000_000u32.to_le_bytes());
    v[4..8].copy_from_slice(&576_000_000u32.to_le_bytes());
    v[8..12].copy_from_slice(&0x0000_2800u32.to_le_bytes());
    v
}
