/*
 * TID.h - transaction identifier: a mailer object plus a 32-bit value.
 * (Used as reply box RID and as the continuation target of ANT messages.)
 */
#ifndef _TID_h_DEFINED
#define _TID_h_DEFINED

#include <OID.h>
#include <Types.h>

#define TID_UNDEF 0

#ifdef __cplusplus

struct TID {
    OID      mailer;
    longword value;

    TID() : mailer(), value(TID_UNDEF) {}
    TID(const OID& m, longword v) : mailer(m), value(v) {}

    const OID& GetMailer() const { return mailer; }
    longword   GetValue() const { return value; }
    void       SetMailer(const OID& m) { mailer = m; }
    void       SetValue(longword v) { value = v; }
    bool       IsValid() const { return mailer.IsValid() && value != TID_UNDEF; }
    void       MakeInvalid() { mailer.MakeInvalid(); value = TID_UNDEF; }

    bool operator==(const TID& t) const { return mailer == t.mailer && value == t.value; }
    bool operator!=(const TID& t) const { return !(*this == t); }
};

#else

typedef struct TID {
    OID      mailer;
    longword value;
} TID;

#endif

#endif /* _TID_h_DEFINED */
