/*
 * openr_host.h - the private ABI between an OPEN-R object (.BIN) and the cargo-openr
 * runtime that loads it.  Not an OPEN-R header: programs never include it.
 *
 * Division of labour (as on Aperios): the runtime is the "system" - it loads objects,
 * runs one message loop per object, moves messages, keeps the service registry, the
 * shared-memory table, the console, the clock and the /MS file system.  Everything an
 * object links from OPEN_R/lib (OObject, OSubject/OObserver, RCRegion, osyslog, MCOOP
 * calls) is per-object code built on the calls below, exactly as Sony's libObjectComm
 * and libOPENR were per-object libraries on the robot.
 *
 * Finding the table: the runtime exports one symbol, `openr_runtime_api_v1`; the
 * archives find it with dlsym(RTLD_DEFAULT) the first time they need it, so it is
 * usable from static constructors that run inside dlopen().  Every call identifies the
 * calling object by its thread (one thread per object, objects are loaded on their own
 * thread), so no context pointer is passed.  When no runtime is present (a .BIN loaded
 * by another program) openr_host() returns NULL and the libc wrappers act like libc.
 *
 * Conventions: "oid" is the OID's address value (OID::GetAddress()).  Messages are
 * copied by the runtime at send time; the sender may reuse its buffer at once.
 * Functions never call back into the object synchronously except `call` on a self
 * target, which is refused (-2): objects handle self connections in-object (2.8.1).
 */
#ifndef OPENR_HOST_H
#define OPENR_HOST_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OPENR_HOST_ABI_VERSION 1

/* Fields of OPowerStatus (robot-api 9.2), in its units. */
struct openr_power_state {
    unsigned int robot_status;            /* orsb... bits */
    unsigned int battery_status;          /* obsb... bits */
    unsigned int remaining_capacity;      /* % */
    unsigned int temperature;             /* 0.1 K, 2981 = 25 degC */
    unsigned int fully_charged_capacity;  /* mAh */
    unsigned int voltage;                 /* mV */
    int current;                          /* mA, negative = discharging */
    int time_dif;                         /* hours */
    unsigned int volume;                  /* 0..3 */
};

struct openr_host_api {
    unsigned int abi_version;      /* OPENR_HOST_ABI_VERSION */
    unsigned int size;             /* sizeof(struct openr_host_api) of the runtime */

    /* ---- files (fs_wrap.cc) ---- */
    /* Maps an object-visible path (/MS/...) to a host path in `out`.  `create` != 0
     * allows the last component to be missing (it is then named in upper case).
     * Returns 0, or -1 with errno set (ENOENT outside /MS, EACCES on escape). */
    int (*map_path)(const char* path, int create, char* out, size_t out_len);
    /* exit() inside an object: stops that object only.  Does not return. */
    void (*object_exit)(int status);

    /* ---- identity ---- */
    /* The calling object's OID address (stable, e.g. 0x80000043). */
    void* (*self_oid)(void);
    /* The calling object's name from its ocf ("helloWorld"); never NULL. */
    const char* (*self_name)(void);

    /* ---- messages (MCOOP.h) ---- */
    /* Queues `msg` for `selector` of object `dest`.  0, or -1 if `dest` is unknown or
     * has stopped (sINVALIDOID / oSEND_FAIL for the caller). */
    int (*send)(void* dest, unsigned int selector, const void* msg, size_t size);
    /* Sends and waits for the reply (Reply()/Return(msg) of the receiver).  The reply is
     * copied into `reply` (at most `reply_cap` bytes, full size in *got).  `timeout_ms`
     * 0 = forever.  0 ok, -1 unknown dest, -2 dest is the caller, -3 timeout. */
    int (*call)(void* dest, unsigned int selector, const void* msg, size_t size,
                void* reply, size_t reply_cap, size_t* got, unsigned int timeout_ms);
    /* Replies to the message being processed if it was a call not yet answered.
     * Returns 0 if a reply was sent, 1 if there was nothing to answer. */
    int (*reply)(const void* msg, size_t size);

    /* ---- service registry (OObject::RegisterServiceEntry) ---- */
    /* 0 = registered, 1 = name already registered (oALREADY_EXIST). */
    int (*register_service)(const char* name, void* oid, unsigned int selector);
    /* Removes every service registered by the calling object (OObject::Destroy). */
    void (*unregister_services)(void);

    /* ---- console (osyslog, apsys) ---- */
    /* Writes `len` bytes to the console in one piece (never interleaved with other
     * objects' messages). */
    void (*console_write)(const char* text, size_t len);

    /* ---- shared memory (RCRegion, NewSharedMemoryRegion, data vectors) ---- */
    /* Allocates `size` zeroed bytes with one reference; returns the base and sets
     * *mem_id (never 0), or NULL.  Memory is shared by all objects (one address space)
     * and freed when its last reference goes. */
    void* (*shm_alloc)(size_t size, unsigned int* mem_id);
    /* Base address and size of a region, NULL if unknown. */
    void* (*shm_base)(unsigned int mem_id, size_t* size);
    void (*shm_ref)(unsigned int mem_id);
    void (*shm_unref)(unsigned int mem_id);

    /* ---- time (GetSystemTime, OPENR::GetTime) ---- */
    /* Virtual time since boot. */
    void (*system_time)(unsigned int* sec, unsigned int* usec);
    /* The robot's clock: seconds since 2000-01-01 00:00 UTC and the time difference
     * (hours, -12..12).  set_time changes the offset of the emulated clock. */
    void (*get_clock)(long long* sec_since_2000, int* time_dif);
    void (*set_clock)(long long sec_since_2000, int time_dif);
    /* Sleeps the calling object for `nsec` of virtual time (MCOOP Wait). */
    void (*sleep_ns)(unsigned long long nsec);

    /* ---- robot design and design data (OPENRAPI.h, 4.5) ---- */
    /* "ERS-7" etc. */
    const char* (*robot_design)(void);
    /* Loads the file DESIGNDB.CFG names for `keyword` in the current design's section
     * (gunzipped if needed) into shared memory.  Returns an OStatus value: 0 oSUCCESS,
     * 6 oNOT_FOUND, 4110 oDESIGNDATA_SIZE_ZERO, 5 oNO_MEMORY.  The data stays valid until
     * delete_design_data(id). */
    unsigned int (*find_design_data)(const char* keyword, unsigned int* id, void** data, size_t* size);
    /* 0 oSUCCESS or 4 oINVALID_ARG. */
    unsigned int (*delete_design_data)(unsigned int id);

    /* ---- timers (SetTimeEvent) ---- */
    /* Delivers a copy of `msg` to (dest, selector) after `after_ms` of virtual time,
     * then every `period_ms` if non-zero.  Returns an id (never 0) for cancel_timer. */
    unsigned int (*set_timer)(void* dest, unsigned int selector, const void* msg, size_t size,
                              unsigned int after_ms, unsigned int period_ms);
    int (*cancel_timer)(unsigned int id);

    /* ---- power (OPower.h, robot-api 9) ---- */
    /* Current power state of the (virtual) robot. */
    void (*power_status)(struct openr_power_state* out);
    /* Starts (filter != NULL) or stops (filter == NULL) sending OPowerStatusMessages to
     * (oid, selector) with the observation rules of robot-api 9.3: `filter` holds the
     * OPowerStatus given to ObservePowerStatus (bits to watch, "every change" /
     * "not notify" / target values).  Returns 0, or 6 (oNOT_FOUND) when stopping an
     * entry that does not observe. */
    unsigned int (*observe_power)(void* oid, unsigned int selector, const struct openr_power_state* filter);
    /* OPENR::SetMotorPower: sets or clears orsbMOTOR_POWER (observers see the edge). */
    void (*set_motor_power)(int on);
    /* OPENR::Shutdown: begins the Stop/Destroy sequence. */
    void (*shutdown)(void);

    /* ---- the virtual robot: OPENRAPI.h primitives, gains, vectors (robot-api 4) ----
     * Every call returns an OStatus value. */
    unsigned int (*open_primitive)(const char* locator, unsigned int* id);
    unsigned int (*close_primitive)(unsigned int id);
    unsigned int (*control_primitive)(unsigned int id, unsigned int request, const void* param,
                                      size_t param_size, void* result, size_t result_size);
    /* `op`: OPENR_GAIN_*; `gains` = {P, I, D, P shift, I shift, D shift}, read or written. */
    unsigned int (*joint_gain)(int op, unsigned int id, unsigned short* gains);
    /* Fills a 16-byte OJointValue / OSensorValue with the newest reading. */
    unsigned int (*joint_value)(unsigned int id, void* value16);
    unsigned int (*sensor_value)(unsigned int id, void* value16);
    /* `op`: OPENR_SYNC_NEW (key out in *k1), _CANCEL (key), _DIVIDE (key -> *k1, *k2). */
    unsigned int (*sync_key)(int op, unsigned int key, unsigned int* k1, unsigned int* k2);
    /* Allocates a data vector initialised exactly as robot-api 6 says (OPENR_VECTOR_*;
     * `n` slots, `data_size` per sound slot); one reference, freed by delete_vector. */
    unsigned int (*new_vector)(int kind, size_t n, size_t data_size, unsigned int* mem_id, void** base);
    unsigned int (*delete_vector)(unsigned int mem_id);
    unsigned int (*set_cdt)(unsigned int mem_id);
    /* set != 0: store *value; else read it (0..3). */
    unsigned int (*volume_switch)(int set, unsigned char* value);

    /* ---- system objects only (OVirtualRobotComm, OVirtualRobotAudioComm) ---- */
    /* The calling object provides `service` (OPENR_VR_*); the runtime sends it
     * struct openr_vr_event messages at (caller, selector). */
    unsigned int (*vr_attach)(int service, unsigned int selector);
    /* A vector arrived at the effector (or speaker) from the subject identified by
     * (subject_oid, subject_selector): `base`/`size` stay valid until the runtime reports
     * OPENR_VR_DONE for *token.  A malformed vector is refused (non-zero, no token). */
    unsigned int (*vr_submit)(int service, void* subject_oid, unsigned int subject_selector,
                              void* base, size_t size, unsigned long long* token);

    /* ---- later additions: appended, so objects built before them keep working ---- */
    /* OPENR::Fatal: the robot plays the warning of `kind` (an OFatal) and powers off
     * at once: the run ends without Stop or Destroy, as a failure.  Does not return. */
    void (*fatal)(unsigned int kind);
};

/* joint_gain ops */
#define OPENR_GAIN_ENABLE 0
#define OPENR_GAIN_DISABLE 1
#define OPENR_GAIN_SET 2
#define OPENR_GAIN_REGISTER_DEFAULT 3
#define OPENR_GAIN_SET_DEFAULT 4
#define OPENR_GAIN_GET 5
#define OPENR_GAIN_GET_DEFAULT 6
/* sync_key ops */
#define OPENR_SYNC_NEW 0
#define OPENR_SYNC_CANCEL 1
#define OPENR_SYNC_DIVIDE 2
/* new_vector kinds */
#define OPENR_VECTOR_COMMAND 0
#define OPENR_VECTOR_SOUND 1
#define OPENR_VECTOR_CDT 2
#define OPENR_VECTOR_SENSOR 3
#define OPENR_VECTOR_IMAGE 4
/* vr services */
#define OPENR_VR_EFFECTOR 0
#define OPENR_VR_SENSOR 1
#define OPENR_VR_IMAGE 2
#define OPENR_VR_SPEAKER 3
#define OPENR_VR_MIC 4

/* What the runtime tells a system object (sent to its vr_attach selector). */
struct openr_vr_event {
    unsigned int kind;             /* OPENR_VR_DONE, OPENR_VR_DATA or OPENR_VR_CONNECTED */
    unsigned int service;          /* OPENR_VR_* */
    unsigned long long token;      /* DONE: the vr_submit token */
    unsigned int mem_id;           /* DATA: a new vector in shared memory; the event owns
                                    * one reference, which the receiver must drop
                                    * (shm_unref) once its RCRegion holds its own */
    unsigned int size;
};
#define OPENR_VR_DONE 1
#define OPENR_VR_DATA 2
/* The service manager has just connected a subject to the object's observer (its
 * newest subject): the effector and the speaker assert ready to it now, before any
 * user Start (robot-api 8.2.3, 8.5). Sent as a call; no other field is used. */
#define OPENR_VR_CONNECTED 3

/* Returns the runtime's table, or NULL when the object runs outside cargo-openr. */
const struct openr_host_api* openr_host(void);

/* Whether `function` is one of the OPEN-R calls Sony's Remote Processing OPEN-R does not
 * offer host objects (IG4.3) and this object runs as one (start-rp-openr sets
 * OPENR_RP_HOST=1). The first call for each function says so on stderr. */
int openr_rp_unavailable(const char* function);

/*
 * Exported by every object (libmcoopstub) for the runtime, which does not know the C++
 * layouts of OPEN-R messages: it asks the object to build and read them.  Each returns
 * the size written, or 0 if `cap` is too small.
 */
size_t openr_make_reason_message(unsigned int reason, void* buf, size_t cap);
/* OConnectMessage{command, entry = (subject oid, subject selector), subName}. */
size_t openr_make_connect_message(int command, void* subject_oid, unsigned int subject_selector,
                                  const char* sub_name, void* buf, size_t cap);
/* The status of an OStatusMessage reply (oFAIL if it is too short). */
unsigned int openr_read_status_message(const void* msg, size_t size);
/* OPowerStatusMessage carrying `state`. */
size_t openr_make_power_status_message(const struct openr_power_state* state, void* buf, size_t cap);

#ifdef __cplusplus
}
#endif

#endif /* OPENR_HOST_H */
