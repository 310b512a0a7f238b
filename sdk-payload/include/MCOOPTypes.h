/*
 * MCOOPTypes.h - types of the MCOOP kernel interface.
 */
#ifndef _MCOOPTypes_h_DEFINED
#define _MCOOPTypes_h_DEFINED

#include <TID.h>

typedef TID RID;   /* reply box identifier */

#endif /* _MCOOPTypes_h_DEFINED */
