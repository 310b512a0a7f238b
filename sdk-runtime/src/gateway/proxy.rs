//! The OPEN-R API proxy (remote-processing 1.3, 7.4): a host object's hardware calls —
//! primitives, joint gains, joint and sensor values, motor power, the power status —
//! run on the robot. A call is one `PROXY_CALL` frame (`api:u8`, its arguments,
//! little-endian) answered by one `PROXY_REPLY` (`OStatus:u32`, the out-values).
//! Memory-only helpers (`NewCommandVectorData`, …) stay on the host: the vectors they
//! make travel as data through the gateway channels.
use std::net::TcpStream;
use std::time::Duration;

use super::link::Link;
use super::wire;
use crate::robot::status::{O_FAIL, O_SUCCESS};
use openr_sys::PrimitiveId;

pub const OPEN_PRIMITIVE: u8 = 1;
pub const CLOSE_PRIMITIVE: u8 = 2;
pub const JOINT_GAIN: u8 = 3;
pub const JOINT_VALUE: u8 = 4;
pub const SENSOR_VALUE: u8 = 5;
pub const SET_MOTOR_POWER: u8 = 6;
pub const POWER_STATUS: u8 = 7;
pub const ROBOT_DESIGN: u8 = 8;

/// How long a call waits for the proxy connection to come up.
const CONNECT_WAIT: Duration = Duration::from_secs(10);

/// Runs `api` on the robot: None when this run has no proxy (the call runs locally),
/// else the reply (`[O_FAIL]` when the robot cannot be reached).
pub fn call(api: u8, args: &[u8]) -> Option<Vec<u8>> {
    let link = super::state()?.client.get()?;
    let mut req = vec![api];
    req.extend_from_slice(args);
    match link.exchange(wire::PROXY_CALL, &req, CONNECT_WAIT) {
        Some((wire::PROXY_REPLY, reply)) if reply.len() >= 4 => Some(reply),
        _ => {
            once_unreachable(link);
            Some(O_FAIL.to_le_bytes().to_vec())
        }
    }
}

fn once_unreachable(link: &Link) {
    if !super::state().is_some_and(|s| s.unreachable.swap(true, std::sync::atomic::Ordering::AcqRel)) {
        super::warn(&format!("{}: the robot's OPEN-R API proxy is not reachable: OPENR:: calls of host objects return oFAIL", link.place));
    }
}

/// `GetRobotDesign` of a host object: the robot's design, asked once (it never changes
/// during a run). None when this run has no proxy; Some(None) when the robot cannot be
/// reached (then it is asked again next time).
pub fn robot_design() -> Option<Option<&'static std::ffi::CStr>> {
    let state = super::state()?;
    if let Some(d) = state.design.get() {
        return Some(Some(d.as_c_str()));
    }
    let reply = call(ROBOT_DESIGN, &[])?;
    let (status, name) = split(&reply);
    let name = std::ffi::CString::new(name).ok().filter(|_| status == O_SUCCESS);
    Some(name.map(|n| state.design.get_or_init(|| n).as_c_str()))
}

/// The status of a reply and the out-values after it.
pub fn split(reply: &[u8]) -> (u32, &[u8]) {
    let status = u32::from_le_bytes([reply[0], reply[1], reply[2], reply[3]]);
    (status, &reply[4..])
}

/// Robot: answers calls until the host goes.
pub(super) fn serve_calls(s: &mut TcpStream) {
    while let Ok((kind, req)) = wire::read_frame(s) {
        if kind != wire::PROXY_CALL || req.is_empty() {
            break;
        }
        if wire::write_frame(s, wire::PROXY_REPLY, &execute(req[0], &req[1..])).is_err() {
            break;
        }
    }
}

/// One call against this robot.
fn execute(api: u8, args: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    let status = run(api, args, &mut out).unwrap_or(crate::robot::status::O_INVALID_ARG);
    let mut reply = status.to_le_bytes().to_vec();
    reply.extend_from_slice(&out);
    reply
}

fn run(api: u8, args: &[u8], out: &mut Vec<u8>) -> Option<u32> {
    use crate::robot_api as r;
    let mut a = wire::In::new(args);
    Some(match api {
        OPEN_PRIMITIVE => {
            let loc = std::ffi::CString::new(args).ok()?;
            let mut id = PrimitiveId::default();
            // SAFETY: a C string and a live out-param.
            let st = unsafe { r::open_primitive(loc.as_ptr(), &mut id) };
            out.extend_from_slice(&id.0.to_le_bytes());
            st
        }
        CLOSE_PRIMITIVE => r::close_primitive(PrimitiveId(a.u32().ok()?)),
        JOINT_GAIN => {
            let (op, id) = (a.i32().ok()?, PrimitiveId(a.u32().ok()?));
            let mut gains = [0u16; 6];
            for g in &mut gains {
                *g = a.u16().ok()?;
            }
            // SAFETY: six live words.
            let st = unsafe { r::joint_gain(op, id, gains.as_mut_ptr()) };
            gains.iter().for_each(|g| out.extend_from_slice(&g.to_le_bytes()));
            st
        }
        JOINT_VALUE | SENSOR_VALUE => {
            let mut v = [0u8; 16];
            let id = PrimitiveId(a.u32().ok()?);
            // SAFETY: 16 live bytes, the size of OJointValue / OSensorValue.
            let st = unsafe {
                if api == JOINT_VALUE {
                    r::joint_value(id, v.as_mut_ptr().cast())
                } else {
                    r::sensor_value(id, v.as_mut_ptr().cast())
                }
            };
            out.extend_from_slice(&v);
            st
        }
        SET_MOTOR_POWER => {
            crate::host_api::set_motor_power(a.i32().ok()?);
            O_SUCCESS
        }
        POWER_STATUS => {
            let mut p = crate::power::PowerState::default();
            // SAFETY: a live out-param.
            unsafe { crate::host_api::power_status(&mut p) };
            // SAFETY: a repr(C) struct of 32-bit integers, no padding.
            out.extend_from_slice(unsafe { std::slice::from_raw_parts((&p as *const crate::power::PowerState).cast::<u8>(), std::mem::size_of_val(&p)) });
            O_SUCCESS
        }
        ROBOT_DESIGN => {
            let rt = crate::runtime::Runtime::get()?;
            out.extend_from_slice(rt.design.as_bytes());
            O_SUCCESS
        }
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_or_unknown_call_is_an_invalid_argument() {
        let invalid = crate::robot::status::O_INVALID_ARG.to_le_bytes().to_vec();
        assert_eq!(execute(CLOSE_PRIMITIVE, &[1, 2]), invalid, "3 bytes short of an id");
        assert_eq!(execute(JOINT_GAIN, &[0; 19]), invalid, "one byte short of six gains");
        assert_eq!(execute(99, &[]), invalid, "no such call");
    }
}
