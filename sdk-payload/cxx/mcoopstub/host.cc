// host.cc - locating the runtime's API table (see openr_host.h).
#include <dlfcn.h>
#include <stdio.h>
#include "openr_host.h"

// A table of another version, or smaller than the one this object was built with (a
// runtime older than the SDK root), is not used: every call would be a wrong function.
static const struct openr_host_api* checked(const struct openr_host_api* api)
{
    if (api == 0) return 0;
    if (api->abi_version != OPENR_HOST_ABI_VERSION || api->size < sizeof(struct openr_host_api)) {
        fprintf(stderr, "error: this object was built for host ABI %u (%u-byte table) but the "
                        "runtime offers ABI %u (%u bytes); rebuild it with the runtime's SDK root\n",
                (unsigned)OPENR_HOST_ABI_VERSION, (unsigned)sizeof(struct openr_host_api),
                api->abi_version, api->size);
        return 0;
    }
    return api;
}

extern "C" const struct openr_host_api* openr_host(void)
{
    // Looked up once per object; the runtime outlives every object it loads.
    static const struct openr_host_api* api =
        checked(static_cast<const struct openr_host_api*>(dlsym(RTLD_DEFAULT, "openr_runtime_api_v1")));
    return api;
}
