/*
 * WellknownOID.h - object identifiers with fixed addresses.
 */
#ifndef _WellknownOID_h_DEFINED
#define _WellknownOID_h_DEFINED

#include <FixedPtr.h>

#define OID_ALL          OPENR_FIXED_PTR(0x00000000)
#define OID_REGISTRYMGR  OPENR_FIXED_PTR(0x80000000)

#endif /* _WellknownOID_h_DEFINED */
