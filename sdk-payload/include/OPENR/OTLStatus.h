/*
 * OPENR/OTLStatus.h - result codes of the OPEN-R template library (OList).
 */
#ifndef _OTLStatus_h_DEFINED
#define _OTLStatus_h_DEFINED

typedef int OTLStatus;
const OTLStatus otlSUCCESS   = 0;
const OTLStatus otlOVERFLOW  = 1;
const OTLStatus otlUNDERFLOW = 2;
const OTLStatus otlFAIL      = 3;
const OTLStatus otlNOMEMORY  = 4;

#endif /* _OTLStatus_h_DEFINED */
