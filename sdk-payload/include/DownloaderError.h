/*
 * DownloaderError.h - error codes of the kernel object downloader (Load/Unload).
 */
#ifndef _DownloaderError_h_DEFINED
#define _DownloaderError_h_DEFINED

#include <SystemError.h>

#define DownloaderErrorBase  (SystemErrorBase + 64)

#endif /* _DownloaderError_h_DEFINED */
