// objcomm_internal.h - state shared by the ObjectComm translation units (not installed
// as a public header).
#ifndef OBJCOMM_INTERNAL_H
#define OBJCOMM_INTERNAL_H

#include <vector>

#include <OPENR/ObjcommMessages.h>
#include <OPENR/OObserverInfo.h>
#include <OPENR/RCRegion.h>

// End-of-unit marker in a subject's per-observer queue (object-model 2.8.3).
#define OBJCOMM_END_MARKER (reinterpret_cast<RCRegion*>(0xffffffffUL))

// A subject's record of one connected observer (object-model 2.6).
struct _OObserverInfo {
    ObserverID             id;
    size_t                 d_skip;
    size_t                 d_min;
    size_t                 d_max;
    int                    ready_flag;     // 1 asserted, 0 unknown/served, -1 deasserted
    int                    n_notify;       // complete units in the queue
    int                    n_data;         // queue entries used (regions + markers)
    size_t                 skip_counter;
    size_t                 q_size;
    std::vector<RCRegion*> queue;
    ObjcommVersion         version;
};

// Self connection (object-model 2.8.1 step 6): while an observer invokes its own
// object's Control entry directly, the subject's ControlHandler answers here instead of
// replying to a call.  One per object (each object links its own copy of the library).
extern OControlReplyMessage* objcommSelfReply;

#endif
