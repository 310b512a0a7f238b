//
// SaveLog.cc
//
// Like the image savers, sound recorders and PID loggers of the time, this
// object saves what it measured into /MS/OPEN-R/MW/DATA/P. The program's
// own MS directory has no DATA/P: on the robot the directory comes from the
// base tree (OPEN_R/MS_ERS7/WCONSOLE/nomemprot/OPEN-R) the stick was made
// from, and so it does on the host.
//

#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <dirent.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SaveLog.h"

#define LOG_FILE  "/MS/OPEN-R/MW/DATA/P/LOG.TXT"
#define WLAN_FILE "/MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT"

SaveLog::SaveLog()
{
}

OStatus
SaveLog::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
SaveLog::DoStart(const OSystemEvent& event)
{
    SaveLines();
    ShowWlanDefaults();
    ListStick();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SaveLog::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SaveLog::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SaveLog::SaveLines()
{
    FILE* fp = fopen(LOG_FILE, "w");
    if (fp == NULL) {
        OSYSPRINT(("SaveLog : can't open %s\n", LOG_FILE));
        return;
    }
    for (int i = 1; i <= 3; i++) {
        fprintf(fp, "joint %d error %d\n", i, i * 10);
    }
    fclose(fp);
    OSYSPRINT(("SaveLog : saved 3 lines to %s\n", LOG_FILE));
}

// A file of the base tree, read as any file of the stick.
void
SaveLog::ShowWlanDefaults()
{
    FILE* fp = fopen(WLAN_FILE, "r");
    if (fp == NULL) {
        OSYSPRINT(("SaveLog : no %s\n", WLAN_FILE));
        return;
    }
    char line[128];
    while (fgets(line, sizeof(line), fp) != NULL) {
        if (strncmp(line, "HOSTNAME=", 9) == 0) {
            line[strcspn(line, "\r\n")] = '\0';
            OSYSPRINT(("SaveLog : %s says %s\n", WLAN_FILE, line));
        }
    }
    fclose(fp);
}

static int
compareNames(const void* a, const void* b)
{
    return strcmp((const char*)a, (const char*)b);
}

// The stick's OPEN-R holds the program's MW and the base tree's SYSTEM.
void
SaveLog::ListStick()
{
    DIR* dir = opendir("/MS/OPEN-R");
    if (dir == NULL) {
        OSYSPRINT(("SaveLog : can't open /MS/OPEN-R\n"));
        return;
    }
    char names[16][16];
    int num = 0;
    struct dirent* entry;
    while ((entry = readdir(dir)) != NULL && num < 16) {
        if (entry->d_name[0] == '.') continue;
        strncpy(names[num], entry->d_name, 15);
        names[num][15] = '\0';
        num++;
    }
    closedir(dir);
    qsort(names, num, sizeof(names[0]), compareNames);
    OSYSPRINT(("SaveLog : /MS/OPEN-R holds"));
    for (int i = 0; i < num; i++) OSYSPRINT((" %s", names[i]));
    OSYSPRINT(("\n"));
}
