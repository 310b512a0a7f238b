//
// Legacy.cc
//
// A collection of habits from 2003-era AIBO code, all in one object:
//
//  - pre-standard headers <iostream.h>, <fstream.h>, <iomanip.h>, <vector.h>
//  - "using namespace std;" in a file that also uses OPEN-R's "byte"
//  - atoi, malloc, free, isdigit, toupper, sprintf, qsort, gets without
//    including <stdlib.h>, <ctype.h> or <stdio.h>
//  - a pointer kept in an int (and turned back into a pointer)
//  - strtok over lines read with ifstream
//  - a lower-case path: the Memory Stick is case-insensitive
//  - <dirent.h> to list a directory
//

#include <iostream.h>
#include <fstream.h>
#include <iomanip.h>
#include <vector.h>
#include <dirent.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Legacy.h"

using namespace std;

static const char* const CONFIG_FILE = "/MS/open-r/mw/conf/legacy.cfg";
static const char* const DATA_DIR    = "/MS/OPEN-R/MW/DATA/P";

Legacy::Legacy() : count(0), numScale(0), askName(0), checksum(0)
{
    strcpy(name, "nobody");
}

OStatus
Legacy::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Legacy::DoStart(const OSystemEvent& event)
{
    ReadConfig();
    if (askName) AskName();

    cout << "Legacy : name = " << name << ", count = " << count << endl;

    vector<int> values;
    int sum = 0;
    for (int i = 0; i < numScale; i++) {
        values.push_back(scale[i]);
        sum += scale[i];
    }
    cout << "Legacy : scale";
    for (vector<int>::iterator it = values.begin(); it != values.end(); ++it) {
        cout << " " << setw(3) << *it;
    }
    cout << " (sum " << sum << ", x kGain = " << sum * kGain << ")" << endl;

    char hex[16];
    sprintf(hex, "0x%02x", checksum);
    cout << "Legacy : config checksum " << hex << endl;

    PointerRoundTrip();
    ListDataDirectory();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Legacy::DoStop(const OSystemEvent& event)
{
    cout << "Legacy : stop" << endl;
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Legacy::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

//
// Keywords are case-insensitive: they are upper-cased with toupper()
// before being compared.
//
void
Legacy::ReadConfig()
{
    ifstream in(CONFIG_FILE);
    if (!in) {
        cout << "Legacy : can't open " << CONFIG_FILE << endl;
        return;
    }

    char line[256];
    while (in.getline(line, sizeof(line))) {
        for (char* p = line; *p != '\0'; p++) checksum += (byte)*p;

        if (line[0] == '#') continue;

        char* key = strtok(line, " \t\r\n");
        if (key == NULL) continue;
        for (char* p = key; *p != '\0'; p++) *p = toupper(*p);

        if (strcmp(key, "NAME") == 0) {
            char* value = strtok(NULL, " \t\r\n");
            if (value != NULL) {
                strncpy(name, value, sizeof(name) - 1);
                name[sizeof(name) - 1] = '\0';
            }
        } else if (strcmp(key, "COUNT") == 0) {
            char* value = strtok(NULL, " \t\r\n");
            if (value != NULL && isdigit(value[0])) count = atoi(value);
        } else if (strcmp(key, "SCALE") == 0) {
            char* value;
            while ((value = strtok(NULL, " ,\t\r\n")) != NULL && numScale < kMaxScale) {
                if (isdigit(value[0])) scale[numScale++] = atoi(value);
            }
        } else if (strcmp(key, "ASK_NAME") == 0) {
            char* value = strtok(NULL, " \t\r\n");
            askName = (value != NULL && toupper(value[0]) == 'Y');
        } else {
            cout << "Legacy : unknown keyword " << key << endl;
        }
    }
}

//
// Only called when LEGACY.CFG says "ask_name yes": gets() blocks until
// a line is typed on the console.
//
void
Legacy::AskName()
{
    char buf[256];
    cout << "Legacy : your name? " << flush;
    if (gets(buf) != NULL && buf[0] != '\0') {
        strncpy(name, buf, sizeof(name) - 1);
        name[sizeof(name) - 1] = '\0';
    }
}

//
// Old code often kept a pointer in an int (message fields, user data
// of callbacks). That only works where pointers are 32 bits, as on the
// robot; we check instead of trusting it.
//
void
Legacy::PointerRoundTrip()
{
    void* mem = malloc(64);
    int   handle = (int)mem;
    void* back = (void*)handle;

    if (back == mem) {
        strcpy((char*)back, "round trip");
        cout << "Legacy : pointer round trip ok (" << (char*)back << ")" << endl;
    } else {
        cout << "Legacy : pointer round trip LOST bits (pointers wider than int)" << endl;
    }
    free(mem);
}

static int
compareNames(const void* a, const void* b)
{
    return strcmp((const char*)a, (const char*)b);
}

void
Legacy::ListDataDirectory()
{
    DIR* dir = opendir(DATA_DIR);
    if (dir == NULL) {
        cout << "Legacy : can't open " << DATA_DIR << endl;
        return;
    }

    const int MAX_FILES = 32;
    char names[MAX_FILES][16];
    int  num = 0;

    struct dirent* entry;
    while ((entry = readdir(dir)) != NULL && num < MAX_FILES) {
        if (entry->d_name[0] == '.') continue;    // "." and ".."
        strncpy(names[num], entry->d_name, 15);
        names[num][15] = '\0';
        num++;
    }
    closedir(dir);

    qsort(names, num, sizeof(names[0]), compareNames);

    cout << "Legacy : " << DATA_DIR << " has " << num << " file(s):";
    for (int i = 0; i < num; i++) cout << " " << names[i];
    cout << endl;
}
