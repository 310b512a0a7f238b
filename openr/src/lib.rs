//! OPEN-R objects written in Rust, run by `cargo openr run` beside C++ objects.
//!
//! An object is a `cdylib` whose dynamic symbols are what the runtime loads from any
//! `.BIN` (see `sdk-payload/cxx/openr_host.h`): `ObjectEntryTable`, the message builders
//! `openr_make_reason_message`, `openr_make_connect_message`,
//! `openr_read_status_message`, and `openr_ocf_name`. The [`object!`] macro emits all of
//! them for a type implementing [`Object`]; this crate speaks the subject/observer
//! protocol (object-model 2.8) with the C++ message layouts, so Rust subjects feed C++
//! observers and the other way round.
//!
//! Ids keep the distinct types of `openr-sys` ([`MemId`], [`Selector`],
//! [`robot::PrimitiveId`]), so one cannot be passed where another is expected.
//!
//! ```no_run
//! use openr::{Context, NotifyEvent, Object, Observer, ReadyEvent, Subject};
//!
//! struct Echo { out: Subject<str>, inp: Observer<str> }
//!
//! impl Object for Echo {
//!     fn init(ctx: &mut Context) -> Self {
//!         Echo { out: ctx.subject("Echo.Out.char.S"), inp: ctx.observer("Echo.In.char.O") }
//!     }
//!     fn ready(&mut self, ctx: &mut Context, ev: ReadyEvent) {
//!         if self.out.is(&ev) && ev.is_assert() {
//!             self.out.send(ctx, "hello");
//!         }
//!     }
//!     fn notify(&mut self, ctx: &mut Context, ev: NotifyEvent) {
//!         if let Some(text) = self.inp.data(&ev, 0) {
//!             openr::osysprint!("Echo got {text}\n");
//!         }
//!         self.inp.assert_ready(ctx);
//!     }
//! }
//!
//! openr::object!(Echo, "echo");
//! ```
#![deny(unsafe_op_in_unsafe_fn)]

pub mod abi;
mod comm;
pub mod console;
mod host;
mod object;
mod payload;
pub mod robot;
mod shm;

pub use comm::{observer_selectors, subject_selectors, MAX_OBSERVERS, MAX_SUBJECTS, SEL_EVENT};
pub use console::Priority;
pub use object::{Context, NotifyEvent, Object, Observer, ReadyEvent, Status, Subject};
/// The host table's id types (one declaration, in `openr-sys`): a region's [`MemId`]
/// (`Region::mem_id`), an entry's [`Selector`] (`ReadyEvent::observer`,
/// `NotifyEvent::subject`, [`SEL_EVENT`]); `robot::PrimitiveId` is openr-sys's too.
pub use openr_sys::{MemId, Selector};
pub use payload::{Payload, Plain};
pub use shm::Region;

/// Rows of `ObjectEntryTable`: the four life-cycle entries, Control/Ready per subject
/// slot, Connect/Notify per observer slot, the event entry and the `{UNDEF, NULL}`
/// terminator.
pub const ENTRY_ROWS: usize = 4 + 2 * MAX_SUBJECTS + 2 * MAX_OBSERVERS + 2;

#[doc(hidden)]
pub unsafe extern "C" fn __entry<T: Object, const SEL: u32>(msg: *mut std::ffi::c_void) {
    // SAFETY: the runtime calls entry SEL with that entry's message.
    unsafe { object::dispatch::<T>(abi::Selector(SEL), msg) }
}

/// The entry table of object type `T` (what `object!` exports as `ObjectEntryTable`).
pub const fn entry_table<T: Object>() -> [abi::EntryRow; ENTRY_ROWS] {
    macro_rules! rows {
        ($($n:literal),*) => {
            [$(abi::EntryRow { selector: abi::Selector($n), entry: Some(__entry::<T, $n>) },)*
             abi::EntryRow { selector: abi::UNDEF, entry: None }]
        };
    }
    rows!(
        0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
        40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68
    )
}

/// A NUL-terminated copy of `s` in an array of `N` bytes (for `openr_ocf_name`).
pub const fn c_name<const N: usize>(s: &str) -> [u8; N] {
    let b = s.as_bytes();
    let mut out = [0u8; N];
    let mut i = 0;
    while i < b.len() && i + 1 < N {
        out[i] = b[i];
        i += 1;
    }
    out
}

#[doc(hidden)]
pub mod __glue {
    //! The builders the runtime asks every object for (`openr_host.h`), with the C++
    //! layouts; `object!` exports them under their C names.
    use std::ffi::{c_char, c_void, CStr};

    use crate::abi::{self, OConnectMessage, OReasonMessage, OServiceEntry, OStatusMessage};

    /// # Safety
    /// `buf` is NULL or has `cap` writable bytes.
    pub unsafe fn make_reason(reason: u32, buf: *mut c_void, cap: usize) -> usize {
        let m = OReasonMessage { msg_type: abi::OMSG_REASON, reason, param_size: 0, param: [0; 128] };
        // SAFETY: `buf` is NULL or has `cap` writable bytes (this function's contract, as `put`'s).
        unsafe { put(&m, buf, cap) }
    }

    /// # Safety
    /// As `make_reason`; `name` is NULL or a C string.
    pub unsafe fn make_connect(command: i32, oid: *mut c_void, selector: abi::Selector, name: *const c_char, buf: *mut c_void, cap: usize) -> usize {
        let mut m = OConnectMessage { msg_type: abi::OMSG_CONNECT, command: command as u32, entry: OServiceEntry { oid, selector }, sub_name: [0; 128] };
        if !name.is_null() {
            // SAFETY: a C string per the contract.
            abi::set_name(&mut m.sub_name, unsafe { CStr::from_ptr(name) }.to_bytes());
        }
        // SAFETY: `buf` is NULL or has `cap` writable bytes (this function's contract, as `put`'s).
        unsafe { put(&m, buf, cap) }
    }

    /// # Safety
    /// `msg` is NULL or has `size` readable bytes.
    pub unsafe fn read_status(msg: *const c_void, size: usize) -> u32 {
        if msg.is_null() || size < std::mem::size_of::<OStatusMessage>() {
            return abi::O_FAIL;
        }
        // SAFETY: size checked.
        unsafe { abi::read::<OStatusMessage>(msg) }.status
    }

    unsafe fn put<T: Copy>(m: &T, buf: *mut c_void, cap: usize) -> usize {
        let n = std::mem::size_of::<T>();
        if buf.is_null() || cap < n {
            return 0;
        }
        // SAFETY: `buf` has room for n bytes.
        unsafe { std::ptr::copy_nonoverlapping((m as *const T).cast::<u8>(), buf.cast::<u8>(), n) };
        n
    }
}

/// Makes the crate an OPEN-R object: `openr::object!(MyObject, "myObject");` exports
/// `ObjectEntryTable` for `MyObject: Object`, the runtime glue and the object's name
/// (as mkbin records an ocf name).
#[macro_export]
macro_rules! object {
    ($ty:ty, $name:literal) => {
        #[no_mangle]
        #[allow(non_upper_case_globals)]
        pub static ObjectEntryTable: [$crate::abi::EntryRow; $crate::ENTRY_ROWS] = $crate::entry_table::<$ty>();

        #[no_mangle]
        #[allow(non_upper_case_globals)]
        pub static openr_ocf_name: [u8; $name.len() + 1] = $crate::c_name::<{ $name.len() + 1 }>($name);

        /// # Safety
        /// Called by the runtime with a buffer of `cap` bytes.
        #[no_mangle]
        pub unsafe extern "C" fn openr_make_reason_message(reason: u32, buf: *mut ::std::ffi::c_void, cap: usize) -> usize {
            unsafe { $crate::__glue::make_reason(reason, buf, cap) }
        }

        /// # Safety
        /// Called by the runtime with a C string and a buffer of `cap` bytes.
        #[no_mangle]
        pub unsafe extern "C" fn openr_make_connect_message(
            command: i32,
            oid: *mut ::std::ffi::c_void,
            selector: $crate::abi::Selector,
            name: *const ::std::ffi::c_char,
            buf: *mut ::std::ffi::c_void,
            cap: usize,
        ) -> usize {
            unsafe { $crate::__glue::make_connect(command, oid, selector, name, buf, cap) }
        }

        /// # Safety
        /// Called by the runtime with a reply of `size` bytes.
        #[no_mangle]
        pub unsafe extern "C" fn openr_read_status_message(msg: *const ::std::ffi::c_void, size: usize) -> u32 {
            unsafe { $crate::__glue::read_status(msg, size) }
        }
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::comm::{entry_of, Entry};

    #[test]
    fn every_selector_maps_back_to_its_slot() {
        assert_eq!(entry_of(abi::Selector(0)), Entry::Init);
        assert_eq!(entry_of(abi::Selector(3)), Entry::Destroy);
        for k in 0..MAX_SUBJECTS {
            let (c, r) = subject_selectors(k);
            assert_eq!((entry_of(c), entry_of(r)), (Entry::Control(k), Entry::Ready(k)));
        }
        for k in 0..MAX_OBSERVERS {
            let (c, n) = observer_selectors(k);
            assert_eq!((entry_of(c), entry_of(n)), (Entry::Connect(k), Entry::Notify(k)));
        }
        assert_eq!(observer_selectors(MAX_OBSERVERS - 1).1 .0 as usize, ENTRY_ROWS - 3);
        assert_eq!((entry_of(SEL_EVENT), SEL_EVENT.0 as usize), (Entry::Event, ENTRY_ROWS - 2));
    }

    #[test]
    fn strings_travel_with_a_nul_like_the_cxx_samples() {
        let mut buf = vec![0xffu8; "hi".size()];
        "hi".write(&mut buf);
        assert_eq!(buf, b"hi\0");
        assert_eq!(<str as Payload>::read(b"hello\0junk"), Some("hello"));
        assert_eq!(<u32 as Payload>::read(&7u32.to_ne_bytes()), Some(&7));
    }

    #[test]
    fn glue_builds_and_reads_the_cxx_layouts() {
        let mut buf = [0u8; 256];
        let name = c"A.B.c.S";
        // SAFETY: `name` is a C string; `buf` has `buf.len()` writable bytes.
        let n = unsafe { __glue::make_connect(0, 0x8000_0040usize as *mut _, abi::Selector(9), name.as_ptr(), buf.as_mut_ptr().cast(), buf.len()) };
        assert_eq!(n, 152);
        assert_eq!(&buf[0..4], &abi::OMSG_CONNECT.to_ne_bytes());
        assert_eq!(&buf[8..16], &0x8000_0040usize.to_ne_bytes());
        assert_eq!(&buf[16..20], &9u32.to_ne_bytes());
        assert_eq!(&buf[24..32], b"A.B.c.S\0");
        // SAFETY: `buf` has at least the 10 writable bytes claimed.
        assert_eq!(unsafe { __glue::make_reason(0, buf.as_mut_ptr().cast(), 10) }, 0, "too small");
        let status = [2u32.to_ne_bytes(), 6u32.to_ne_bytes()].concat();
        // SAFETY: `status` has the 8 readable bytes claimed.
        assert_eq!(unsafe { __glue::read_status(status.as_ptr().cast(), 8) }, 6);
        // SAFETY: `status` has the 4 readable bytes claimed.
        assert_eq!(unsafe { __glue::read_status(status.as_ptr().cast(), 4) }, abi::O_FAIL);
    }
}
