/*
 * OPENR/OShmPtr.h - typed smart pointer to an array of T in shared memory.
 * Header-only.
 */
#ifndef _OShmPtr_h_DEFINED
#define _OShmPtr_h_DEFINED

#include <string.h>
#include <OPENR/RCRegion.h>
#include <OPENR/OShmPtrBase.h>
#include <OPENR/SharedMemoryAllocator.h>

template <class T>
class OShmPtr : public OShmPtrBase {
public:
    OShmPtr() : OShmPtrBase() {}

    OStatus Allocate(size_t n = 1) { return OShmPtrBase::Allocate(n * sizeof(T)); }

    T*     Ptr() const { return static_cast<T*>(Base()); }
    T*     operator->() const { return Ptr(); }
    T&     operator*() const { return *Ptr(); }
    T&     operator[](size_t i) const { return Ptr()[i]; }
    size_t NumberOfElements() const { return Size() / sizeof(T); }
};

#endif /* _OShmPtr_h_DEFINED */
