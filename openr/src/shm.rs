//! Shared memory regions (object-model 4.1): the host's reference-counted blocks that
//! `RCRegion` wraps on the C++ side. All objects share one address space, so a region's
//! base is valid in every object while someone holds a reference.
use crate::host;

/// One host reference on a shared-memory block (or a window of it): `shm_ref` when
/// cloned, `shm_unref` when dropped.
#[derive(Debug)]
pub struct Region {
    mem_id: u32,
    offset: usize,
    base: *mut u8,
    size: usize,
}

impl Region {
    /// Allocates `size` zeroed bytes (`shm_alloc`); `None` without a runtime or memory.
    pub fn alloc(size: usize) -> Option<Region> {
        let (mem_id, base) = host::shm_alloc(size)?;
        Some(Region { mem_id, offset: 0, base, size })
    }

    /// Takes a new reference on `size` bytes at `offset` of an existing block
    /// (`shm_ref`); `None` if the block is unknown or the window does not fit.
    pub fn attach(mem_id: u32, offset: usize, size: usize) -> Option<Region> {
        let (block, total) = host::shm_base(mem_id)?;
        if offset.checked_add(size)? > total {
            return None;
        }
        host::shm_ref(mem_id);
        // SAFETY: offset + size <= total, inside the block.
        Some(Region { mem_id, offset, base: unsafe { block.add(offset) }, size })
    }

    /// The host's id of the block (`MemoryRegionID`).
    pub fn mem_id(&self) -> u32 {
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
        Region { ..*self }
    }
}

impl Drop for Region {
    fn drop(&mut self) {
        host::shm_unref(self.mem_id);
    }
}
