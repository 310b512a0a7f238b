//
// ConfigReader.cc
//
// Reads /MS/OPEN-R/MW/CONF/ROBOT.CFG, whose keys were typed by hand in any
// case, with the string functions the robot's C library (newlib) had and a
// PC's glibc lacks: stricmp, strnicmp, strcmpi, strncmpi, strlwr, strupr,
// strlcpy. No C header is included: OPEN-R's headers brought them all.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "ConfigReader.h"

static const char* const CONFIG_FILE = "/MS/OPEN-R/MW/CONF/ROBOT.CFG";

ConfigReader::ConfigReader() : player(0)
{
    strcpy(name, "?");
    strcpy(team, "?");
    strcpy(mode, "?");
}

OStatus
ConfigReader::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

// Trim blanks and the line end in place.
static char* trim(char* s)
{
    while (*s == ' ' || *s == '\t') s++;
    char* e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n')) *--e = '\0';
    return s;
}

void
ConfigReader::Apply(char* key, char* value)
{
    if (stricmp(key, "name") == 0) {
        strlcpy(name, value, sizeof(name));
    } else if (strcmpi(key, "team") == 0) {
        strlcpy(team, value, sizeof(team));
        strupr(team);
    } else if (strnicmp(key, "play", 4) == 0) {
        player = atoi(value);
    } else if (strncmpi(key, "gamemode", 8) == 0) {
        size_t full = strlcpy(mode, value, sizeof(mode));
        strlwr(mode);
        OSYSPRINT(("ConfigReader : mode '%s' kept as '%s' (%d of %d chars)\n",
                   value, mode, (int)strlen(mode), (int)full));
    } else {
        OSYSPRINT(("ConfigReader : unknown key '%s'\n", strlwr(key)));
    }
}

OStatus
ConfigReader::DoStart(const OSystemEvent& event)
{
    FILE* fp = fopen(CONFIG_FILE, "r");
    if (fp == 0) {
        OSYSLOG1((osyslogERROR, "ConfigReader : cannot open %s", CONFIG_FILE));
        return oFAIL;
    }
    char line[128];
    while (fgets(line, sizeof(line), fp) != 0) {
        char* s = trim(line);
        if (*s == '#' || *s == '\0') continue;
        char* eq = index(s, '=');
        if (eq == 0) continue;
        *eq = '\0';
        Apply(trim(s), trim(eq + 1));
    }
    fclose(fp);

    OSYSPRINT(("ConfigReader : name = %s, team = %s, player = %d, mode = %s\n",
               name, team, player, mode));
    OSYSPRINT(("ConfigReader : stricmp(\"ERS-7\", \"ers-7\") = %d\n", stricmp("ERS-7", "ers-7")));
    return oSUCCESS;
}

OStatus
ConfigReader::DoStop(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus
ConfigReader::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
