/*
 * OPENR/OPENREvent.h - OSystemEvent: argument of DoInit/DoStart/DoStop/
 * DoDestroy (object-model 2.4).
 */
#ifndef _OPENREvent_h_DEFINED
#define _OPENREvent_h_DEFINED

#include <OPENR/OPENR.h>
#include <OPENR/ObjcommEvent.h>

class OSystemEvent {
public:
    OSystemEvent(OReason reason, void* param, size_t paramSize)
        : reason_(reason), param_(param), paramSize_(paramSize) {}
    ~OSystemEvent() {}

    OReason     Reason() const { return reason_; }
    const void* Param() const { return param_; }
    size_t      ParamSize() const { return paramSize_; }

private:
    OReason reason_;
    void*   param_;
    size_t  paramSize_;
};

#endif /* _OPENREvent_h_DEFINED */
