/*
 * antModuleRef.h - opaque handle of an ANT endpoint (network-api 1.4).
 * A zero reference designates the ANT environment itself.
 */
#ifndef _antModuleRef_h_DEFINED
#define _antModuleRef_h_DEFINED

#include <antTypes.h>

class antModuleBase;

class antModuleRef {
public:
    antModuleRef() : module(0), index(0) {}
    antModuleRef(void* ptr, uint32 idx) : module((antModuleBase*)ptr), index(idx) {}

    bool operator==(const antModuleRef& r) const {
        return module == r.module && index == r.index;
    }
    bool operator!=(const antModuleRef& r) const { return !(*this == r); }

    void Print(std::ostream& os) const;   /* "[module|index]"; runtime library */

    /* host accessors */
    void*  GetModule() const { return (void*)module; }
    uint32 GetIndex() const { return index; }

private:
    antModuleBase* module;
    uint32         index;
};

std::ostream& operator<<(std::ostream& os, const antModuleRef& ref);

#endif /* _antModuleRef_h_DEFINED */
