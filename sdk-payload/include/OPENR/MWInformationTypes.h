/*
 * OPENR/MWInformationTypes.h - identifiers of the level-1 (middleware
 * information) API.
 */
#ifndef _MWInformationTypes_h_DEFINED
#define _MWInformationTypes_h_DEFINED

#include <Types.h>

typedef longword MWIID;
const MWIID mwiidINVALID = 0xffffffff;

#endif /* _MWInformationTypes_h_DEFINED */
