//! What subjects send and observers read: how a value becomes the bytes of a region.
//! `str` is sent with a terminating NUL, as the C++ samples send `strlen + 1` bytes, so a
//! C++ observer can print it and a C++ string reads back in Rust.

/// A type that can travel in a region.
pub trait Payload {
    /// Bytes needed.
    fn size(&self) -> usize;
    /// Writes exactly `size()` bytes.
    fn write(&self, out: &mut [u8]);
    /// Views received bytes as a value.
    fn read(bytes: &[u8]) -> Option<&Self>;
}

impl Payload for [u8] {
    fn size(&self) -> usize {
        self.len()
    }
    fn write(&self, out: &mut [u8]) {
        out.copy_from_slice(self);
    }
    fn read(bytes: &[u8]) -> Option<&[u8]> {
        Some(bytes)
    }
}

impl Payload for str {
    fn size(&self) -> usize {
        self.len() + 1
    }
    fn write(&self, out: &mut [u8]) {
        out[..self.len()].copy_from_slice(self.as_bytes());
        out[self.len()] = 0;
    }
    fn read(bytes: &[u8]) -> Option<&str> {
        let n = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
        std::str::from_utf8(&bytes[..n]).ok()
    }
}

/// Plain data: `Copy`, `#[repr(C)]`, no padding, no pointers, valid for every bit pattern.
///
/// # Safety
/// Implement only for types that satisfy all of the above.
pub unsafe trait Plain: Copy + 'static {}

macro_rules! plain {
    // SAFETY: primitive integers and floats: no padding, no pointers, every bit pattern valid.
    ($($t:ty),*) => { $(unsafe impl Plain for $t {})* };
}
plain!(u8, i8, u16, i16, u32, i32, u64, i64, f32, f64);
// SAFETY: an array of plain elements has no padding between them and no other content.
unsafe impl<T: Plain, const N: usize> Plain for [T; N] {}

impl<T: Plain> Payload for T {
    fn size(&self) -> usize {
        std::mem::size_of::<T>()
    }
    fn write(&self, out: &mut [u8]) {
        // SAFETY: Plain types have no padding, so all size_of::<T>() bytes are initialised.
        let bytes = unsafe { std::slice::from_raw_parts((self as *const T).cast::<u8>(), std::mem::size_of::<T>()) };
        out.copy_from_slice(bytes);
    }
    fn read(bytes: &[u8]) -> Option<&T> {
        let ok = bytes.len() >= std::mem::size_of::<T>() && bytes.as_ptr().align_offset(std::mem::align_of::<T>()) == 0;
        // SAFETY: size and alignment checked; every bit pattern is a valid T.
        ok.then(|| unsafe { &*bytes.as_ptr().cast::<T>() })
    }
}
