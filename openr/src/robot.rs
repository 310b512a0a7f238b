//! The `OPENR::` robot calls (robot-api 4): primitives, motor power, joint gains and
//! readings, the robot design, shutdown, and command vectors (robot-api 6.2/6.3) that a
//! `Subject<CommandVector>` hands to `OVirtualRobotComm.Effector` without copying, as
//! the C++ samples send `RCRegion(memID, offset, base, totalSize)`.
use std::ffi::{CStr, CString};

use crate::abi;
use crate::host;
use crate::object::{Context, Status, Subject};
use crate::payload::Payload;
use crate::shm::{self, Region};

/// An `OStatus` value other than oSUCCESS (`OPENR/OStatus.h`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct OStatus(pub u32);

impl OStatus {
    pub const FAIL: OStatus = OStatus(2);
    pub const INVALID_ARG: OStatus = OStatus(4);
    pub const NO_MEMORY: OStatus = OStatus(5);
    pub const NOT_FOUND: OStatus = OStatus(6);
    pub const INVALID_PRIMITIVE_ID: OStatus = OStatus(4096);
    pub const GAIN_DISABLED: OStatus = OStatus(4108);
}

impl std::fmt::Display for OStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "OStatus {}", self.0)
    }
}

impl std::error::Error for OStatus {}

pub type Result<T> = std::result::Result<T, OStatus>;

fn check(rc: u32) -> Result<()> {
    if rc == abi::O_SUCCESS {
        Ok(())
    } else {
        Err(OStatus(rc))
    }
}

fn api() -> Result<&'static abi::openr_host_api> {
    host::api().ok_or(OStatus::FAIL)
}

/// `OPrimitiveID`: the host table's own type (`openr_sys::PrimitiveId`), so a primitive
/// id cannot be passed where a memory id or a selector is expected.
pub use openr_sys::PrimitiveId;

/// `OPENR::OpenPrimitive(locator, &id)`.
pub fn open_primitive(locator: &str) -> Result<PrimitiveId> {
    let a = api()?;
    let c = CString::new(locator).map_err(|_| OStatus::INVALID_ARG)?;
    let mut id = PrimitiveId::default();
    // SAFETY: a C string and a live out-parameter.
    check(unsafe { (a.open_primitive)(c.as_ptr(), &mut id) })?;
    Ok(id)
}

/// `OPENR::ClosePrimitive(id)`.
pub fn close_primitive(id: PrimitiveId) -> Result<()> {
    // SAFETY: any id is accepted (an unknown one is an error status).
    check(unsafe { (api()?.close_primitive)(id) })
}

/// `OPENR::SetMotorPower(opowerON / opowerOFF)`.
pub fn set_motor_power(on: bool) -> Result<()> {
    // SAFETY: plain call.
    unsafe { (api()?.set_motor_power)(on as i32) };
    Ok(())
}

/// `OPENR::Shutdown()`: begins the Stop/Destroy sequence.
pub fn shutdown() -> Result<()> {
    // SAFETY: `shutdown` takes no arguments.
    unsafe { (api()?.shutdown)() };
    Ok(())
}

/// `OPENR::GetRobotDesign`: "ERS-7" etc.
pub fn robot_design() -> Result<String> {
    // SAFETY: `robot_design` takes no arguments.
    let p = unsafe { (api()?.robot_design)() };
    if p.is_null() {
        return Err(OStatus::FAIL);
    }
    // SAFETY: the runtime returns a C string that lives as long as it does.
    Ok(unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
}

/// PID gains and shifts of a joint (`OPENR::SetJointGain` arguments).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Gain {
    pub p: u16,
    pub i: u16,
    pub d: u16,
    pub p_shift: u16,
    pub i_shift: u16,
    pub d_shift: u16,
}

impl Gain {
    /// Standard ERS-7 gains (ers7-model 4.5); shifts are always 0x0E/0x02/0x0F.
    pub const fn standard(p: u16, i: u16, d: u16) -> Gain {
        Gain { p, i, d, p_shift: 0x0e, i_shift: 0x02, d_shift: 0x0f }
    }
    /// Legs J1 and J3.
    pub const LEG_J1: Gain = Gain::standard(0x1c, 0x08, 0x01);
    pub const LEG_J3: Gain = Gain::standard(0x1c, 0x08, 0x01);
    /// Legs J2.
    pub const LEG_J2: Gain = Gain::standard(0x14, 0x04, 0x01);
}

fn gain_op(op: i32, id: PrimitiveId, gains: &mut [u16; 6]) -> Result<()> {
    // SAFETY: six u16 read or written.
    check(unsafe { (api()?.joint_gain)(op, id, gains.as_mut_ptr()) })
}

/// `OPENR::EnableJointGain(id)`.
pub fn enable_joint_gain(id: PrimitiveId) -> Result<()> {
    gain_op(abi::GAIN_ENABLE, id, &mut [0; 6])
}

/// `OPENR::DisableJointGain(id)`.
pub fn disable_joint_gain(id: PrimitiveId) -> Result<()> {
    gain_op(abi::GAIN_DISABLE, id, &mut [0; 6])
}

/// `OPENR::SetJointGain(id, p, i, d, ps, is, ds)`.
pub fn set_joint_gain(id: PrimitiveId, g: Gain) -> Result<()> {
    gain_op(abi::GAIN_SET, id, &mut [g.p, g.i, g.d, g.p_shift, g.i_shift, g.d_shift])
}

/// `OJointValue` (robot-api 6.4): angles in µrad.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct JointValue {
    pub value_urad: i32,
    pub signal: u16,
    pub pwm_duty: i16,
    pub ref_value_urad: i32,
    pub ref_signal: u16,
}

impl JointValue {
    pub fn degrees(&self) -> f64 {
        self.value_urad as f64 * 180.0 / std::f64::consts::PI / 1e6
    }
}

/// `OSensorValue` (16 bytes): value, signal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct SensorValue {
    pub value: i32,
    pub signal: u16,
}

fn le_i32(b: &[u8], o: usize) -> i32 {
    i32::from_le_bytes(b[o..o + 4].try_into().unwrap())
}
fn le_u16(b: &[u8], o: usize) -> u16 {
    u16::from_le_bytes(b[o..o + 2].try_into().unwrap())
}

/// `OPENR::GetJointValue(id, &v)`.
pub fn joint_value(id: PrimitiveId) -> Result<JointValue> {
    let mut b = [0u8; 16];
    // SAFETY: `b` is 16 writable bytes, the `value16` the table's `joint_value` fills.
    check(unsafe { (api()?.joint_value)(id, b.as_mut_ptr().cast()) })?;
    Ok(JointValue {
        value_urad: le_i32(&b, 0),
        signal: le_u16(&b, 4),
        pwm_duty: le_u16(&b, 6) as i16,
        ref_value_urad: le_i32(&b, 8),
        ref_signal: le_u16(&b, 12),
    })
}

/// `OPENR::GetSensorValue(id, &v)`.
pub fn sensor_value(id: PrimitiveId) -> Result<SensorValue> {
    let mut b = [0u8; 16];
    // SAFETY: `b` is 16 writable bytes, the `value16` the table's `sensor_value` fills.
    check(unsafe { (api()?.sensor_value)(id, b.as_mut_ptr().cast()) })?;
    Ok(SensorValue { value: le_i32(&b, 0), signal: le_u16(&b, 4) })
}

/// `odataJOINT_COMMAND2`.
pub const ODATA_JOINT_COMMAND2: u32 = 259;
/// Frames per command slot (`OCommandData`).
pub const MAX_FRAMES: usize = 16;
const HEADER: usize = 192;
const INFO: usize = 32;

/// An `OCommandVectorData` in shared memory (`OPENR::NewCommandVectorData`), owning one
/// reference on its region. Send it with `Subject<CommandVector>::send_vector`.
#[derive(Debug)]
pub struct CommandVector {
    region: Region,
    slots: usize,
}

impl CommandVector {
    /// A vector of `n` slots, initialised as robot-api 6.3 says (numData 0).
    pub fn new(n: usize) -> Result<CommandVector> {
        let a = api()?;
        let (mut mem_id, mut base) = (abi::MemId::default(), std::ptr::null_mut());
        // SAFETY: live out-parameters.
        check(unsafe { (a.new_vector)(abi::VECTOR_COMMAND, n, 0, &mut mem_id, &mut base) })?;
        let size = host::shm_base(mem_id).map(|(_, s)| s).unwrap_or(HEADER + 160 * n);
        Ok(CommandVector { region: Region::adopt(mem_id, base.cast(), size), slots: n })
    }

    /// Slots (`maxNumData`).
    pub fn slots(&self) -> usize {
        self.slots
    }

    /// The region (mem_id, offset 0, whole block).
    pub fn region(&self) -> &Region {
        &self.region
    }

    fn put(&mut self, off: usize, v: u32) {
        self.region.bytes_mut()[off..off + 4].copy_from_slice(&v.to_le_bytes());
    }

    fn get(&self, off: usize) -> u32 {
        u32::from_le_bytes(self.region.bytes()[off..off + 4].try_into().unwrap())
    }

    /// `SetNumData(n)`.
    pub fn set_num_data(&mut self, n: usize) -> Result<()> {
        if n > self.slots {
            return Err(OStatus::INVALID_ARG);
        }
        self.put(32, n as u32);
        Ok(())
    }

    pub fn num_data(&self) -> usize {
        self.get(32) as usize
    }

    /// Slot `slot`: `GetInfo(slot)->Set(odataJOINT_COMMAND2, id, frames.len())` and
    /// the frames' target angles (µrad).
    pub fn set_joint2(&mut self, slot: usize, id: PrimitiveId, frames_urad: &[i32]) -> Result<()> {
        if slot >= self.slots || frames_urad.is_empty() || frames_urad.len() > MAX_FRAMES {
            return Err(OStatus::INVALID_ARG);
        }
        let info = HEADER + INFO * slot;
        self.put(info, ODATA_JOINT_COMMAND2);
        self.put(info + 4, id.0);
        self.put(info + 12, frames_urad.len() as u32);
        let data = self.get(info + 20) as usize;
        for (k, &v) in frames_urad.iter().enumerate() {
            self.put(data + 8 * k, v as u32);
            self.put(data + 8 * k + 4, 0);
        }
        Ok(())
    }

    /// Whether a receiver (the effector) still holds the vector: references besides
    /// this one, counted on the Rust side from what subjects send and get back.
    pub fn in_use(&self) -> bool {
        shm::rust_refs(self.region.mem_id()) > 1
    }
}

/// The bytes of the vector (a copy, should `set_data` be used; `send_vector` does not
/// copy). Received vectors are not viewed through this type.
impl Payload for CommandVector {
    fn size(&self) -> usize {
        self.region.len()
    }
    fn write(&self, out: &mut [u8]) {
        out.copy_from_slice(self.region.bytes());
    }
    fn read(_bytes: &[u8]) -> Option<&CommandVector> {
        None
    }
}

impl Subject<CommandVector> {
    /// `SetData(RCRegion*)` with the vector's own region, then `NotifyObservers`.
    pub fn send_vector(&self, ctx: &mut Context, v: &CommandVector) -> Status {
        match self.set_region(ctx, v.region()) {
            Status::NoMemory => Status::NoMemory,
            _ => self.notify_observers(ctx),
        }
    }
}
