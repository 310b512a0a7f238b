//! The checks of a peer's payloads that need no runtime state, only the robot model:
//! the message handlers call them, and the fuzz checks (fuzz-checks `peer`) drive them
//! without a runtime.
use crate::role_of;
use crate::wire::*;
use openr_robot::model::RobotModel;
use openr_robot::Readings;

/// Every primitive of a READINGS message is known, listed in its section (joints or
/// sensors) and belongs to a role in `roles`. The refusal: (error code, text).
pub fn check_readings(model: &RobotModel, roles: u32, r: &Readings) -> Result<(), (u16, String)> {
    for &(id, _) in r.joints.iter().chain(&r.sensors) {
        let Some(p) = model.primitive(id) else {
            return Err((E_BAD_PAYLOAD, format!("READINGS: unknown primitive ID {id:#x}")));
        };
        let Some(role) = role_of(p.kind) else {
            return Err((E_BAD_PAYLOAD, format!("READINGS: {} ({id:#x}) has no readings", p.locator)));
        };
        let is_joint = r.joints.iter().any(|&(j, _)| j == id);
        if is_joint != (role == ROLE_JOINTS) {
            return Err((E_BAD_PAYLOAD, format!("READINGS: {} ({id:#x}) listed in the wrong section", p.locator)));
        }
        if roles & role == 0 {
            let name = ROLE_NAMES[role.trailing_zeros() as usize];
            return Err((E_ROLE, format!("READINGS: {} needs the {name} role, which this peer does not hold", p.locator)));
        }
    }
    Ok(())
}

/// IMAGE: u16 width, u16 height (the camera's, `w` × `h`), then exactly its RGB bytes.
pub fn parse_image(payload: &[u8], w: usize, h: usize) -> Result<&[u8], String> {
    let mut i = In::new(payload);
    let dims = (i.u16(), i.u16());
    let rgb = i.rest();
    match dims {
        (Ok(pw), Ok(ph)) if pw as usize == w && ph as usize == h && rgb.len() == w * h * 3 => Ok(rgb),
        _ => Err(format!("IMAGE must be u16 width {w}, u16 height {h}, then {} RGB bytes", w * h * 3)),
    }
}

/// MIC: 16-bit stereo PCM, so whole 4-byte sample pairs.
pub fn check_mic(payload: &[u8]) -> Result<(), String> {
    if payload.len() % 4 != 0 {
        return Err("MIC: 16-bit stereo PCM (a multiple of 4 bytes)".into());
    }
    Ok(())
}

/// CLOCK: its u32 flags.
pub fn parse_clock(payload: &[u8]) -> Result<u32, String> {
    In::new(payload).u32().map_err(|e| format!("CLOCK: {e}"))
}
