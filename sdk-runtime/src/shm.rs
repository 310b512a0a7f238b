//! Shared memory regions (RCRegion, data vectors, design data). One address space, so a
//! region is just zeroed heap memory; what matters is its lifetime: it lives while any
//! object holds a reference (robot-api 7), counted here across objects.
// Fx: a region is looked up on every message that carries one (SipHash showed in profiles).
use rustc_hash::FxHashMap as HashMap;
use std::sync::Mutex;

use openr_sys::MemId;

struct Region {
    base: *mut u8,
    size: usize,
    refs: usize,
}

// SAFETY: `base` is a calloc'd block owned by the table (freed only by `unref`, under its
// lock); it is only handed out, never dereferenced here, so it may move between threads.
unsafe impl Send for Region {}

pub struct ShmTable {
    inner: Mutex<(u32, HashMap<MemId, Region>)>,
}

impl ShmTable {
    pub fn new() -> ShmTable {
        ShmTable { inner: Mutex::new((0, HashMap::default())) }
    }

    /// Allocates `size` zeroed bytes (16-byte aligned) with one reference.
    pub fn alloc(&self, size: usize) -> Option<(MemId, *mut u8)> {
        // SAFETY: calloc with a non-zero size; null is checked below.
        let base = unsafe { libc::calloc(1, size.max(1)) }.cast::<u8>();
        if base.is_null() {
            return None;
        }
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        g.0 = g.0.wrapping_add(1).max(1);
        let id = MemId(g.0);
        g.1.insert(id, Region { base, size, refs: 1 });
        Some((id, base))
    }

    pub fn base(&self, id: MemId) -> Option<(*mut u8, usize)> {
        let g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        g.1.get(&id).map(|r| (r.base, r.size))
    }

    pub fn add_ref(&self, id: MemId) {
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(r) = g.1.get_mut(&id) {
            r.refs += 1;
        }
    }

    /// Drops one reference; frees the memory with the last. Returns whether it was freed.
    pub fn unref(&self, id: MemId) -> bool {
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        let Some(r) = g.1.get_mut(&id) else { return false };
        r.refs -= 1;
        if r.refs > 0 {
            return false;
        }
        let r = g.1.remove(&id).expect("present");
        // SAFETY: `r` was the last reference to its calloc'd block, just removed from the table: freed once.
        unsafe { libc::free(r.base.cast()) };
        true
    }

    /// Number of live regions (for leak checks in tests and benchmarks).
    pub fn live(&self) -> usize {
        self.inner.lock().unwrap_or_else(|p| p.into_inner()).1.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lives_until_the_last_reference() {
        let t = ShmTable::new();
        let (id, base) = t.alloc(64).unwrap();
        assert!(!base.is_null());
        assert_eq!(t.base(id).unwrap().1, 64);
        t.add_ref(id);
        assert!(!t.unref(id));
        assert!(t.base(id).is_some());
        assert!(t.unref(id));
        assert!(t.base(id).is_none());
        assert_eq!(t.live(), 0);
    }
}
