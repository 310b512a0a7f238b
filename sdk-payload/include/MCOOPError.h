/*
 * MCOOPError.h - error codes returned by the MCOOP kernel calls of MCOOP.h
 * in addition to the generic codes of SystemError.h.
 */
#ifndef _MCOOPError_h_DEFINED
#define _MCOOPError_h_DEFINED

#include <Types.h>
#include <SystemError.h>
#include <MailerError.h>
#include <DownloaderError.h>

#define sRBOXALREADYUSED     (SystemErrorBase + 0)
#define sTIMEOUT             (SystemErrorBase + 18)

#endif /* _MCOOPError_h_DEFINED */
