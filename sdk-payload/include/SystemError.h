/*
 * SystemError.h - kernel (Aperios/MCOOP) error codes, type sError.
 * Usable from C and C++. All codes are macros.
 */
#ifndef _SystemError_h_DEFINED
#define _SystemError_h_DEFINED

#define sSUCCESS         0
#define sUNDEF           1
#define sFAIL            2
#define sNOTSUPPORTED    3
#define sNOTENOUGHRES    4
#define sINVALIDARG      5
#define sNOMEMORY        6
#define sINVALIDOID      7
#define sNOTIMPLYET      9

/* First code of the subsystem-specific ranges (MCOOPError.h ...). */
#define SystemErrorBase  10

#endif /* _SystemError_h_DEFINED */
