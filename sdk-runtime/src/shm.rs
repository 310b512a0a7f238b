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
    /// From [`ShmTable::alloc_dirty`]: kept for another such region when freed.
    recycle: bool,
}

// SAFETY: `base` is a calloc'd block owned by the table (freed only by `unref`, under its
// lock); it is only handed out, never dereferenced here, so it may move between threads.
unsafe impl Send for Region {}

/// Freed [`ShmTable::alloc_dirty`] blocks kept for the next ones (a camera publishes
/// one image-sized vector per image; a few are in flight at once).
const SPARE: usize = 4;

struct Inner {
    last_id: u32,
    regions: HashMap<MemId, Region>,
    /// Blocks (size, base) of freed recycled regions, initialised (their last bytes).
    spare: Vec<(usize, *mut u8)>,
}

pub struct ShmTable {
    inner: Mutex<Inner>,
}

// SAFETY: the spare blocks are owned by the table alone (no region refers to them) and
// are only handed out under its lock, so the table may be shared between threads.
unsafe impl Send for Inner {}

impl Inner {
    /// Registers `base` as a new region with one reference.
    fn insert(&mut self, base: *mut u8, size: usize, recycle: bool) -> MemId {
        self.last_id = self.last_id.wrapping_add(1).max(1);
        let id = MemId(self.last_id);
        self.regions.insert(id, Region { base, size, refs: 1, recycle });
        id
    }
}

impl ShmTable {
    pub fn new() -> ShmTable {
        ShmTable { inner: Mutex::new(Inner { last_id: 0, regions: HashMap::default(), spare: Vec::new() }) }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Allocates `size` zeroed bytes (16-byte aligned) with one reference.
    pub fn alloc(&self, size: usize) -> Option<(MemId, *mut u8)> {
        // SAFETY: calloc with a non-zero size; null is checked below.
        let base = unsafe { libc::calloc(1, size.max(1)) }.cast::<u8>();
        if base.is_null() {
            return None;
        }
        Some((self.insert(base, size, false), base))
    }

    /// Like [`ShmTable::alloc`], but the bytes are whatever an earlier region of this
    /// size held (initialised, not zeroed): for a caller that writes all `size` of them.
    /// Spares the zeroing and the allocation of a large block per camera image.
    pub fn alloc_dirty(&self, size: usize) -> Option<(MemId, *mut u8)> {
        let mut g = self.lock();
        if let Some(i) = g.spare.iter().position(|&(n, _)| n == size) {
            // A spare block: one lock for taking it and registering the region.
            let base = g.spare.swap_remove(i).1;
            return Some((g.insert(base, size, true), base));
        }
        drop(g);
        // SAFETY: calloc with a non-zero size; null is checked below.
        let base = unsafe { libc::calloc(1, size.max(1)) }.cast::<u8>();
        if base.is_null() {
            return None;
        }
        Some((self.insert(base, size, true), base))
    }

    fn insert(&self, base: *mut u8, size: usize, recycle: bool) -> MemId {
        self.lock().insert(base, size, recycle)
    }

    pub fn base(&self, id: MemId) -> Option<(*mut u8, usize)> {
        self.lock().regions.get(&id).map(|r| (r.base, r.size))
    }

    pub fn add_ref(&self, id: MemId) {
        if let Some(r) = self.lock().regions.get_mut(&id) {
            r.refs += 1;
        }
    }

    /// Drops one reference; frees the memory with the last (or keeps a recycled
    /// region's block as a spare). Returns whether it was freed.
    pub fn unref(&self, id: MemId) -> bool {
        let mut g = self.lock();
        let Some(r) = g.regions.get_mut(&id) else { return false };
        r.refs -= 1;
        if r.refs > 0 {
            return false;
        }
        let r = g.regions.remove(&id).expect("present");
        if r.recycle && g.spare.len() < SPARE {
            g.spare.push((r.size, r.base));
            return true;
        }
        drop(g);
        // SAFETY: `r` was the last reference to its calloc'd block, just removed from the table: freed once.
        unsafe { libc::free(r.base.cast()) };
        true
    }

    /// Number of live regions (for leak checks in tests and benchmarks).
    pub fn live(&self) -> usize {
        self.lock().regions.len()
    }
}

impl Drop for ShmTable {
    fn drop(&mut self) {
        for (_, base) in self.lock().spare.drain(..) {
            // SAFETY: a spare block belongs to no region and is in the list once: freed once.
            unsafe { libc::free(base.cast()) };
        }
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

    #[test]
    fn a_dirty_region_reuses_a_freed_one_of_its_size() {
        let t = ShmTable::new();
        let (a, base) = t.alloc_dirty(4096).unwrap();
        // SAFETY: a live region of 4096 bytes.
        unsafe { base.write(7) };
        assert!(t.unref(a));
        assert_eq!(t.live(), 0);
        let (b, other) = t.alloc_dirty(100).unwrap();
        assert_ne!(other, base, "another size gets another block");
        let (c, again) = t.alloc_dirty(4096).unwrap();
        assert_eq!(again, base);
        // SAFETY: a live region of 4096 bytes: the old bytes are still there.
        assert_eq!(unsafe { again.read() }, 7);
        assert_ne!(c, a, "a new region ID");
        assert!(t.unref(b) && t.unref(c));
        // zeroed regions are never recycled
        let (d, z) = t.alloc(4096).unwrap();
        // SAFETY: a live, zeroed region of 4096 bytes.
        assert_eq!(unsafe { z.read() }, 0);
        t.unref(d);
    }
}
