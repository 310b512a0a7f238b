//! The host table (`openr_host.h`): what every object's OPEN-R library asks of the
//! runtime. The runtime exports one instance as `openr_runtime_api_v1`.

/// `OPENR_HOST_ABI_VERSION`.
pub const HOST_ABI_VERSION: u32 = 1;

/// `struct openr_power_state`: the fields of OPowerStatus (robot-api 9.2), in its units.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct openr_power_state {
    /// orsb... bits.
    pub robot_status: u32,
    /// obsb... bits.
    pub battery_status: u32,
    /// Percent.
    pub remaining_capacity: u32,
    /// 0.1 K (2981 = 25 degC).
    pub temperature: u32,
    /// mAh.
    pub fully_charged_capacity: u32,
    /// mV.
    pub voltage: u32,
    /// mA, negative while discharging.
    pub current: i32,
    /// Hours.
    pub time_dif: i32,
    /// 0..3.
    pub volume: u32,
}

/// `struct openr_vr_event`: what the runtime tells a system object (sent to its
/// `vr_attach` selector).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct openr_vr_event {
    /// `VR_DONE`, `VR_DATA` or `VR_CONNECTED`.
    pub kind: u32,
    /// `VR_EFFECTOR`…`VR_MIC`.
    pub service: u32,
    /// DONE: the `vr_submit` token.
    pub token: u64,
    /// DATA: a new vector in shared memory; the event owns one reference.
    pub mem_id: crate::MemId,
    /// DATA: its size in bytes.
    pub size: u32,
}

/// `joint_gain` ops (`OPENR_GAIN_*`).
pub const GAIN_ENABLE: i32 = 0;
pub const GAIN_DISABLE: i32 = 1;
pub const GAIN_SET: i32 = 2;
pub const GAIN_REGISTER_DEFAULT: i32 = 3;
pub const GAIN_SET_DEFAULT: i32 = 4;
pub const GAIN_GET: i32 = 5;
pub const GAIN_GET_DEFAULT: i32 = 6;
/// `sync_key` ops (`OPENR_SYNC_*`).
pub const SYNC_NEW: i32 = 0;
pub const SYNC_CANCEL: i32 = 1;
pub const SYNC_DIVIDE: i32 = 2;
/// `new_vector` kinds (`OPENR_VECTOR_*`).
pub const VECTOR_COMMAND: i32 = 0;
pub const VECTOR_SOUND: i32 = 1;
pub const VECTOR_CDT: i32 = 2;
pub const VECTOR_SENSOR: i32 = 3;
pub const VECTOR_IMAGE: i32 = 4;
/// System-object services (`OPENR_VR_*`).
pub const VR_EFFECTOR: i32 = 0;
pub const VR_SENSOR: i32 = 1;
pub const VR_IMAGE: i32 = 2;
pub const VR_SPEAKER: i32 = 3;
pub const VR_MIC: i32 = 4;
/// `openr_vr_event::kind` values.
pub const VR_DONE: u32 = 1;
pub const VR_DATA: u32 = 2;
pub const VR_CONNECTED: u32 = 3;

/// Every constant of the header (`#define` name, value), for the header check.
pub const HOST_DEFINES: &[(&str, i64)] = &[
    ("OPENR_HOST_ABI_VERSION", HOST_ABI_VERSION as i64),
    ("OPENR_GAIN_ENABLE", GAIN_ENABLE as i64),
    ("OPENR_GAIN_DISABLE", GAIN_DISABLE as i64),
    ("OPENR_GAIN_SET", GAIN_SET as i64),
    ("OPENR_GAIN_REGISTER_DEFAULT", GAIN_REGISTER_DEFAULT as i64),
    ("OPENR_GAIN_SET_DEFAULT", GAIN_SET_DEFAULT as i64),
    ("OPENR_GAIN_GET", GAIN_GET as i64),
    ("OPENR_GAIN_GET_DEFAULT", GAIN_GET_DEFAULT as i64),
    ("OPENR_SYNC_NEW", SYNC_NEW as i64),
    ("OPENR_SYNC_CANCEL", SYNC_CANCEL as i64),
    ("OPENR_SYNC_DIVIDE", SYNC_DIVIDE as i64),
    ("OPENR_VECTOR_COMMAND", VECTOR_COMMAND as i64),
    ("OPENR_VECTOR_SOUND", VECTOR_SOUND as i64),
    ("OPENR_VECTOR_CDT", VECTOR_CDT as i64),
    ("OPENR_VECTOR_SENSOR", VECTOR_SENSOR as i64),
    ("OPENR_VECTOR_IMAGE", VECTOR_IMAGE as i64),
    ("OPENR_VR_EFFECTOR", VR_EFFECTOR as i64),
    ("OPENR_VR_SENSOR", VR_SENSOR as i64),
    ("OPENR_VR_IMAGE", VR_IMAGE as i64),
    ("OPENR_VR_SPEAKER", VR_SPEAKER as i64),
    ("OPENR_VR_MIC", VR_MIC as i64),
    ("OPENR_VR_DONE", VR_DONE as i64),
    ("OPENR_VR_DATA", VR_DATA as i64),
    ("OPENR_VR_CONNECTED", VR_CONNECTED as i64),
];

/// The host table's functions, in header order: `fn name(args) -> result = value
/// returned when the runtime's function panicked;`. Comments: see `openr_host.h`.
#[doc(hidden)]
#[macro_export]
macro_rules! host_fns {
    ($mode:ident [$($pre:tt)*]) => { $crate::__dispatch! { $mode [$($pre)*]
        // files
        fn map_path(path: *const $crate::c_char, create: $crate::c_int, out: *mut $crate::c_char, out_len: usize) -> $crate::c_int = -1;
        fn object_exit(status: $crate::c_int) -> () = ();
        // identity
        fn self_oid() -> *mut $crate::c_void = ::core::ptr::null_mut();
        fn self_name() -> *const $crate::c_char = c"?".as_ptr();
        // messages
        fn send(dest: *mut $crate::c_void, selector: $crate::Selector, msg: *const $crate::c_void, size: usize) -> $crate::c_int = -1;
        fn call(dest: *mut $crate::c_void, selector: $crate::Selector, msg: *const $crate::c_void, size: usize, reply: *mut $crate::c_void, reply_cap: usize, got: *mut usize, timeout_ms: $crate::c_uint) -> $crate::c_int = -1;
        fn reply(msg: *const $crate::c_void, size: usize) -> $crate::c_int = 1;
        // service registry
        fn register_service(name: *const $crate::c_char, oid: *mut $crate::c_void, selector: $crate::Selector) -> $crate::c_int = -1;
        fn unregister_services() -> () = ();
        // console
        fn console_write(text: *const $crate::c_char, len: usize) -> () = ();
        // shared memory
        fn shm_alloc(size: usize, mem_id: *mut $crate::MemId) -> *mut $crate::c_void = ::core::ptr::null_mut();
        fn shm_base(mem_id: $crate::MemId, size: *mut usize) -> *mut $crate::c_void = ::core::ptr::null_mut();
        fn shm_ref(mem_id: $crate::MemId) -> () = ();
        fn shm_unref(mem_id: $crate::MemId) -> () = ();
        // time
        fn system_time(sec: *mut $crate::c_uint, usec: *mut $crate::c_uint) -> () = ();
        fn get_clock(sec_since_2000: *mut $crate::c_longlong, time_dif: *mut $crate::c_int) -> () = ();
        fn set_clock(sec_since_2000: $crate::c_longlong, time_dif: $crate::c_int) -> () = ();
        fn sleep_ns(nsec: $crate::c_ulonglong) -> () = ();
        // robot design and design data (OStatus results)
        fn robot_design() -> *const $crate::c_char = c"ERS-7".as_ptr();
        fn find_design_data(keyword: *const $crate::c_char, id: *mut $crate::DesignDataId, data: *mut *mut $crate::c_void, size: *mut usize) -> $crate::c_uint = $crate::O_FAIL;
        fn delete_design_data(id: $crate::DesignDataId) -> $crate::c_uint = $crate::O_FAIL;
        // timers (0 = no timer)
        fn set_timer(dest: *mut $crate::c_void, selector: $crate::Selector, msg: *const $crate::c_void, size: usize, after_ms: $crate::c_uint, period_ms: $crate::c_uint) -> $crate::TimerId = $crate::TimerId::NONE;
        fn cancel_timer(id: $crate::TimerId) -> $crate::c_int = -1;
        // power
        fn power_status(out: *mut $crate::openr_power_state) -> () = ();
        fn observe_power(oid: *mut $crate::c_void, selector: $crate::Selector, filter: *const $crate::openr_power_state) -> $crate::c_uint = $crate::O_FAIL;
        fn set_motor_power(on: $crate::c_int) -> () = ();
        fn shutdown() -> () = ();
        // the virtual robot (OStatus results)
        fn open_primitive(locator: *const $crate::c_char, id: *mut $crate::PrimitiveId) -> $crate::c_uint = $crate::O_FAIL;
        fn close_primitive(id: $crate::PrimitiveId) -> $crate::c_uint = $crate::O_FAIL;
        fn control_primitive(id: $crate::PrimitiveId, request: $crate::c_uint, param: *const $crate::c_void, param_size: usize, result: *mut $crate::c_void, result_size: usize) -> $crate::c_uint = $crate::O_FAIL;
        fn joint_gain(op: $crate::c_int, id: $crate::PrimitiveId, gains: *mut $crate::c_ushort) -> $crate::c_uint = $crate::O_FAIL;
        fn joint_value(id: $crate::PrimitiveId, value16: *mut $crate::c_void) -> $crate::c_uint = $crate::O_FAIL;
        fn sensor_value(id: $crate::PrimitiveId, value16: *mut $crate::c_void) -> $crate::c_uint = $crate::O_FAIL;
        fn sync_key(op: $crate::c_int, key: $crate::SyncKey, k1: *mut $crate::SyncKey, k2: *mut $crate::SyncKey) -> $crate::c_uint = $crate::O_FAIL;
        fn new_vector(kind: $crate::c_int, n: usize, data_size: usize, mem_id: *mut $crate::MemId, base: *mut *mut $crate::c_void) -> $crate::c_uint = $crate::O_FAIL;
        fn delete_vector(mem_id: $crate::MemId) -> $crate::c_uint = $crate::O_FAIL;
        fn set_cdt(mem_id: $crate::MemId) -> $crate::c_uint = $crate::O_FAIL;
        fn volume_switch(set: $crate::c_int, value: *mut $crate::c_uchar) -> $crate::c_uint = $crate::O_FAIL;
        // system objects only
        fn vr_attach(service: $crate::c_int, selector: $crate::Selector) -> $crate::c_uint = $crate::O_FAIL;
        fn vr_submit(service: $crate::c_int, subject_oid: *mut $crate::c_void, subject_selector: $crate::Selector, base: *mut $crate::c_void, size: usize, token: *mut $crate::c_ulonglong) -> $crate::c_uint = $crate::O_FAIL;
        // later additions (appended: objects built before them keep working)
        fn fatal(kind: $crate::c_uint) -> () = ();
    } };
}

/// `oFAIL` (object-model 2.10).
pub const O_FAIL: u32 = 2;

crate::host_fns!(struct [
    /// `struct openr_host_api`, the runtime's side of every OPEN-R call.
    openr_host_api, HOST_FIELDS
]);

/// The runtime's host table: `openr_sys::host_table!(crate::host_impl, on_panic)`
/// where the module holds one `unsafe fn` per entry (same name and arguments) and
/// `on_panic(function_name, payload)` reports a panic.
#[macro_export]
macro_rules! host_table {
    ($($imp:ident)::+, $on_panic:path) => {
        $crate::host_fns!(instance [openr_host_api, $crate::HOST_ABI_VERSION, [$($imp)::+], $on_panic])
    };
}
