//
// FtpServer.cc
//
// A small FTP server for the Memory Stick, in the style of the IPStack
// samples: up to four control connections (PI) on port 21, each with its
// own data connection (DTP), passive (port 3000 + session) or active (from
// port 20). Users come from /MS/OPEN-R/MW/CONF/PASSWD ("user password home"
// per line, password * = any). Paths are upper-cased and kept below the
// user's home. Transfers are binary (TYPE A is accepted and ignored).
//

#include <ctype.h>
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "FtpServer.h"
#include "entry.h"

FtpServer::FtpServer() : numLogins(0), stopping(false)
{
    memset(session, 0, sizeof(session));
}

OStatus
FtpServer::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
FtpServer::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    if (!LoadPasswd()) {
        OSYSPRINT(("FtpServer : can't read %s\n", FTP_PASSWD_PATH));
        return oFAIL;
    }
    ipstackRef = antStackRef("IPStack");
    for (int i = 0; i < FTP_CONNECTION_MAX; i++) {
        if (!InitEndpointBuffers(&session[i].pi) || !InitEndpointBuffers(&session[i].dtp))
            return oFAIL;
        ListenPI(i);
    }
    OSYSPRINT(("FtpServer : listening on port %d (%d users)\n", FTP_LISTEN_PORT, numLogins));
    return oSUCCESS;
}

OStatus
FtpServer::DoStop(const OSystemEvent& event)
{
    stopping = true;
    for (int i = 0; i < FTP_CONNECTION_MAX; i++) ClosePI(i);
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
FtpServer::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

bool
FtpServer::LoadPasswd()
{
    FILE* fp = fopen(FTP_PASSWD_PATH, "r");
    if (fp == 0) return false;
    char line[256];
    numLogins = 0;
    while (numLogins < FTP_MAX_LOGIN && fgets(line, sizeof(line), fp) != 0) {
        FtpLogin* l = &logins[numLogins];
        if (sscanf(line, "%31s %31s %127s", l->user, l->pass, l->home) == 3) numLogins++;
    }
    fclose(fp);
    return true;
}

bool
FtpServer::InitEndpointBuffers(FtpEndpoint* e)
{
    antEnvCreateSharedBufferMsg sendMsg(FTP_BUFFER_SIZE);
    sendMsg.Call(ipstackRef, sizeof(sendMsg));
    antEnvCreateSharedBufferMsg recvMsg(FTP_BUFFER_SIZE);
    recvMsg.Call(ipstackRef, sizeof(recvMsg));
    if (sendMsg.error != ANT_SUCCESS || recvMsg.error != ANT_SUCCESS) return false;
    e->sendBuffer = sendMsg.buffer;
    e->sendBuffer.Map();
    e->sendData = (char*)e->sendBuffer.GetAddress();
    e->recvBuffer = recvMsg.buffer;
    e->recvBuffer.Map();
    e->recvData = (char*)e->recvBuffer.GetAddress();
    e->state = FTP_CLOSED;
    e->sending = false;
    return true;
}

bool
FtpServer::NewEndpoint(FtpEndpoint* e)
{
    antEnvCreateEndpointMsg createMsg(EndpointType_TCP, FTP_BUFFER_SIZE * 2);
    createMsg.Call(ipstackRef, sizeof(createMsg));
    if (createMsg.error != ANT_SUCCESS) return false;
    e->endpoint = createMsg.moduleRef;
    e->sending = false;
    return true;
}

// ---------------------------------------------------------------- control (PI)

void
FtpServer::ListenPI(int index)
{
    FtpEndpoint* pi = &session[index].pi;
    if (!NewEndpoint(pi)) return;
    TCPEndpointListenMsg listenMsg(pi->endpoint, IP_ADDR_ANY, FTP_LISTEN_PORT);
    listenMsg.continuation = (void*)index;
    listenMsg.Send(ipstackRef, myOID_, Extra_Entry[entryListenContforPI], sizeof(listenMsg));
    pi->state = FTP_LISTENING;
}

void
FtpServer::ListenContforPI(ANTENVMSG msg)
{
    TCPEndpointListenMsg* listenMsg = (TCPEndpointListenMsg*)antEnvMsg::Receive(msg);
    int index = (int)listenMsg->continuation;
    FtpSession* s = &session[index];
    if (s->pi.state != FTP_LISTENING) return;
    if (listenMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("FtpServer : listen error %d\n", listenMsg->error));
        ClosePI(index);
        return;
    }
    s->pi.state = FTP_CONNECTED;
    s->pending[0] = '\0';
    s->closeAfterSend = false;
    s->user[0] = '\0';
    s->login = -1;
    strcpy(s->cwd, "/MS/");
    s->binary = false;
    s->passive = false;
    s->transfer = XFER_NONE;
    s->file = 0;
    s->lAddress = listenMsg->lAddress;
    char addr[16];
    OSYSPRINT(("FtpServer : session %d: connection from %s\n", index,
               listenMsg->fAddress.GetAsString(addr)));
    Reply(index, "220 AIBO FTP Server ready");
    ReceivePI(index);
}

void
FtpServer::ReceivePI(int index)
{
    FtpEndpoint* pi = &session[index].pi;
    TCPEndpointReceiveMsg receiveMsg(pi->endpoint, (byte*)pi->recvData, 1, FTP_BUFFER_SIZE - 1);
    receiveMsg.continuation = (void*)index;
    receiveMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveContforPI], sizeof(receiveMsg));
}

void
FtpServer::ReceiveContforPI(ANTENVMSG msg)
{
    TCPEndpointReceiveMsg* receiveMsg = (TCPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    int index = (int)receiveMsg->continuation;
    FtpSession* s = &session[index];
    if (s->pi.state != FTP_CONNECTED) return;
    if (receiveMsg->error != TCP_SUCCESS) {
        ClosePI(index);
        return;
    }
    // one command per chunk, as the robot's server does
    char* line = s->pi.recvData;
    line[receiveMsg->sizeMin] = '\0';
    char* end = strpbrk(line, "\r\n");
    if (end != 0) {
        *end = '\0';
        Command(index, line);
    }
    if (s->pi.state == FTP_CONNECTED && !s->closeAfterSend) ReceivePI(index);
}

void
FtpServer::Reply(int index, const char* text)
{
    FtpSession* s = &session[index];
    if (strlen(s->pending) + strlen(text) + 3 > sizeof(s->pending)) return;
    strcat(s->pending, text);
    strcat(s->pending, "\r\n");
    FlushReply(index);
}

void
FtpServer::FlushReply(int index)
{
    FtpSession* s = &session[index];
    if (s->pi.sending || s->pi.state != FTP_CONNECTED || s->pending[0] == '\0') return;
    int size = strlen(s->pending);
    memcpy(s->pi.sendData, s->pending, size);
    s->pending[0] = '\0';
    TCPEndpointSendMsg sendMsg(s->pi.endpoint, (byte*)s->pi.sendData, size);
    sendMsg.continuation = (void*)index;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendContforPI], sizeof(sendMsg));
    s->pi.sending = true;
}

void
FtpServer::SendContforPI(ANTENVMSG msg)
{
    TCPEndpointSendMsg* sendMsg = (TCPEndpointSendMsg*)antEnvMsg::Receive(msg);
    int index = (int)sendMsg->continuation;
    FtpSession* s = &session[index];
    s->pi.sending = false;
    if (s->pi.state != FTP_CONNECTED) return;
    if (sendMsg->error != TCP_SUCCESS) {
        ClosePI(index);
    } else if (s->pending[0] != '\0') {
        FlushReply(index);
    } else if (s->closeAfterSend) {
        ClosePI(index);
    }
}

void
FtpServer::ClosePI(int index)
{
    FtpSession* s = &session[index];
    if (s->pi.state == FTP_CLOSED || s->pi.state == FTP_CLOSING) return;
    if (s->dtp.state == FTP_LISTENING || s->dtp.state == FTP_CONNECTED) CloseDTP(index, true);
    TCPEndpointCloseMsg closeMsg(s->pi.endpoint);
    closeMsg.continuation = (void*)index;
    closeMsg.Send(ipstackRef, myOID_, Extra_Entry[entryCloseContforPI], sizeof(closeMsg));
    s->pi.state = FTP_CLOSING;
}

void
FtpServer::CloseContforPI(ANTENVMSG msg)
{
    TCPEndpointCloseMsg* closeMsg = (TCPEndpointCloseMsg*)antEnvMsg::Receive(msg);
    int index = (int)closeMsg->continuation;
    session[index].pi.state = FTP_CLOSED;
    if (!stopping) ListenPI(index);
}

// ---------------------------------------------------------------- commands

bool
FtpServer::MakePath(int index, const char* arg, char* out)
{
    FtpSession* s = &session[index];
    char work[2 * FTP_PATH_MAX];
    if (arg[0] == '/') work[0] = '\0';
    else strcpy(work, s->cwd);
    strncat(work, "/", sizeof(work) - strlen(work) - 1);
    strncat(work, arg, sizeof(work) - strlen(work) - 1);

    // normalise: drop "", "." and resolve ".."; upper-case
    char result[2 * FTP_PATH_MAX] = "";
    char* save = 0;
    for (char* part = strtok_r(work, "/", &save); part != 0; part = strtok_r(0, "/", &save)) {
        if (strcmp(part, ".") == 0) continue;
        if (strcmp(part, "..") == 0) {
            char* slash = strrchr(result, '/');
            if (slash != 0) *slash = '\0';
            continue;
        }
        strcat(result, "/");
        for (char* p = part; *p; p++) *p = toupper((unsigned char)*p);
        strcat(result, part);
    }
    if (result[0] == '\0') strcpy(result, "/");

    const char* home = logins[s->login].home;
    int homeLen = strlen(home);
    while (homeLen > 1 && home[homeLen - 1] == '/') homeLen--;
    if (strncmp(result, home, homeLen) != 0 ||
        (result[homeLen] != '\0' && result[homeLen] != '/')) return false;
    if (strlen(result) >= FTP_PATH_MAX) return false;
    strcpy(out, result);
    return true;
}

void
FtpServer::Command(int index, char* line)
{
    FtpSession* s = &session[index];
    char text[FTP_PATH_MAX + 64];
    char* arg = strchr(line, ' ');
    if (arg != 0) *arg++ = '\0';
    else arg = line + strlen(line);
    for (char* p = line; *p; p++) *p = toupper((unsigned char)*p);

    if (strcmp(line, "USER") == 0) {
        strncpy(s->user, arg, sizeof(s->user) - 1);
        s->login = -1;
        sprintf(text, "331 Password required for %s.", s->user);
        Reply(index, text);
        return;
    }
    if (strcmp(line, "PASS") == 0) {
        if (s->user[0] == '\0') {
            Reply(index, "503 Login with USER first.");
            return;
        }
        for (int i = 0; i < numLogins; i++) {
            if (strcmp(logins[i].user, s->user) == 0 &&
                (strcmp(logins[i].pass, "*") == 0 || strcmp(logins[i].pass, arg) == 0)) {
                s->login = i;
                strcpy(s->cwd, logins[i].home);
                sprintf(text, "230 User %s logged in.", s->user);
                Reply(index, text);
                return;
            }
        }
        Reply(index, "530 Login incorrect.");
        return;
    }
    if (strcmp(line, "QUIT") == 0) {
        Reply(index, "221 Goodbye. Thanks for using the AIBO FTP Server.");
        s->closeAfterSend = true;
        return;
    }
    if (strcmp(line, "SYST") == 0) { Reply(index, "215 Aperios system type."); return; }
    if (strcmp(line, "NOOP") == 0) { Reply(index, "200 NOOP command successful."); return; }
    if (s->login < 0) {
        Reply(index, "530 Please login with USER and PASS.");
        return;
    }

    char path[FTP_PATH_MAX];
    if (strcmp(line, "PWD") == 0 || strcmp(line, "XPWD") == 0) {
        sprintf(text, "257 \"%s\" is current directory.", s->cwd);
        Reply(index, text);
    } else if (strcmp(line, "CWD") == 0 || strcmp(line, "CDUP") == 0) {
        struct stat st;
        if (MakePath(index, strcmp(line, "CDUP") == 0 ? ".." : arg, path) &&
            stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
            strcpy(s->cwd, path);
            if (s->cwd[strlen(s->cwd) - 1] != '/') strcat(s->cwd, "/");
            Reply(index, "250 CWD command successful.");
        } else {
            Reply(index, "550 No such directory.");
        }
    } else if (strcmp(line, "TYPE") == 0) {
        char t = toupper((unsigned char)arg[0]);
        if (t == 'I' || t == 'A') {
            s->binary = (t == 'I');
            sprintf(text, "200 TYPE set to %c.", t);
            Reply(index, text);
        } else {
            Reply(index, "502 Unknown type.");
        }
    } else if (strcmp(line, "PORT") == 0) {
        int h1, h2, h3, h4, p1, p2;
        if (sscanf(arg, "%d,%d,%d,%d,%d,%d", &h1, &h2, &h3, &h4, &p1, &p2) != 6) {
            Reply(index, "501 Syntax error.");
            return;
        }
        s->portAddress = IPAddress((byte)h1, (byte)h2, (byte)h3, (byte)h4);
        s->portPort = (Port)((p1 << 8) | p2);
        s->passive = false;
        Reply(index, "200 PORT command successful.");
    } else if (strcmp(line, "PASV") == 0) {
        if (s->dtp.state != FTP_CLOSED || !NewEndpoint(&s->dtp)) {
            Reply(index, "425 Can't open data connection.");
            return;
        }
        Port port = FTP_PASV_DATA_PORT + index;
        TCPEndpointListenMsg listenMsg(s->dtp.endpoint, IP_ADDR_ANY, port);
        listenMsg.continuation = (void*)index;
        listenMsg.Send(ipstackRef, myOID_, Extra_Entry[entryListenContforDTP], sizeof(listenMsg));
        s->dtp.state = FTP_LISTENING;
        s->passive = true;
        uint32 a = s->lAddress.Address();
        sprintf(text, "227 Entering Passive Mode. %d,%d,%d,%d,%d,%d",
                (int)(a >> 24) & 0xff, (int)(a >> 16) & 0xff, (int)(a >> 8) & 0xff, (int)a & 0xff,
                port >> 8, port & 0xff);
        Reply(index, text);
    } else if (strcmp(line, "RETR") == 0) {
        StartTransfer(index, XFER_RETR, arg);
    } else if (strcmp(line, "STOR") == 0) {
        StartTransfer(index, XFER_STOR, arg);
    } else if (strcmp(line, "LIST") == 0) {
        StartTransfer(index, XFER_LIST, arg);
    } else if (strcmp(line, "NLST") == 0) {
        StartTransfer(index, XFER_NLST, arg);
    } else {
        sprintf(text, "500 '%.32s %.64s': command not understood.", line, arg);
        Reply(index, text);
    }
}

// ---------------------------------------------------------------- data (DTP)

void
FtpServer::StartTransfer(int index, FtpTransfer kind, const char* arg)
{
    FtpSession* s = &session[index];
    if (s->transfer != XFER_NONE) {
        Reply(index, "425 Transfer in progress.");
        return;
    }
    // LIST options such as "-l" are ignored
    if ((kind == XFER_LIST || kind == XFER_NLST) && arg[0] == '-') arg = "";
    if (!MakePath(index, arg[0] != '\0' ? arg : ".", s->path)) {
        Reply(index, kind == XFER_STOR ? "553 error." : "550 No such file.");
        return;
    }
    const char* base = strrchr(s->path, '/');
    strcpy(s->name, base != 0 ? base + 1 : s->path);
    s->file = 0;
    if (kind == XFER_RETR) {
        s->file = fopen(s->path, "rb");
        if (s->file == 0) { Reply(index, "550 No such file."); return; }
    } else if (kind == XFER_STOR) {
        s->file = fopen(s->path, "wb");
        if (s->file == 0) { Reply(index, "553 error."); return; }
    } else {
        struct stat st;
        if (stat(s->path, &st) != 0 || !S_ISDIR(st.st_mode)) { Reply(index, "450 Not taken."); return; }
    }
    s->transfer = kind;
    s->transferFailed = false;

    if (s->passive) {
        if (s->dtp.state == FTP_CONNECTED) DataConnected(index);
        else if (s->dtp.state != FTP_LISTENING) CloseDTP(index, true);
        return;   // the data connection arrives later
    }
    if (s->dtp.state != FTP_CLOSED || !NewEndpoint(&s->dtp)) {
        Reply(index, "425 Can't open data connection.");
        if (s->file != 0) fclose(s->file);
        s->transfer = XFER_NONE;
        return;
    }
    TCPEndpointConnectMsg connectMsg(s->dtp.endpoint, 0, FTP_DATA_PORT, s->portAddress, s->portPort);
    connectMsg.continuation = (void*)index;
    connectMsg.Send(ipstackRef, myOID_, Extra_Entry[entryConnectContforDTP], sizeof(connectMsg));
    s->dtp.state = FTP_LISTENING;   // i.e. "being set up"
}

void
FtpServer::ListenContforDTP(ANTENVMSG msg)
{
    TCPEndpointListenMsg* listenMsg = (TCPEndpointListenMsg*)antEnvMsg::Receive(msg);
    int index = (int)listenMsg->continuation;
    FtpSession* s = &session[index];
    if (s->dtp.state != FTP_LISTENING) return;
    if (listenMsg->error != TCP_SUCCESS) {
        CloseDTP(index, true);
        return;
    }
    s->dtp.state = FTP_CONNECTED;
    if (s->transfer != XFER_NONE) DataConnected(index);
}

void
FtpServer::ConnectContforDTP(ANTENVMSG msg)
{
    TCPEndpointConnectMsg* connectMsg = (TCPEndpointConnectMsg*)antEnvMsg::Receive(msg);
    int index = (int)connectMsg->continuation;
    FtpSession* s = &session[index];
    if (s->dtp.state != FTP_LISTENING) return;
    if (connectMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("FtpServer : data connection failed (%d)\n", connectMsg->error));
        CloseDTP(index, true);
        return;
    }
    s->dtp.state = FTP_CONNECTED;
    DataConnected(index);
}

void
FtpServer::DataConnected(int index)
{
    FtpSession* s = &session[index];
    char text[FTP_PATH_MAX + 64];
    sprintf(text, "150 %s data connection for %s.", s->binary ? "Binary" : "ASCII", s->name);
    Reply(index, text);
    switch (s->transfer) {
    case XFER_RETR: SendNextChunk(index); break;
    case XFER_LIST:
    case XFER_NLST: SendListing(index); break;
    case XFER_STOR: {
        TCPEndpointReceiveMsg receiveMsg(s->dtp.endpoint, (byte*)s->dtp.recvData, 1, FTP_BUFFER_SIZE);
        receiveMsg.continuation = (void*)index;
        receiveMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveContforDTP], sizeof(receiveMsg));
        break;
    }
    default: break;
    }
}

void
FtpServer::SendNextChunk(int index)
{
    FtpSession* s = &session[index];
    int n = fread(s->dtp.sendData, 1, FTP_BUFFER_SIZE, s->file);
    if (n <= 0) {
        CloseDTP(index, false);
        return;
    }
    TCPEndpointSendMsg sendMsg(s->dtp.endpoint, (byte*)s->dtp.sendData, n);
    sendMsg.continuation = (void*)index;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendContforDTP], sizeof(sendMsg));
}

void
FtpServer::SendListing(int index)
{
    FtpSession* s = &session[index];
    int size = 0;
    DIR* dir = opendir(s->path);
    struct dirent* entry;
    while (dir != 0 && (entry = readdir(dir)) != 0) {
        if (size > FTP_BUFFER_SIZE - 200) break;
        if (s->transfer == XFER_NLST) {
            if (entry->d_name[0] == '.') continue;
            size += sprintf(s->dtp.sendData + size, "%s\r\n", entry->d_name);
            continue;
        }
        char full[2 * FTP_PATH_MAX];
        sprintf(full, "%s/%s", s->path, entry->d_name);
        struct stat st;
        if (stat(full, &st) != 0) continue;
        bool isDir = S_ISDIR(st.st_mode);
        char perm[4] = { (st.st_mode & S_IRUSR) ? 'r' : '-', (st.st_mode & S_IWUSR) ? 'w' : '-',
                         isDir ? 'x' : '-', '\0' };
        size += sprintf(s->dtp.sendData + size, "%c%s%s%s 0 AIBO AIBO %ld May 11 1999 %s\r\n",
                        isDir ? 'd' : '-', perm, perm, perm, (long)st.st_size, entry->d_name);
    }
    if (dir != 0) closedir(dir);
    if (size == 0) {
        CloseDTP(index, false);
        return;
    }
    TCPEndpointSendMsg sendMsg(s->dtp.endpoint, (byte*)s->dtp.sendData, size);
    sendMsg.continuation = (void*)index;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendContforDTP], sizeof(sendMsg));
}

void
FtpServer::SendContforDTP(ANTENVMSG msg)
{
    TCPEndpointSendMsg* sendMsg = (TCPEndpointSendMsg*)antEnvMsg::Receive(msg);
    int index = (int)sendMsg->continuation;
    FtpSession* s = &session[index];
    if (s->dtp.state != FTP_CONNECTED) return;
    if (sendMsg->error != TCP_SUCCESS) CloseDTP(index, true);
    else if (s->transfer == XFER_RETR) SendNextChunk(index);
    else CloseDTP(index, false);
}

void
FtpServer::ReceiveContforDTP(ANTENVMSG msg)
{
    TCPEndpointReceiveMsg* receiveMsg = (TCPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    int index = (int)receiveMsg->continuation;
    FtpSession* s = &session[index];
    if (s->dtp.state != FTP_CONNECTED) return;
    if (receiveMsg->error == TCP_CONNECTION_CLOSED) {
        CloseDTP(index, false);   // the client finished the upload
        return;
    }
    if (receiveMsg->error != TCP_SUCCESS ||
        fwrite(s->dtp.recvData, 1, receiveMsg->sizeMin, s->file) != (size_t)receiveMsg->sizeMin) {
        CloseDTP(index, true);
        return;
    }
    TCPEndpointReceiveMsg again(s->dtp.endpoint, (byte*)s->dtp.recvData, 1, FTP_BUFFER_SIZE);
    again.continuation = (void*)index;
    again.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveContforDTP], sizeof(again));
}

void
FtpServer::CloseDTP(int index, bool failed)
{
    FtpSession* s = &session[index];
    if (s->file != 0) {
        fclose(s->file);
        s->file = 0;
    }
    s->transferFailed = s->transferFailed || failed;
    if (s->dtp.state == FTP_CLOSING) return;
    if (s->dtp.state == FTP_CLOSED) {
        // nothing to close: answer at once
        if (s->transfer != XFER_NONE) Reply(index, "426 Transfer abort.");
        s->transfer = XFER_NONE;
        return;
    }
    TCPEndpointCloseMsg closeMsg(s->dtp.endpoint);
    closeMsg.continuation = (void*)index;
    closeMsg.Send(ipstackRef, myOID_, Extra_Entry[entryCloseContforDTP], sizeof(closeMsg));
    s->dtp.state = FTP_CLOSING;
}

void
FtpServer::CloseContforDTP(ANTENVMSG msg)
{
    TCPEndpointCloseMsg* closeMsg = (TCPEndpointCloseMsg*)antEnvMsg::Receive(msg);
    int index = (int)closeMsg->continuation;
    FtpSession* s = &session[index];
    s->dtp.state = FTP_CLOSED;
    if (s->transfer != XFER_NONE) {
        Reply(index, s->transferFailed ? "426 Transfer abort." : "226 Transfer complete.");
        s->transfer = XFER_NONE;
    }
    s->passive = false;
}
