//
// FileSys.cc
//
// Objects read and write the Memory Stick with the usual C, POSIX and
// C++ calls. Paths are absolute and start with /MS/; names are FAT 8.3
// and case-insensitive.
//

#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/types.h>
#include <sys/stat.h>
#include <dirent.h>
#include <fstream>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "FileSys.h"

#define DATA_DIR   "/MS/OPEN-R/MW/DATA/P"
#define LOG_FILE   DATA_DIR "/LOG.TXT"
#define OLD_LOG    DATA_DIR "/OLDLOG.TXT"
#define STREAM_FILE DATA_DIR "/STREAM.TXT"
#define TMP_DIR    DATA_DIR "/TMPDIR"

static const int LOG_SIZE = 3 * 11;   // three lines "log line N\n"

FileSys::FileSys()
{
}

OStatus
FileSys::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
FileSys::DoStart(const OSystemEvent& event)
{
    // Leftovers of an earlier run would change the directory listing.
    unlink(OLD_LOG);

    WriteWithStdio();
    ReadWithPosix();
    StatAndRename();
    CaseInsensitiveNames();
    Directories();
    Streams();
    ListDirectory();
    EscapeAttempt();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
FileSys::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
FileSys::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
FileSys::Result(const char* step, bool ok)
{
    OSYSPRINT(("FileSys : %-31s %s\n", step, ok ? "ok" : "FAILED"));
}

void
FileSys::WriteWithStdio()
{
    FILE* fp = fopen(LOG_FILE, "w");
    if (fp == NULL) {
        Result("fopen(LOG.TXT, \"w\")", false);
        return;
    }
    for (int i = 1; i <= 3; i++) {
        fprintf(fp, "log line %d\n", i);
    }
    fclose(fp);
    Result("fopen/fprintf LOG.TXT", true);
}

void
FileSys::ReadWithPosix()
{
    int fd = open(LOG_FILE, O_RDONLY);
    if (fd < 0) {
        Result("open(LOG.TXT, O_RDONLY)", false);
        return;
    }

    char buf[128];
    int  n = read(fd, buf, sizeof(buf) - 1);
    close(fd);

    if (n < 0) n = 0;
    buf[n] = '\0';
    Result("open/read LOG.TXT", n == LOG_SIZE && strncmp(buf, "log line 1\n", 11) == 0);

    // Print the last line (without its newline).
    int bytes = n;
    if (n > 0 && buf[n - 1] == '\n') buf[--n] = '\0';
    char* last = strrchr(buf, '\n');
    OSYSPRINT(("FileSys :   read %d bytes, last line \"%s\"\n",
               bytes, last != NULL ? last + 1 : buf));
}

void
FileSys::StatAndRename()
{
    struct stat st;
    bool ok = (stat(LOG_FILE, &st) == 0);
    Result("stat LOG.TXT", ok && S_ISREG(st.st_mode) && st.st_size == LOG_SIZE);
    if (ok) {
        OSYSPRINT(("FileSys :   size %d, regular file %s\n",
                   (int)st.st_size, S_ISREG(st.st_mode) ? "yes" : "no"));
    }

    ok = (rename(LOG_FILE, OLD_LOG) == 0);
    Result("rename LOG.TXT OLDLOG.TXT", ok);

    // The old name must be gone, the new one must be there.
    Result("LOG.TXT gone, OLDLOG.TXT there",
           stat(LOG_FILE, &st) != 0 && stat(OLD_LOG, &st) == 0);
}

void
FileSys::CaseInsensitiveNames()
{
    // Create with a lower-case name, find it again in upper case.
    FILE* fp = fopen("/ms/open-r/mw/data/p/lower.txt", "w");
    if (fp != NULL) {
        fputs("written as lower.txt\n", fp);
        fclose(fp);
    }

    char line[64] = "";
    fp = fopen(DATA_DIR "/LOWER.TXT", "r");
    if (fp != NULL) {
        fgets(line, sizeof(line), fp);
        fclose(fp);
    }
    Result("lower.txt found as LOWER.TXT", strcmp(line, "written as lower.txt\n") == 0);
}

void
FileSys::Directories()
{
    struct stat st;
    bool ok = (mkdir(TMP_DIR, 0777) == 0);
    ok = ok && stat(TMP_DIR, &st) == 0 && S_ISDIR(st.st_mode);
    ok = ok && (rmdir(TMP_DIR) == 0);
    ok = ok && stat(TMP_DIR, &st) != 0;
    Result("mkdir/stat/rmdir TMPDIR", ok);
}

void
FileSys::Streams()
{
    {
        std::ofstream out(STREAM_FILE);
        out << "written by ofstream " << 42 << std::endl;
        Result("ofstream STREAM.TXT", out.good());
    }

    std::ifstream in(STREAM_FILE);
    char word[32] = "";
    int  number = 0;
    in >> word;                 // "written"
    in >> word >> word;         // "by" "ofstream"
    in >> number;
    Result("ifstream STREAM.TXT", in.good() && strcmp(word, "ofstream") == 0 && number == 42);
}

static int
compareNames(const void* a, const void* b)
{
    return strcmp((const char*)a, (const char*)b);
}

void
FileSys::ListDirectory()
{
    DIR* dir = opendir(DATA_DIR);
    if (dir == NULL) {
        Result("opendir DATA/P", false);
        return;
    }

    char names[32][16];
    int  num = 0;
    struct dirent* entry;
    while ((entry = readdir(dir)) != NULL && num < 32) {
        if (strcmp(entry->d_name, ".") == 0 || strcmp(entry->d_name, "..") == 0) continue;
        strncpy(names[num], entry->d_name, 15);
        names[num][15] = '\0';
        num++;
    }
    closedir(dir);
    qsort(names, num, sizeof(names[0]), compareNames);

    Result("opendir/readdir DATA/P", num > 0);
    OSYSPRINT(("FileSys :   %d entries:", num));
    for (int i = 0; i < num; i++) OSYSPRINT((" %s", names[i]));
    OSYSPRINT(("\n"));
}

void
FileSys::EscapeAttempt()
{
    // Paths may not leave the Memory Stick.
    FILE* fp = fopen("/MS/../../etc/passwd", "r");
    if (fp == NULL) {
        OSYSPRINT(("FileSys : fopen(\"/MS/../../etc/passwd\") refused\n"));
    } else {
        OSYSPRINT(("FileSys : fopen(\"/MS/../../etc/passwd\") NOT refused\n"));
        fclose(fp);
    }
}
