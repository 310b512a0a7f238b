/*
 * OPENR/StackAllocator.h - pool allocator handing out objects of type T,
 * N per chunk (RCRegion uses a pool of 20). Header-only; chunks are never
 * returned to the system.
 */
#ifndef _StackAllocator_h_DEFINED
#define _StackAllocator_h_DEFINED

#include <new>
#include <OPENR/ArrayStack.h>

template <class T, int N>
class StackAllocator {
public:
    StackAllocator() : chunk_(0), used_(N), free_() {}

    void* Allocate() {
        void* p;
        if (free_.Pop(&p)) return p;
        if (used_ >= N) {
            chunk_ = static_cast<char*>(::operator new(sizeof(T) * N, std::nothrow));
            if (chunk_ == 0) return 0;
            used_ = 0;
        }
        return chunk_ + sizeof(T) * (used_++);
    }

    void Free(void* p) {
        if (p == 0) return;
        if (!free_.Push(p)) {
            /* free list full: leak the slot (pool memory is never released) */
        }
    }

private:
    char*                  chunk_;
    int                    used_;
    ArrayStack<void*, N>   free_;
};

#endif /* _StackAllocator_h_DEFINED */
