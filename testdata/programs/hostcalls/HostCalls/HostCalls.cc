//
// HostCalls.cc
//
// The robot's C library has no processes and no dynamic loader: fork,
// exec, system, popen, kill and friends "are not functional" there. Code
// that calls them compiles on the host, so a recompiled object could start
// host programs, signal them or load host libraries -- unless the runtime
// refuses, as the robot does. This object tries each call with a command
// that would leave a file in a host directory (HOSTCALL.CFG names it) and
// prints "HostCalls : <call> refused (ERRNO)" or "... NOT REFUSED".
//

#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <errno.h>
#include <signal.h>
#include <unistd.h>
#include <dlfcn.h>
#include <spawn.h>
#include <pthread.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <sys/ptrace.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "HostCalls.h"

extern char** environ;

static const char* errnoName(int e)
{
    switch (e) {
    case ENOSYS: return "ENOSYS";
    case EPERM:  return "EPERM";
    case ENOENT: return "ENOENT";
    case 0:      return "no errno";
    default:     return "other errno";
    }
}

static void Tried(const char* who, const char* call, bool succeeded, int err)
{
    if (succeeded) {
        OSYSPRINT(("HostCalls : %s%-24s NOT REFUSED\n", who, call));
    } else {
        OSYSPRINT(("HostCalls : %s%-24s refused (%s)\n", who, call, errnoName(err)));
    }
}

#define TRY(call, expr) \
    do { errno = 0; bool ok_ = (expr); Tried(who, call, ok_, errno); } while (0)

// A child that did start ends at once, so that a failing run stays one process.
static bool Forked(pid_t pid)
{
    if (pid == 0) raise(SIGKILL);
    if (pid < 0) return false;
    waitpid(pid, NULL, 0);
    return true;
}

static bool Popened(const char* cmd)
{
    FILE* p = popen(cmd, "r");
    if (p == NULL) return false;
    pclose(p);
    return true;
}

// posix_spawn returns its error instead of setting errno.
static bool Spawned(int rc, pid_t pid)
{
    if (rc == 0) waitpid(pid, NULL, 0);
    errno = rc;
    return rc == 0;
}

// Every call, each with a command that would write <outside>/<CALL>.
static void Routes(const char* who, const char* outside)
{
    char cmd[600];
    snprintf(cmd, sizeof cmd, "echo escaped > %s/SYSTEM", outside);
    TRY("system(cmd)", system(cmd) != -1);

    snprintf(cmd, sizeof cmd, "echo escaped > %s/POPEN", outside);
    TRY("popen(cmd)", Popened(cmd));

    TRY("fork()", Forked(fork()));

    snprintf(cmd, sizeof cmd, "echo escaped > %s/SPAWN", outside);
    char* argv[] = { (char*)"sh", (char*)"-c", cmd, NULL };
    pid_t pid;
    TRY("posix_spawn(/bin/sh)", Spawned(posix_spawn(&pid, "/bin/sh", NULL, NULL, argv, environ), pid));
    TRY("posix_spawnp(sh)", Spawned(posix_spawnp(&pid, "sh", NULL, NULL, argv, environ), pid));

    TRY("kill(parent, 0)", kill(getppid(), 0) == 0);
    TRY("ptrace(PEEKDATA, parent)", ptrace(PTRACE_PEEKDATA, getppid(), NULL, NULL) != -1 || errno == 0);

    TRY("dlopen(libc.so.6)", dlopen("libc.so.6", RTLD_NOW) != NULL);
    const char* why = dlerror();
    if (why != NULL) OSYSPRINT(("HostCalls : %sdlerror: %s\n", who, why));

    // A successful exec would replace the whole runtime: the run's missing
    // "done" line and the file in <outside> would tell.
    snprintf(cmd, sizeof cmd, "echo escaped > %s/EXEC", outside);
    TRY("execve(/bin/sh)", execve("/bin/sh", argv, environ) != -1);
    TRY("execv(/bin/sh)", execv("/bin/sh", argv) != -1);
    TRY("execvp(sh)", execvp("sh", argv) != -1);
    TRY("execl(/bin/sh)", execl("/bin/sh", "sh", "-c", cmd, (char*)NULL) != -1);
    TRY("execlp(sh)", execlp("sh", "sh", "-c", cmd, (char*)NULL) != -1);
}

HostCalls::HostCalls()
{
    outside[0] = '\0';
}

OStatus
HostCalls::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
HostCalls::DoStart(const OSystemEvent& event)
{
    if (ReadConfig()) {
        // system(NULL) asks whether a shell exists: on the robot, none.
        OSYSPRINT(("HostCalls : system(NULL) = %d\n", system(NULL)));
        Routes("", outside);
        FromOwnThread();
    }
    OSYSPRINT(("HostCalls : done\n"));

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
HostCalls::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
HostCalls::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

bool
HostCalls::ReadConfig()
{
    FILE* fp = fopen("/MS/OPEN-R/MW/CONF/HOSTCALL.CFG", "r");
    if (fp == NULL) {
        OSYSPRINT(("HostCalls : can't open /MS/OPEN-R/MW/CONF/HOSTCALL.CFG\n"));
        return false;
    }
    bool ok = fscanf(fp, "%255s", outside) == 1;
    fclose(fp);
    if (!ok) OSYSPRINT(("HostCalls : HOSTCALL.CFG needs a host directory\n"));
    return ok;
}

static void* threadBody(void* arg)
{
    Routes("own thread: ", static_cast<const char*>(arg));
    return NULL;
}

// A thread the object starts itself is the object's too.
void
HostCalls::FromOwnThread()
{
    pthread_t t;
    if (pthread_create(&t, NULL, threadBody, outside) != 0) {
        OSYSPRINT(("HostCalls : pthread_create FAILED\n"));
        return;
    }
    pthread_join(t, NULL);
}
