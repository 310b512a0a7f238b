//
// FtpServer.h
//

#ifndef FtpServer_h_DEFINED
#define FtpServer_h_DEFINED

#include <stdio.h>
#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <TCPEndpointMsg.h>
#include "def.h"

const int         FTP_CONNECTION_MAX = 4;
const int         FTP_BUFFER_SIZE    = 8192;
const Port        FTP_LISTEN_PORT    = 21;
const Port        FTP_DATA_PORT      = 20;
const Port        FTP_PASV_DATA_PORT = 3000;
const int         FTP_MAX_LOGIN      = 8;
const int         FTP_PATH_MAX       = 128;
const char* const FTP_PASSWD_PATH    = "/MS/OPEN-R/MW/CONF/PASSWD";

enum FtpConnState { FTP_CLOSED, FTP_LISTENING, FTP_CONNECTED, FTP_CLOSING };
enum FtpTransfer  { XFER_NONE, XFER_RETR, XFER_STOR, XFER_LIST, XFER_NLST };

struct FtpLogin {
    char user[32];
    char pass[32];
    char home[FTP_PATH_MAX];
};

struct FtpEndpoint {
    antModuleRef    endpoint;
    FtpConnState    state;
    bool            sending;
    antSharedBuffer sendBuffer;
    char*           sendData;
    antSharedBuffer recvBuffer;
    char*           recvData;
};

struct FtpSession {
    FtpEndpoint pi;
    FtpEndpoint dtp;
    char        pending[1024];    // control replies waiting for the current send
    bool        closeAfterSend;
    // login and file system
    char        user[32];
    int         login;            // index in the password table, -1 = none
    char        cwd[FTP_PATH_MAX];
    bool        binary;
    // data connection
    bool        passive;
    IPAddress   lAddress;         // our side of the control connection (PASV reply)
    IPAddress   portAddress;
    Port        portPort;
    FtpTransfer transfer;
    char        path[FTP_PATH_MAX];
    char        name[FTP_PATH_MAX];
    FILE*       file;
    bool        transferFailed;
};

class FtpServer : public OObject {
public:
    FtpServer();
    virtual ~FtpServer() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void ListenContforPI   (ANTENVMSG msg);
    void SendContforPI     (ANTENVMSG msg);
    void ReceiveContforPI  (ANTENVMSG msg);
    void CloseContforPI    (ANTENVMSG msg);
    void ListenContforDTP  (ANTENVMSG msg);
    void ConnectContforDTP (ANTENVMSG msg);
    void SendContforDTP    (ANTENVMSG msg);
    void ReceiveContforDTP (ANTENVMSG msg);
    void CloseContforDTP   (ANTENVMSG msg);

private:
    bool LoadPasswd();
    bool InitEndpointBuffers(FtpEndpoint* e);
    bool NewEndpoint(FtpEndpoint* e);
    void ListenPI(int index);
    void ReceivePI(int index);
    void Reply(int index, const char* text);
    void FlushReply(int index);
    void ClosePI(int index);
    void Command(int index, char* line);
    bool MakePath(int index, const char* arg, char* out);
    void StartTransfer(int index, FtpTransfer kind, const char* arg);
    void DataConnected(int index);
    void SendNextChunk(int index);
    void SendListing(int index);
    void CloseDTP(int index, bool failed);

    antStackRef ipstackRef;
    FtpSession  session[FTP_CONNECTION_MAX];
    FtpLogin    logins[FTP_MAX_LOGIN];
    int         numLogins;
    bool        stopping;
};

#endif // FtpServer_h_DEFINED
