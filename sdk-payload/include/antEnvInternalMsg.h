/*
 * antEnvInternalMsg.h - messages handled by the ANT environment itself
 * (network-api 2): create endpoints and shared buffers, registry access.
 * The `error` fields are not initialised by the constructors.
 */
#ifndef _antEnvInternalMsg_h_DEFINED
#define _antEnvInternalMsg_h_DEFINED

#include <antSharedBuffer.h>
#include <antEnvBaseMsg.h>
#include <string.h>

/* ---- environment operations (selector Entry_antEnv_External, module 0) --- */

enum {
    antEnv_CreateEndpoint      = -1,
    antEnv_CreateSharedBuffer  = -2,
    antEnv_DestroySharedBuffer = -3
};

struct antEnvCreateEndpointMsg : public antEnvMsg {
    antError     error;
    int32        protocol;    /* EndpointType_... */
    int32        poolSize;
    antModuleRef moduleRef;   /* out: the new endpoint */

    antEnvCreateEndpointMsg()
        : antEnvMsg(antEnv_CreateEndpoint), protocol(0), poolSize(0), moduleRef() {}
    antEnvCreateEndpointMsg(int32 proto, int32 pool = 0)
        : antEnvMsg(antEnv_CreateEndpoint), protocol(proto), poolSize(pool), moduleRef() {}

    antError Reply(antError e) { error = e; return antEnvMsg::Reply(); }
};

struct antEnvCreateSharedBufferMsg : public antEnvMsg {
    antError        error;
    uint32          size;
    antSharedBuffer buffer;   /* out */

    antEnvCreateSharedBufferMsg() : antEnvMsg(antEnv_CreateSharedBuffer), size(0), buffer() {}
    antEnvCreateSharedBufferMsg(uint32 sz)
        : antEnvMsg(antEnv_CreateSharedBuffer), size(sz), buffer() {}

    antError Reply(antError e) { error = e; return antEnvMsg::Reply(); }
};

struct antEnvDestroySharedBufferMsg : public antEnvMsg {
    antError        error;
    antSharedBuffer buffer;

    antEnvDestroySharedBufferMsg() : antEnvMsg(antEnv_DestroySharedBuffer), buffer() {}
    antEnvDestroySharedBufferMsg(const antSharedBuffer& b)
        : antEnvMsg(antEnv_DestroySharedBuffer), buffer(b) {}

    antError Reply(antError e) { error = e; return antEnvMsg::Reply(); }
};

/* ---- registry / initialisation (selector Entry_antEnv_Initialize) -------- */

#define ANTENV_KEY_LENGTH_MAX   32
#define ANTENV_VALUE_LENGTH_MAX 32

enum {
    antEnv_InitParam_Int32  = -1,
    antEnv_InitParam_String = -2
};

enum {
    antEnvInit_SetParam = -1,
    antEnvInit_Start    = -2,
    antEnvInit_GetParam = -3
};

union antEnvInitParamValue {
    char  str[ANTENV_VALUE_LENGTH_MAX];
    int32 i32;
};

inline void antEnvInitCopyValue(int32 type, antEnvInitParamValue& dst,
                                const antEnvInitParamValue& src)
{
    if (type == antEnv_InitParam_Int32) dst.i32 = src.i32;
    else memcpy(dst.str, src.str, ANTENV_VALUE_LENGTH_MAX);
}

struct antEnvInitSetParamMsg : public antEnvMsg {
    int32                paramType;
    char                 key[ANTENV_KEY_LENGTH_MAX];
    antEnvInitParamValue value;
    antError             error;

    antEnvInitSetParamMsg(const char* k, int32 v)
        : antEnvMsg(antEnvInit_SetParam, Entry_antEnv_Initialize),
          paramType(antEnv_InitParam_Int32) {
        strncpy(key, k, ANTENV_KEY_LENGTH_MAX);
        value.i32 = v;
    }
    antEnvInitSetParamMsg(const char* k, const char* v)
        : antEnvMsg(antEnvInit_SetParam, Entry_antEnv_Initialize),
          paramType(antEnv_InitParam_String) {
        strncpy(key, k, ANTENV_KEY_LENGTH_MAX);
        strncpy(value.str, v, ANTENV_VALUE_LENGTH_MAX);
    }

    antEnvInitSetParamMsg& operator=(const antEnvInitSetParamMsg& m) {
        antEnvMsg::operator=(m);
        paramType = m.paramType;
        memcpy(key, m.key, ANTENV_KEY_LENGTH_MAX);
        antEnvInitCopyValue(paramType, value, m.value);
        error = m.error;
        return *this;
    }

    antError Reply(antError e) { error = e; return antEnvMsg::Reply(); }
};

struct antEnvInitStartMsg : public antEnvMsg {
    antError error;

    antEnvInitStartMsg() : antEnvMsg(antEnvInit_Start, Entry_antEnv_Initialize) {}

    antError Reply(antError e) { error = e; return antEnvMsg::Reply(); }
};

struct antEnvInitGetParamMsg : public antEnvMsg {
    int32                paramType;   /* set by the reply */
    char                 key[ANTENV_KEY_LENGTH_MAX];
    antEnvInitParamValue value;       /* out */
    antError             error;

    antEnvInitGetParamMsg(const char* k)
        : antEnvMsg(antEnvInit_GetParam, Entry_antEnv_Initialize) {
        strncpy(key, k, ANTENV_KEY_LENGTH_MAX);
    }

    antEnvInitGetParamMsg& operator=(const antEnvInitGetParamMsg& m) {
        antEnvMsg::operator=(m);
        paramType = m.paramType;
        memcpy(key, m.key, ANTENV_KEY_LENGTH_MAX);
        antEnvInitCopyValue(paramType, value, m.value);
        error = m.error;
        return *this;
    }

    antError Reply(antError e) { error = e; return antEnvMsg::Reply(); }
};

#endif /* _antEnvInternalMsg_h_DEFINED */
