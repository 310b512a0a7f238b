/*
 * OPENR/OShmPtrBase.h - owning handle of one RCRegion (shares the region and
 * its reference count when copied). Header-only.
 */
#ifndef _OShmPtrBase_h_DEFINED
#define _OShmPtrBase_h_DEFINED

#include <OPENR/RCRegion.h>

class OShmPtrBase {
public:
    OShmPtrBase() : rcr_(0) {}
    OShmPtrBase(const OShmPtrBase& p) : rcr_(p.rcr_) {
        if (rcr_ != 0) rcr_->AddReference();
    }
    OShmPtrBase& operator=(const OShmPtrBase& p) {
        if (this != &p) {
            if (p.rcr_ != 0) p.rcr_->AddReference();
            Deallocate();
            rcr_ = p.rcr_;
        }
        return *this;
    }
    ~OShmPtrBase() { Deallocate(); }

    OStatus Allocate(size_t size) {
        Deallocate();
        rcr_ = new RCRegion(size);
        return rcr_ != 0 ? oSUCCESS : oNO_MEMORY;
    }
    void Deallocate() {
        if (rcr_ != 0) {
            rcr_->RemoveReference();
            rcr_ = 0;
        }
    }

    void*          Base() const { return rcr_ != 0 ? (void*)rcr_->Base() : (void*)0; }
    size_t         Size() const { return rcr_ != 0 ? rcr_->Size() : 0; }
    MemoryRegionID MemID() const { return rcr_ != 0 ? rcr_->MemID() : 0; }
    offset_t       Offset() const { return rcr_ != 0 ? rcr_->Offset() : 0; }
    RCRegion*      RCRPtr() const { return rcr_; }
    bool           IsValid() const { return rcr_ != 0; }

protected:
    RCRegion* rcr_;
};

#endif /* _OShmPtrBase_h_DEFINED */
