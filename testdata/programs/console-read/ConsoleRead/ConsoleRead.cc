//
// ConsoleRead.cc
//
// A command prompt on the robot's console (telnet to port 59000), the way
// many AIBO programs did it: print a prompt, read a line, act on it, forever.
// Like them it never checks for end of input: the robot's console has none,
// a read just waits until something is typed.
//
// /MS/OPEN-R/MW/CONF/READER.CFG picks the reading style: "gets" or "cin".
//

#include <stdio.h>
#include <string.h>
#include <iostream>
#include <string>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "ConsoleRead.h"

static const char* const READER_CFG = "/MS/OPEN-R/MW/CONF/READER.CFG";

OStatus
ConsoleRead::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
ConsoleRead::DoStart(const OSystemEvent& event)
{
    char style[16] = "gets";
    FILE* fp = fopen(READER_CFG, "r");
    if (fp != 0) {
        fscanf(fp, "%15s", style);
        fclose(fp);
    }
    OSYSPRINT(("ConsoleRead : reading the console with %s\n", style));
    if (strcmp(style, "cin") == 0) {
        CinLoop();
    } else {
        GetsLoop();
    }
    return oSUCCESS;        // never reached: the loops do not end
}

void
ConsoleRead::GetsLoop()
{
    char line[128];
    int n = 0;
    for (;;) {
        printf("ConsoleRead > ");
        line[0] = '\0';
        gets(line);
        n++;
        printf("ConsoleRead : line %d: %s\n", n, line);
    }
}

void
ConsoleRead::CinLoop()
{
    std::string word;
    int n = 0;
    for (;;) {
        std::cout << "ConsoleRead > ";
        word = "";
        std::cin >> word;
        n++;
        std::cout << "ConsoleRead : word " << n << ": " << word << std::endl;
    }
}

OStatus
ConsoleRead::DoStop(const OSystemEvent& event)
{
    OSYSPRINT(("ConsoleRead : DoStop\n"));
    return oSUCCESS;
}

OStatus
ConsoleRead::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
