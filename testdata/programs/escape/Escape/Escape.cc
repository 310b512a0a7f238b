//
// Escape.cc
//
// An object may touch the Memory Stick and nothing else. This one tries
// every way out it can think of -- links inside the stick leading out,
// ".." after the stick's host path, host paths given to calls the link
// does not wrap, a thread of its own -- and prints for each route whether
// it was refused, and with which errno. On the robot every one of them
// fails; on the host they must fail too.
//
// ESCAPE.CFG names the stick's host directory (line 1) and a host
// directory outside it (line 2): the test writes it, and the links
// OUTDIR, DANGLING, LINKFILE.TXT and INSIDE at the stick's root.
//

#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <limits.h>
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>
#include <utime.h>
#include <dirent.h>
#include <pthread.h>
#include <sys/types.h>
#include <sys/stat.h>
#include <fstream>
#include <string>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Escape.h"

static const char* errnoName(int e)
{
    switch (e) {
    case ENOENT:       return "ENOENT";
    case EACCES:       return "EACCES";
    case EPERM:        return "EPERM";
    case ENOSYS:       return "ENOSYS";
    case EROFS:        return "EROFS";
    case ENAMETOOLONG: return "ENAMETOOLONG";
    case 0:            return "no errno";
    default:           return "other errno";
    }
}

// Prints one route: "refused (ERRNO)" or "NOT REFUSED".
static void Tried(const char* route, bool succeeded, int err)
{
    if (succeeded) {
        OSYSPRINT(("Escape : %-40s NOT REFUSED\n", route));
    } else {
        OSYSPRINT(("Escape : %-40s refused (%s)\n", route, errnoName(err)));
    }
}

#define TRY(route, call) \
    do { errno = 0; bool ok_ = (call); Tried(route, ok_, errno); } while (0)

static bool Got(FILE* fp)  { if (fp == NULL) return false; fclose(fp); return true; }
static bool Got(int fd)    { if (fd < 0) return false; close(fd); return true; }
static bool Got(DIR* dir)  { if (dir == NULL) return false; closedir(dir); return true; }
static bool Zero(int rc)   { return rc == 0; }
static bool Stats(const char* path) { struct stat st; return stat(path, &st) == 0; }

static bool GotStream(const char* path)
{
    std::ifstream in(path);
    std::string line;
    return in.is_open() && std::getline(in, line);
}

static bool MadeStream(const char* path)
{
    std::ofstream out(path);
    out << "escaped\n";
    return out.is_open() && out.good();
}

Escape::Escape()
{
    stick[0] = outside[0] = '\0';
}

OStatus
Escape::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Escape::DoStart(const OSystemEvent& event)
{
    if (ReadConfig()) {
        ThroughLinks();
        ThroughHostPaths();
        FromOwnThread();
        StillWorks();
    }
    OSYSPRINT(("Escape : done\n"));

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Escape::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Escape::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

bool
Escape::ReadConfig()
{
    FILE* fp = fopen("/MS/OPEN-R/MW/CONF/ESCAPE.CFG", "r");
    if (fp == NULL) {
        OSYSPRINT(("Escape : can't open /MS/OPEN-R/MW/CONF/ESCAPE.CFG\n"));
        return false;
    }
    bool ok = fscanf(fp, "%255s %255s", stick, outside) == 2;
    fclose(fp);
    if (!ok) OSYSPRINT(("Escape : ESCAPE.CFG needs two host directories\n"));
    return ok;
}

// OUTDIR -> outside, DANGLING -> outside/MISSING, LINKFILE.TXT ->
// outside/NEW7.TXT (absent): creating through them must not create outside.
void
Escape::ThroughLinks()
{
    TRY("fopen(OUTDIR/NEW1.TXT, w)", Got(fopen("/MS/OUTDIR/NEW1.TXT", "w")));
    TRY("fopen(OUTDIR/NEW2.TXT, a)", Got(fopen("/MS/OUTDIR/NEW2.TXT", "a")));
    TRY("open(OUTDIR/NEW3.TXT, O_CREAT)", Got(open("/MS/OUTDIR/NEW3.TXT", O_WRONLY | O_CREAT, 0666)));
    TRY("creat(OUTDIR/NEW4.TXT)", Got(creat("/MS/OUTDIR/NEW4.TXT", 0666)));
    TRY("ofstream(OUTDIR/NEW5.TXT)", MadeStream("/MS/OUTDIR/NEW5.TXT"));
    TRY("mkdir(OUTDIR/NEWDIR)", Zero(mkdir("/MS/OUTDIR/NEWDIR", 0777)));
    TRY("rename(DATA/P/VICTIM.TXT, OUTDIR/..)", Zero(rename("/MS/OPEN-R/MW/DATA/P/VICTIM.TXT", "/MS/OUTDIR/MOVED.TXT")));
    TRY("fopen(DANGLING/NEW6.TXT, w)", Got(fopen("/MS/DANGLING/NEW6.TXT", "w")));
    TRY("fopen(LINKFILE.TXT, w) (dangling)", Got(fopen("/MS/LINKFILE.TXT", "w")));
    TRY("fopen(OUTDIR/SECRET.TXT, r)", Got(fopen("/MS/OUTDIR/SECRET.TXT", "r")));
    TRY("ifstream(OUTDIR/SECRET.TXT)", GotStream("/MS/OUTDIR/SECRET.TXT"));
    TRY("stat(OUTDIR/SECRET.TXT)", Stats("/MS/OUTDIR/SECRET.TXT"));
    TRY("unlink(OUTDIR/SECRET.TXT)", Zero(unlink("/MS/OUTDIR/SECRET.TXT")));
}

// Host paths, ".." and calls mkbin does not wrap.
void
Escape::ThroughHostPaths()
{
    char path[600], other[600];
    snprintf(path, sizeof path, "%s/../../../../etc/passwd", stick);
    TRY("ifstream(<stick>/../../../../etc/passwd)", GotStream(path));
    TRY("fopen(<stick>/../../../../etc/passwd)", Got(fopen(path, "r")));
    TRY("fopen(/MS/../etc/passwd)", Got(fopen("/MS/../etc/passwd", "r")));
    TRY("ifstream(/etc/passwd)", GotStream("/etc/passwd"));
    TRY("openat(AT_FDCWD, /etc/passwd)", Got(openat(AT_FDCWD, "/etc/passwd", O_RDONLY)));
    int dir = open("/MS/OPEN-R", O_RDONLY | O_DIRECTORY);
    TRY("openat(dirfd, ../../../../etc/passwd)", Got(openat(dir, "../../../../etc/passwd", O_RDONLY)));
    if (dir >= 0) close(dir);
    struct dirent** list = NULL;
    TRY("scandir(/etc)", scandir("/etc", &list, NULL, alphasort) >= 0);
    TRY("opendir(/etc)", Got(opendir("/etc")));
    TRY("stat(/etc/passwd)", Stats("/etc/passwd"));
    TRY("access(/etc/passwd)", Zero(access("/etc/passwd", R_OK)));
    char resolved[PATH_MAX];
    TRY("realpath(/etc/passwd)", realpath("/etc/passwd", resolved) != NULL);
    TRY("realpath(/MS/OUTDIR)", realpath("/MS/OUTDIR", resolved) != NULL);

    snprintf(path, sizeof path, "%s/SECRET.TXT", outside);
    snprintf(other, sizeof other, "%s/HOSTLINK", outside);
    TRY("symlink(/etc/passwd, <outside>/HOSTLINK)", Zero(symlink("/etc/passwd", other)));
    TRY("symlink(/etc, /MS/OPEN-R/ETC)", Zero(symlink("/etc", "/MS/OPEN-R/ETC")));
    TRY("link(<outside>/SECRET.TXT, /MS/HARD.TXT)", Zero(link(path, "/MS/HARD.TXT")));
    TRY("chmod(<outside>/SECRET.TXT)", Zero(chmod(path, 0777)));
    TRY("truncate(<outside>/SECRET.TXT)", Zero(truncate(path, 0)));
    TRY("utime(<outside>/SECRET.TXT)", Zero(utime(path, NULL)));
    TRY("unlink(<outside>/SECRET.TXT)", Zero(unlink(path)));
    TRY("rename(<outside>/SECRET.TXT, /MS/S.TXT)", Zero(rename(path, "/MS/S.TXT")));
    TRY("mkdir(<outside>/NEWDIR)", Zero(mkdir((std::string(outside) + "/NEWDIR").c_str(), 0777)));
    TRY("chdir(/MS/OPEN-R)", Zero(chdir("/MS/OPEN-R")));
    char tmpl[] = "/tmp/escapeXXXXXX";
    TRY("mkstemp(/tmp/escapeXXXXXX)", Got(mkstemp(tmpl)));
    TRY("tmpfile()", Got(tmpfile()));
}

static void* threadBody(void* arg)
{
    const char* outside = static_cast<const char*>(arg);
    char path[600];
    snprintf(path, sizeof path, "%s/SECRET.TXT", outside);
    TRY("own thread: ifstream(/etc/passwd)", GotStream("/etc/passwd"));
    TRY("own thread: fopen(<outside>/SECRET.TXT)", Got(fopen(path, "r")));
    TRY("own thread: fopen(OUTDIR/NEW8.TXT, w)", Got(fopen("/MS/OUTDIR/NEW8.TXT", "w")));
    bool ok = GotStream("/MS/OPEN-R/MW/CONF/ESCAPE.CFG");
    OSYSPRINT(("Escape : own thread: ifstream(/MS/.../ESCAPE.CFG) %s\n", ok ? "ok" : "FAILED"));
    return NULL;
}

// Threads an object starts itself are the object's too.
void
Escape::FromOwnThread()
{
    pthread_t t;
    if (pthread_create(&t, NULL, threadBody, outside) != 0) {
        OSYSPRINT(("Escape : pthread_create FAILED\n"));
        return;
    }
    pthread_join(t, NULL);
}

// The stick itself, and a link inside it that stays inside, still work.
void
Escape::StillWorks()
{
    FILE* fp = fopen("/MS/INSIDE/OK.TXT", "w");
    bool ok = fp != NULL && fputs("written through INSIDE\n", fp) >= 0;
    if (fp != NULL) fclose(fp);
    ok = ok && GotStream("/MS/OPEN-R/MW/DATA/P/ok.txt");
    OSYSPRINT(("Escape : link inside the stick, write and read %s\n", ok ? "ok" : "FAILED"));

    char resolved[PATH_MAX];
    if (realpath("/ms/open-r/../OPEN-R/mw/conf/escape.cfg", resolved) != NULL) {
        OSYSPRINT(("Escape : realpath(/ms/open-r/../OPEN-R/mw/conf/escape.cfg) = %s\n", resolved));
    }
    if (realpath("/MS/INSIDE", resolved) != NULL) {
        OSYSPRINT(("Escape : realpath(/MS/INSIDE) = %s\n", resolved));
    }
}
