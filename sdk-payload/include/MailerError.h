/*
 * MailerError.h - error codes of the kernel mailer (message transport).
 */
#ifndef _MailerError_h_DEFINED
#define _MailerError_h_DEFINED

#include <Types.h>
#include <SystemError.h>

#define MailerErrorBase      (SystemErrorBase + 0)

#endif /* _MailerError_h_DEFINED */
