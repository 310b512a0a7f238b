//! Shared memory regions (object-model 4.1): the host's reference-counted blocks that
//! `RCRegion` wraps on the C++ side. All objects share one address space, so a region's
//! base is valid in every object while someone holds a reference.
use std::collections::HashMap;
use std::sync::Mutex;

use crate::abi::MemId;
use crate::host;

/// References this process's Rust code holds per block: live `Region` handles plus the
/// subject references travelling with notifications (given back by READY). The host's
/// count is not visible, so `CommandVector::in_use` asks this one.
static RUST_REFS: Mutex<Option<HashMap<MemId, usize>>> = Mutex::new(None);

fn count(mem_id: MemId, up: bool) {
    let mut g = RUST_REFS.lock().unwrap_or_else(|e| e.into_inner());
    let m = g.get_or_insert_with(HashMap::new);
    if up {
        *m.entry(mem_id).or_insert(0) += 1;
    } else if let Some(n) = m.get_mut(&mem_id) {
        *n -= 1;
        if *n == 0 {
            m.remove(&mem_id);
        }
    }
}

/// Rust-side references on `mem_id` (see `RUST_REFS`).
pub(crate) fn rust_refs(mem_id: MemId) -> usize {
    let g = RUST_REFS.lock().unwrap_or_else(|e| e.into_inner());
    g.as_ref().and_then(|m| m.get(&mem_id).copied()).unwrap_or(0)
}

/// A subject's reference came back in a READY message (the host reference is dropped
/// by the caller).
pub(crate) fn token_returned(mem_id: MemId) {
    count(mem_id, false);
}

/// One host reference on a shared-memory block (or a window of it): `shm_ref` when
/// cloned, `shm_unref` when dropped.
#[derive(Debug)]
pub struct Region {
    mem_id: MemId,
    offset: usize,
    base: *mut u8,
    size: usize,
}

impl Region {
    /// Allocates `size` zeroed bytes (`shm_alloc`); `None` without a runtime or memory.
    pub fn alloc(size: usize) -> Option<Region> {
        let (mem_id, base) = host::shm_alloc(size)?;
        count(mem_id, true);
        Some(Region { mem_id, offset: 0, base, size })
    }

    /// Takes a new reference on `size` bytes at `offset` of an existing block
    /// (`shm_ref`); `None` if the block is unknown or the window does not fit.
    pub fn attach(mem_id: MemId, offset: usize, size: usize) -> Option<Region> {
        let (block, total) = host::shm_base(mem_id)?;
        if offset.checked_add(size)? > total {
            return None;
        }
        host::shm_ref(mem_id);
        count(mem_id, true);
        // SAFETY: offset + size <= total, inside the block.
        Some(Region { mem_id, offset, base: unsafe { block.add(offset) }, size })
    }

    /// Adopts the one host reference the caller holds on a whole block (e.g. from
    /// `new_vector`).
    pub(crate) fn adopt(mem_id: MemId, base: *mut u8, size: usize) -> Region {
        count(mem_id, true);
        Region { mem_id, offset: 0, base, size }
    }

    /// The host's id of the block (`MemoryRegionID`).
    pub fn mem_id(&self) -> MemId {
        self.mem_id
    }

    /// Offset of this window in its block.
    pub fn offset(&self) -> usize {
        self.offset
    }

    pub fn len(&self) -> usize {
        self.size
    }

    pub fn is_empty(&self) -> bool {
        self.size == 0
    }

    /// The bytes. Other objects holding the region may write them concurrently if their
    /// program says so; the subject/observer protocol hands data over without that.
    pub fn bytes(&self) -> &[u8] {
        if self.size == 0 {
            return &[];
        }
        // SAFETY: our reference keeps base..base+size mapped.
        unsafe { std::slice::from_raw_parts(self.base, self.size) }
    }

    /// The bytes, for filling a region before it is handed to a subject.
    pub fn bytes_mut(&mut self) -> &mut [u8] {
        if self.size == 0 {
            return &mut [];
        }
        // SAFETY: as in `bytes`; `&mut self` keeps this handle's views unique.
        unsafe { std::slice::from_raw_parts_mut(self.base, self.size) }
    }
}

impl Clone for Region {
    fn clone(&self) -> Region {
        host::shm_ref(self.mem_id);
        count(self.mem_id, true);
        Region { ..*self }
    }
}

impl Drop for Region {
    fn drop(&mut self) {
        count(self.mem_id, false);
        host::shm_unref(self.mem_id);
    }
}
