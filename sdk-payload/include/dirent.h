/*
 * dirent.h - Sony shipped its own (8.3 names, C prototypes) at this path,
 * which shadows the system header because of -I.../OPEN_R/include.
 * The host version forwards to the system <dirent.h> (opendir, readdir,
 * closedir, rewinddir, DIR, struct dirent with d_name); path mapping of
 * "/MS/..." is done by the runtime.
 */
#include <sys/types.h>
#include_next <dirent.h>
