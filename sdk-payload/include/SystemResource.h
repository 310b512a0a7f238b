/*
 * SystemResource.h - kernel resource selectors for Set/GetResourceValue().
 */
#ifndef _SystemResource_h_DEFINED
#define _SystemResource_h_DEFINED

#include <Types.h>

typedef longword sResource;

#define rUNDEF             ((sResource)0)
#define rMAXSWITCHNUMOFS   ((sResource)1)   /* max. context switches per scheduling slot */

#endif /* _SystemResource_h_DEFINED */
