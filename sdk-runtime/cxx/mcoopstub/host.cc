// host.cc - locating the runtime's API table (see openr_host.h).
#include <dlfcn.h>
#include "openr_host.h"

extern "C" const struct openr_host_api* openr_host(void)
{
    // Looked up once per object; the runtime outlives every object it loads.
    static const struct openr_host_api* api =
        static_cast<const struct openr_host_api*>(dlsym(RTLD_DEFAULT, "openr_runtime_api_v1"));
    if (api != 0 && api->abi_version != OPENR_HOST_ABI_VERSION) return 0;
    return api;
}
