/*
 * OID.h - object identifier (object-model 2.2).
 *
 * One pointer-sized member `address`; the invalid value is the address
 * 0xFFFFFFFF (OID_UNDEF). Everything is inline. Usable from C (plain struct).
 */
#ifndef _OID_h_DEFINED
#define _OID_h_DEFINED

#include <Types.h>
#include <WellknownOID.h>

#define OID_UNDEF OPENR_FIXED_PTR(0xFFFFFFFF)

#ifdef __cplusplus

struct OID {
    void* address;

    OID() : address(OID_UNDEF) {}
    OID(void* addr) : address(addr) {}

    void  SetAddress(void* addr) { address = addr; }
    void* GetAddress() const { return address; }
    bool  IsValid() const { return address != OID_UNDEF; }
    void  MakeInvalid() { address = OID_UNDEF; }
    void* GetObject() const { return address; }

    static OID Namer() { return OID(OID_REGISTRYMGR); }
    static OID RegistryManager() { return OID(OID_REGISTRYMGR); }

    bool operator==(const OID& o) const { return address == o.address; }
    bool operator!=(const OID& o) const { return address != o.address; }
    bool operator< (const OID& o) const { return address <  o.address; }
    bool operator<=(const OID& o) const { return address <= o.address; }
    bool operator> (const OID& o) const { return address >  o.address; }
    bool operator>=(const OID& o) const { return address >= o.address; }
};

#else /* C */

typedef struct OID {
    void* address;
} OID;

#endif /* __cplusplus */

#endif /* _OID_h_DEFINED */
