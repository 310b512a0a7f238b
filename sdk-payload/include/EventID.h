/*
 * EventID.h - identifier of a kernel event (timer / reply event).
 */
#ifndef _EventID_h_DEFINED
#define _EventID_h_DEFINED

#include <Types.h>

#define EventID_UNDEF 0

#ifdef __cplusplus

class EventID {
public:
    EventID() : value_(EventID_UNDEF) {}
    EventID(longword v) : value_(v) {}

    bool     IsValid() const { return value_ != EventID_UNDEF; }
    void     MakeInvalid() { value_ = EventID_UNDEF; }
    void     SetValue(longword v) { value_ = v; }
    longword GetValue() const { return value_; }

    bool operator==(const EventID& e) const { return value_ == e.value_; }
    bool operator!=(const EventID& e) const { return value_ != e.value_; }

private:
    longword value_;
};

#else

typedef struct EventID {
    longword value_;
} EventID;

#endif

#endif /* _EventID_h_DEFINED */
