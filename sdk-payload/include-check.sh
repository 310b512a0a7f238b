#!/usr/bin/env bash
#
# include-check.sh - compile checks of the OPEN-R SDK headers in
# sdk-payload/include (the future $OPENRSDK_ROOT/OPEN_R/include).
#
#   1. every header compiles alone as a C++ translation unit
#      (and the kernel-level headers also as C);
#   2. every header included twice in one unit compiles (include guards), and
#      two units including every header link into one shared object (no
#      non-inline definitions in headers);
#   3. sample-shaped programs (hand-written HelloWorld stub, stubgen-style
#      stubs, motion/sensor/network/power/legacy code) compile and link into
#      shared objects whose entry functions and ObjectEntryTable are exported.
#
# Exits non-zero on any failure. Usage: sdk-payload/include-check.sh [-v]
#
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
INC="$HERE/include"
CXX=${CXX:-g++}
CC=${CC:-gcc}
VERBOSE=0
[ "${1:-}" = "-v" ] && VERBOSE=1

# The flags the SDK's compiler wrapper adds, and Sony's include path order.
CXXFLAGS=(-std=gnu++98 -fpermissive -fPIC -Wall)
CFLAGS=(-fPIC -Wall)
ASMFLAG=("-Dasm(x)=")
INCS=(-I"$INC/R4000" -I"$INC/MCOOP" -I"$INC")

WORK=$(mktemp -d "${TMPDIR:-/tmp}/openr-include-check.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

failures=0
checks=0

# run NAME CMD... : run a command, record failure and show its output.
run() {
    local name=$1; shift
    checks=$((checks + 1))
    local log="$WORK/log.$checks"
    if "$@" >"$log" 2>&1; then
        [ $VERBOSE = 1 ] && { echo "ok: $name"; cat "$log"; }
        return 0
    fi
    failures=$((failures + 1))
    echo "FAIL: $name"
    echo "  command: $*"
    sed 's/^/  | /' "$log" | head -60
    return 1
}

# Dummy stubgen outputs so that OPENR/core_macro.h (which includes "entry.h")
# can be compiled alone.
mkdir -p "$WORK/stubgen"
cat > "$WORK/stubgen/def.h" <<'EOF'
#ifndef _def_h_DEFINED
#define _def_h_DEFINED
const char* const objectName = "Check";
const int numOfSubject = 1;
const int numOfObserver = 1;
const char* const subjectService[numOfSubject] = { "Check.Out.char.S" };
const char* const observerService[numOfObserver] = { "Check.In.char.O" };
const int sbjOut = 0;
const int obsIn = 0;
#endif
EOF
cat > "$WORK/stubgen/entry.h" <<'EOF'
#ifndef _entry_h_DEFINED
#define _entry_h_DEFINED
#include <Types.h>
#include "def.h"
const int numOfHook = 4;
const Selector Entry_Hook[numOfHook] = { 0, 1, 2, 3 };
const Selector Entry_Control[numOfSubject] = { 4 };
const Selector Entry_Ready[numOfSubject] = { 5 };
const Selector Entry_Connect[numOfObserver] = { 6 };
const Selector Entry_Notify[numOfObserver] = { 7 };
const longword numOfBasicEntries = 8;
#endif
EOF

HEADERS=$(cd "$INC" && find . -name '*.h' | sed 's|^\./||' | LC_ALL=C sort)
nheaders=$(echo "$HEADERS" | wc -l)

# ---------------------------------------------------------------------------
# 1. every header alone
# ---------------------------------------------------------------------------
echo "== 1. each header alone (C++: $CXX ${CXXFLAGS[*]})"
for h in $HEADERS; do
    printf '#include <%s>\nint openr_check_dummy;\n' "$h" > "$WORK/one.cc"
    run "alone: $h" "$CXX" "${CXXFLAGS[@]}" -fsyntax-only -I"$WORK/stubgen" "${INCS[@]}" "$WORK/one.cc"
done

# Headers that must also be usable from C.
C_HEADERS="Types.h SystemError.h apsys.h R4000/FixedPtr.h WellknownOID.h OID.h TID.h
MCOOPTypes.h SystemTime.h Time_a.h TimeEventInfo.h EventID.h SystemResource.h
MailerError.h DownloaderError.h MCOOPError.h MCOOP.h ObjectEntryTable.h dirent.h"
echo "== 1b. C headers (C: $CC ${CFLAGS[*]})"
for h in $C_HEADERS; do
    printf '#include <%s>\nint openr_check_dummy;\n' "$h" > "$WORK/one.c"
    run "C alone: $h" "$CC" "${CFLAGS[@]}" -fsyntax-only "${INCS[@]}" "$WORK/one.c"
done
cat > "$WORK/centry.c" <<'EOF'
#include <Types.h>
#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <apsys.h>
struct Msg { int x; };
void Handler(struct Msg* m) { (void)m; Exit(); }
GEN_ENTRY(HandlerEntry, Handler);
GEN_ENTRY(PrologueEntry, Prologue);
ObjectEntry ObjectEntryTable[] = {
    { 0, (Entry)HandlerEntry },
    { UNDEF, (Entry) ENTRY_UNDEF }
};
int main(void) { printf("%u %d\n", (unsigned)sizeof(longword), sSUCCESS); return 0; }
EOF
run "C: GEN_ENTRY and entry table" "$CC" "${CFLAGS[@]}" -c "${INCS[@]}" "$WORK/centry.c" -o "$WORK/centry.o"

# ---------------------------------------------------------------------------
# 2. include guards, and no out-of-line definitions in headers
# ---------------------------------------------------------------------------
echo "== 2. every header twice in one unit; two units linked together"
{
    for h in $HEADERS; do printf '#include <%s>\n' "$h"; done
    for h in $HEADERS; do printf '#include <%s>\n' "$h"; done
    echo 'int openr_twice;'
} > "$WORK/twice.cc"
run "every header twice" "$CXX" "${CXXFLAGS[@]}" -fsyntax-only -I"$WORK/stubgen" "${INCS[@]}" "$WORK/twice.cc"

for u in a b; do
    {
        for h in $HEADERS; do printf '#include <%s>\n' "$h"; done
        # use a few inline/template facilities so that they are instantiated
        cat <<EOF
int unit_$u()
{
    OList<int, 4> l;
    l.PushBack(1);
    OShmPtr<int> p;
    OTime t(0, 9);
    IPAddress a(10, 0, 1, 100);
    char buf[16];
    a.GetAsString(buf);
    OFbkImageInfo info;
    info.type = odataFBK_YCrCb_HPF; info.width = 4; info.height = 4;
    byte img[6 * 4 * 4];
    OFbkImage im(&info, img, ofbkimageBAND_Y);
    EtherMACAddress mac(2, 0, 0, 0, 0, 1);
    HWAddress hw;
    SystemTime st(1, 2);
    RelativeTime rt = ConvertToRelativeTime(st + st);
    return l.GetSize() + (int)t.GetClock() + im.Width() + (int)mac.IsMulticast()
        + (int)hw.IsBroadcast() + (int)rt.sec + (int)degrees(1.0) + oradians(1.0)
        + (p.IsValid() ? 1 : 0) + (OID().IsValid() ? 1 : 0) + (int)EtherStatusString(ETHER_OK)[0];
}
EOF
    } > "$WORK/unit_$u.cc"
    run "unit $u with every header" "$CXX" "${CXXFLAGS[@]}" -c -I"$WORK/stubgen" "${INCS[@]}" \
        "$WORK/unit_$u.cc" -o "$WORK/unit_$u.o"
done
run "link two units including every header" "$CXX" -shared -o "$WORK/libtwo.so" \
    "$WORK/unit_a.o" "$WORK/unit_b.o"

# nothing in the SDK headers may define __mips__ (or other MIPS markers)
{
    for h in $HEADERS; do printf '#include <%s>\n' "$h"; done
} > "$WORK/macros.cc"
checks=$((checks + 1))
if "$CXX" "${CXXFLAGS[@]}" -dM -E -I"$WORK/stubgen" "${INCS[@]}" "$WORK/macros.cc" 2>/dev/null \
        | grep -E '#define (__mips__|__mips|_MIPSEL|__MIPSEL__|mips) ' ; then
    failures=$((failures + 1))
    echo "FAIL: a header defines a MIPS marker macro"
fi

# transitive visibility that real programs rely on (object-model 6 rules 2-4)
echo "== 2b. transitive visibility"
vis() {   # vis NAME HEADER BODY [extra flags]
    local name=$1 hdr=$2 body=$3; shift 3
    printf '#include <%s>\nint openr_vis_%s()\n{\n%s\n    return 0;\n}\n' "$hdr" "$name" "$body" \
        > "$WORK/vis_$name.cc"
    run "visibility: $name ($hdr)" "$CXX" "${CXXFLAGS[@]}" "$@" -fsyntax-only -I"$WORK/stubgen" "${INCS[@]}" \
        "$WORK/vis_$name.cc"
}
vis OObject OPENR/OObject.h '
    OReasonMessage rm(oreasonBOOT);
    OSystemEvent ev(rm.reason, rm.param, rm.paramSize);
    OPowerStatusMessage pm; pm.powerStatus.Set(orsbALL, obsbALL, 0, 0, 0, 0);
    ONotifyEvent ne; OReadyMessage rdy; OControlMessage cm; OConnectMessage com;
    OReadyEvent re(0, rdy.observerID, rdy.command);
    OConnectEvent ce(0, com.subName, com.command);
    RCRegion* r = ne.RCData(0);
    MemoryRegionID id; void* base;
    if (NewSharedMemoryRegion(4096, MEMPROTINFO_R, &id, &base) != sSUCCESS) return 1;
    DeleteRegion(malloc(4));
    OSYSPRINT(("%d %d %p %d\n", (int)strlen("x"), isdigit(0x31), (void*)r, atoi("1")));
    printf("%s", ev.Param() ? "" : ""); (void)re; (void)ce; (void)cm;
    cout << endl;
    list<int> l;'
vis OSubject OPENR/OSubject.h '
    RCRegion* r = 0; ONotifyEvent ne; OReadyEvent re(0, ObserverID(), objcommCMD_ASSERT_READY);
    OSubject s; s.SetData(r); ObserverConstIterator it = s.begin(); (void)it; (void)ne; (void)re;'
vis OObserver OPENR/OObserver.h '
    OObserver o; ONotifyEvent ne; o.AssertReady(ne.SenderID()); RCRegion* r = ne.RCData(0);
    SubjectConstIterator it = o.begin(); (void)it; (void)r;'
vis OPENRAPI OPENR/OPENRAPI.h '
    OPowerStatus ps; OPENR::GetPowerStatus(&ps);
    OPrimitiveControl_SpeakerVolume vol(ospkvol25dB); MWIID m = mwiidINVALID;
    OCommandVectorData* v = 0; MemoryRegionID id; OPENR::NewCommandVectorData(1, &id, &v);
    OBootCondition bc(obcbPAUSE_SW); OTime t; OCPUInfo cpu; (void)vol; (void)m; (void)bc; (void)t; (void)cpu;'
vis OFbkImage OPENR/OFbkImage.h '
    OFbkImageVectorData* v = 0; OFbkImage im(v->GetInfo(ofbkimageLAYER_H), v->GetData(0), ofbkimageBAND_Y);
    (void)im; OCommandVectorData* c = 0; (void)c;'
vis ant ant.h '
    antStackRef ref("IPStack"); antEnvCreateSharedBufferMsg m(512); m.Call(ref, sizeof(m));
    antSharedBuffer b = m.buffer; b.Map(); void* p = b.GetAddress(); (void)p; Return();'
vis debug OPENR/ODebug.h '
    ODEBUG(printf("x")); DPRINTF(("%d", 1)); DPRINTF2(1, ("%d", 2)); PRINTF(("%d", 3));' -DOPENR_DEBUG
vis syslog OPENR/OSyslog.h '
    OSYSDEBUG(("%d", 1)); OSYSLOG4((osyslogINFO, "%d", 4)); OSYSLOG1((osyslogERROR, "x"));' \
    -DOPENR_DEBUG -DSYSMSGSHOW=1
# newlib's C library surface through any OPEN-R header (openr_newlib.h), also next to
# `using namespace std` and OPEN-R's byte
for h in Types.h OPENR/OObject.h MCOOP.h; do
vis "newlib_$(echo $h | tr '/.' '__')" "$h" '
    using namespace std;
    char s[16]; strcpy(s, "Ab"); strlwr(s); strupr(s); byte b = (byte)s[0];
    if (stricmp(s, "ab") || strnicmp(s, "A", 1) || !strcmpi(s, "x") || strncmpi(s, "a", 1)) return 1;
    char d[4]; strlcpy(d, s, sizeof d); strlcat(d, "c", sizeof d); bzero(d, 1); (void)index(s, 0);
    char* dup = strdup(s); free(dup); (void)strsep(&dup, ","); (void)strcasecmp(s, d);
    double x = sin(M_PI) + cos(M_PI_2) + sqrt(2.0) + fabs(-1.0) + tan(0.0) + atan2(1.0, 1.0)
        + M_TWOPI + M_SQRT3 + floor(0.5) + pow(2.0, 3.0) + hypot(3.0, 4.0) + log(1.0) + exp(0.0);
    double sn, cs; sincos(x, &sn, &cs);
    if (isnan(x) || !finite(x) || isinf(x) || isnanf(1.0f)) return 2;
    float f = atoff("1.5") + sinf(0.0f); int dp, sg; char buf[32]; ecvtbuf(1.5, 3, &dp, &sg, buf);
    (void)gcvtf(f, 3, buf); (void)ecvtf(f, 2, &dp, &sg); (void)fcvtf(f, 2, &dp, &sg);
    va_list* ap = 0; (void)ap; (void)b;
    if (INT_MAX < 0 || errno == -1 || abs(-1) != 1 || rand() < 0) return 3;
    qsort(s, 1, 1, 0);'
done
cat > "$WORK/newlib_link.cc" <<'EOF'
#include <OPENR/OObject.h>
int main()
{
    char s[16] = "MiXeD", d[4];
    int dp, sg;
    char b[32];
    printf("%s|", strlwr(s));
    printf("%s|", strupr(s));
    printf("%d %d %d|", stricmp("abc", "ABC"), strnicmp("abX", "ABy", 2), strcmpi("a", "B") < 0);
    printf("%d %s|", (int)strlcpy(d, "abcdef", sizeof d), d);
    printf("%d %s|", (int)strlcat(d, "zz", sizeof d), d);
    printf("%.2f %s ", atoff("2.25"), gcvtf(1.5f, 3, b));
    ecvtbuf(3.14159, 3, &dp, &sg, b);
    printf("%s %d\n", b, dp);
    return 0;
}
EOF
if run "newlib: link and run strlwr ... ecvtbuf from libOPENR's sources" "$CXX" "${CXXFLAGS[@]}" "${INCS[@]}" \
        "$WORK/newlib_link.cc" "$HERE"/cxx/OPENR/newlib/*.cc -o "$WORK/newlib_link"; then
    checks=$((checks + 1))
    got=$("$WORK/newlib_link")
    want='mixed|MIXED|0 0 1|6 abc|5 abc|2.25 1.5 314 1'
    if [ "$got" != "$want" ]; then
        failures=$((failures + 1))
        echo "FAIL: newlib functions: got '$got', want '$want'"
    fi
fi

# ---------------------------------------------------------------------------
# 3. sample-shaped programs
# ---------------------------------------------------------------------------
echo "== 3. sample-shaped programs"
S="$WORK/samples"
mkdir -p "$S"

# compile_obj DIR NAME [SYMBOL...] : compile every .cc of DIR (with DIR on the
# include path, as Sony's Makefiles' -I.),
# link them into DIR/NAME.so and check the exported entry symbols.
compile_obj() {
    local dir=$1 name=$2; shift 2
    local objs=() f o ok=1
    for f in "$dir"/*.cc; do
        o="${f%.cc}.o"
        run "$name: compile $(basename "$f")" \
            "$CXX" "${CXXFLAGS[@]}" "${ASMFLAG[@]}" -c -I"$dir" "${INCS[@]}" "$f" -o "$o" || ok=0
        objs+=("$o")
    done
    [ $ok = 1 ] || return 1
    run "$name: link shared object" "$CXX" -shared -o "$dir/$name.so" "${objs[@]}" || return 1
    local sym
    for sym in ObjectEntryTable "$@"; do
        checks=$((checks + 1))
        if ! nm -D --defined-only "$dir/$name.so" | awk '{print $3}' | grep -qx "$sym"; then
            failures=$((failures + 1))
            echo "FAIL: $name: symbol $sym is not exported by $name.so"
        fi
    done
}

# gen_stub DIR CLASS SBJ CTRLF READYF OBS CONNF NOTIFYF [EXTRA...]
# Writes def.h, entry.h, <CLASS>Stub.h and <CLASS>Stub.cc the way stubgen2
# does (object-model 1.2) for 1 subject, 1 observer and the given extras;
# an empty function name means "nofunc".
gen_stub() {
    local d=$1 cls=$2 sbj=$3 ctrlf=$4 readyf=$5 obs=$6 connf=$7 notifyf=$8; shift 8
    local extras=("$@") n i sel
    mkdir -p "$d"
    cat > "$d/def.h" <<EOF
#ifndef _def_h_DEFINED
#define _def_h_DEFINED

const char* const objectName = "$cls";
const int numOfSubject = 1;
const int numOfObserver = 1;

const char* const subjectService[numOfSubject] = {
    "$cls.$sbj.char.S"
};
const char* const observerService[numOfObserver] = {
    "$cls.$obs.char.O"
};

const int sbj$sbj = 0;
const int obs$obs = 0;

#endif
EOF
    {
        echo '#ifndef _entry_h_DEFINED'
        echo '#define _entry_h_DEFINED'
        echo '#include <Types.h>'
        echo '#include "def.h"'
        echo 'const int numOfHook = 4;'
        echo 'const Selector Entry_Hook[numOfHook] = { 0, 1, 2, 3 };'
        echo 'const Selector Entry_Control[numOfSubject] = { 4 };'
        echo 'const Selector Entry_Ready[numOfSubject] = { 5 };'
        echo 'const Selector Entry_Connect[numOfObserver] = { 6 };'
        echo 'const Selector Entry_Notify[numOfObserver] = { 7 };'
        echo 'const longword numOfBasicEntries = 8;'
        if [ ${#extras[@]} -gt 0 ]; then
            printf 'const Selector Extra_Entry[] = { '
            for ((i = 0; i < ${#extras[@]}; i++)); do
                [ $i -gt 0 ] && printf ', '
                printf '%d' $((8 + i))
            done
            echo ' };'
            for ((i = 0; i < ${#extras[@]}; i++)); do
                echo "const int entry${extras[$i]} = $i;"
            done
        fi
        echo '#endif'
    } > "$d/entry.h"
    {
        echo '#ifndef _stub_h_DEFINED'
        echo '#define _stub_h_DEFINED'
        echo '#ifndef OPENR_STUBGEN'
        echo '#define OPENR_STUBGEN'
        echo '#endif'
        echo '#include <OPENR/OPENR.h>'
        echo '#include <OPENR/OPENRMessages.h>'
        echo '#include <OPENR/ObjcommMessages.h>'
        echo '#include <OPENR/stub_macro.h>'
        echo '#include "def.h"'
        echo 'extern "C" {'
        for n in Init Start Stop Destroy; do echo "    StubFuncDeclare_Basic($n)"; done
        echo '    StubFuncDeclare_Subject(0)'
        echo '    StubFuncDeclare_Observer(0)'
        for n in "${extras[@]}"; do echo "    void _$n(void*);"; done
        echo '}'
        echo '#endif'
    } > "$d/${cls}Stub.h"
    {
        echo '#ifndef OPENR_STUBGEN'
        echo '#define OPENR_STUBGEN'
        echo '#endif'
        echo '#if defined(__GNUC__)'
        echo '#include <apsys.h>'
        echo '#endif'
        echo '#include <MCOOP.h>'
        echo '#include <ObjectEntryTable.h>'
        echo '#include <OPENR/stub_macro.h>'
        echo '#include "def.h"'
        echo '#include "entry.h"'
        echo "#include \"${cls}Stub.h\""
        echo "#include \"${cls}.h\""
        echo "$cls Self;"
        for n in Init Start Stop Destroy; do echo "StubFuncDefine_Basic($n)"; done
        if [ -n "$ctrlf" ]; then echo "StubFuncDefine_Control(0, $ctrlf)"; else echo 'StubFuncDefine_Control_nofunc(0)'; fi
        if [ -n "$readyf" ]; then echo "StubFuncDefine_Ready(0, $readyf)"; else echo 'StubFuncDefine_Ready_nofunc(0)'; fi
        if [ -n "$connf" ]; then echo "StubFuncDefine_Connect(0, $connf)"; else echo 'StubFuncDefine_Connect_nofunc(0)'; fi
        if [ -n "$notifyf" ]; then echo "StubFuncDefine_Notify(0, $notifyf)"; else echo 'StubFuncDefine_Notify_nofunc(0)'; fi
        for n in "${extras[@]}"; do
            echo "extern \"C\" void _$n(void* msg)"
            echo '{'
            echo "    Self.$n(msg);"
            echo '    Return();'
            echo '}'
        done
        echo '#if defined(__GNUC__)'
        i=0
        for n in Init Start Stop Destroy; do echo "GEN_ENTRY(_hookstub$i, _$n);"; i=$((i + 1)); done
        echo 'GEN_ENTRY(_controlstub0, _Control0);'
        echo 'GEN_ENTRY(_readystub0, _Ready0);'
        echo 'GEN_ENTRY(_connectstub0, _Connect0);'
        echo 'GEN_ENTRY(_notifystub0, _Notify0);'
        for n in "${extras[@]}"; do echo "GEN_ENTRY(_${n}stub, _$n);"; done
        echo 'GEN_ENTRY(PrologueEntry, Prologue);'
        echo 'ObjectEntry ObjectEntryTable[] = {'
        echo '    {0, (Entry)_hookstub0},'
        echo '    {1, (Entry)_hookstub1},'
        echo '    {2, (Entry)_hookstub2},'
        echo '    {3, (Entry)_hookstub3},'
        echo '    {4, (Entry)_controlstub0},'
        echo '    {5, (Entry)_readystub0},'
        echo '    {6, (Entry)_connectstub0},'
        echo '    {7, (Entry)_notifystub0},'
        sel=8
        for n in "${extras[@]}"; do echo "    {$sel, (Entry)_${n}stub},"; sel=$((sel + 1)); done
        echo '    {UNDEF, (Entry) ENTRY_UNDEF}'
        echo '};'
        echo '#else'
        echo '#error "the host build always takes the __GNUC__ branch"'
        echo '#endif'
    } > "$d/${cls}Stub.cc"
}

# --- 3a. HelloWorld with the hand-written stub (object-model 3) -------------
d="$S/HelloWorld"; mkdir -p "$d"
cat > "$d/HelloWorld.h" <<'EOF'
#ifndef HelloWorld_h_DEFINED
#define HelloWorld_h_DEFINED

#include <OPENR/OObject.h>

class HelloWorld : public OObject {
public:
    HelloWorld();
    virtual ~HelloWorld() {}

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);
};

#endif
EOF
cat > "$d/HelloWorld.cc" <<'EOF'
#include <OPENR/OSyslog.h>
#include "HelloWorld.h"

HelloWorld::HelloWorld()
{
}

OStatus HelloWorld::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoInit()\n"));
    return oSUCCESS;
}

OStatus HelloWorld::DoStart(const OSystemEvent& event)
{
    OSYSPRINT(("!!! Hello World !!!\n"));
    OSYSLOG1((osyslogINFO, "reason %d param %p size %d",
              (int)event.Reason(), event.Param(), (int)event.ParamSize()));
    return oSUCCESS;
}

OStatus HelloWorld::DoStop(const OSystemEvent& event)
{
    OSYSLOG1((osyslogERROR, "Bye Bye ..."));
    return oSUCCESS;
}

OStatus HelloWorld::DoDestroy(const OSystemEvent& event)
{
    return oSUCCESS;
}
EOF
cat > "$d/HelloWorldStub.cc" <<'EOF'
#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <apsys.h>
#include "HelloWorld.h"

HelloWorld Self;

extern "C" void InitStub(OReasonMessage* msg)
{
    OSystemEvent event(msg->reason, msg->param, msg->paramSize);
    Self.Init(event);
    Return();
}

extern "C" void StartStub(OReasonMessage* msg)
{
    OSystemEvent event(msg->reason, msg->param, msg->paramSize);
    Self.Start(event);
    Return();
}

extern "C" void StopStub(OReasonMessage* msg)
{
    OSystemEvent event(msg->reason, msg->param, msg->paramSize);
    Self.Stop(event);
    Return();
}

extern "C" void DestroyStub(OReasonMessage* msg)
{
    OSystemEvent event(msg->reason, msg->param, msg->paramSize);
    Self.Destroy(event);
    Return();
}

GEN_ENTRY(InitEntry, InitStub);
GEN_ENTRY(StartEntry, StartStub);
GEN_ENTRY(StopEntry, StopStub);
GEN_ENTRY(DestroyEntry, DestroyStub);
GEN_ENTRY(PrologueEntry, Prologue);

ObjectEntry ObjectEntryTable[] = {
    {oentryINIT,    (Entry)InitEntry},
    {oentrySTART,   (Entry)StartEntry},
    {oentrySTOP,    (Entry)StopEntry},
    {oentryDESTROY, (Entry)DestroyEntry},
    {UNDEF,         (Entry) ENTRY_UNDEF}
};
EOF
compile_obj "$d" HelloWorld InitEntry StartEntry StopEntry DestroyEntry PrologueEntry

# --- 3b. MovingLegs7-shaped object: 1 subject (Control+Ready functions),
#         1 observer (Connect function), 1 extra (power status) --------------
d="$S/MovingLegs7"
gen_stub "$d" MovingLegs7 Move ControlMove Ready DummyObserver ConnectDummy "" UpdatePowerStatus
cat > "$d/MovingLegs7.h" <<'EOF'
#ifndef MovingLegs7_h_DEFINED
#define MovingLegs7_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

enum MovingLegs7State { MLS_IDLE, MLS_START, MLS_MOVING_TO_BROADBASE, MLS_STOP };

static const int NUM_JOINTS   = 12;
static const int NUM_COMMAND_VECTOR = 2;

class MovingLegs7 : public OObject {
public:
    MovingLegs7();
    virtual ~MovingLegs7() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    OStatus ControlMove(const OControlEvent& event);
    void    Ready(const OReadyEvent& event);
    OStatus ConnectDummy(const OConnectEvent& event);
    void    UpdatePowerStatus(void* msg);

private:
    void OpenPrimitives();
    void NewCommandVectorData();
    void SetJointGain();
    MovingLegs7State MoveToBroadBase();
    RCRegion* FindFreeRegion();

    static const double BROADBASE_ANGLE[];
    static const double TILT_INIT = -10.0;     // in-class static const double (gcc 3.3)
    static const int    NUM_FRAMES = 16;

    MovingLegs7State movingLegsState;
    OPrimitiveID     jointID[NUM_JOINTS];
    RCRegion*        region[NUM_COMMAND_VECTOR];
    int              phase;
};

#endif
EOF
cat > "$d/MovingLegs7.cc" <<'EOF'
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MovingLegs7.h"

static const char* const JOINT_LOCATOR[] = {
    "PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2-Joint2:22", "PRM:/r2/c1/c2/c3-Joint2:23",
    "PRM:/r4/c1-Joint2:41", "PRM:/r4/c1/c2-Joint2:42", "PRM:/r4/c1/c2/c3-Joint2:43",
    "PRM:/r3/c1-Joint2:31", "PRM:/r3/c1/c2-Joint2:32", "PRM:/r3/c1/c2/c3-Joint2:33",
    "PRM:/r5/c1-Joint2:51", "PRM:/r5/c1/c2-Joint2:52", "PRM:/r5/c1/c2/c3-Joint2:53"
};

const double MovingLegs7::BROADBASE_ANGLE[] = {
    0, 10, 30, 0, 10, 30, -115, 10, 30, -115, 10, 30
};

MovingLegs7::MovingLegs7() : movingLegsState(MLS_IDLE), phase(0)
{
    for (int i = 0; i < NUM_JOINTS; i++) jointID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus MovingLegs7::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();
    OPENR::SetMotorPower(opowerON);

    OPowerStatus observationStatus;
    observationStatus.Set(orsbALL, obsbALL,
                          opsoREMAINING_CAPACITY_NOT_NOTIFY,
                          opsoTEMPERATURE_NOT_NOTIFY,
                          opsoTIME_DIF_NOT_NOTIFY,
                          opsoVOLUME_NOT_NOTIFY);
    OServiceEntry entry(myOID_, Extra_Entry[entryUpdatePowerStatus]);
    OStatus result = OPENR::ObservePowerStatus(observationStatus, entry);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d", "MovingLegs7::DoInit()",
                  "OPENR::ObservePowerStatus() FAILED", result));
    }
    return oSUCCESS;
}

OStatus MovingLegs7::DoStart(const OSystemEvent& event)
{
    if (subject[sbjMove]->IsReady() == true) {
        movingLegsState = MLS_START;
    }
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus MovingLegs7::DoStop(const OSystemEvent& event)
{
    movingLegsState = MLS_IDLE;
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus MovingLegs7::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

OStatus MovingLegs7::ControlMove(const OControlEvent& event)
{
    OSYSPRINT(("control %d %s add=%d\n", event.SbjIndex(), event.SubName(),
               (int)event.IsAddObserver()));
    return oSUCCESS;
}

OStatus MovingLegs7::ConnectDummy(const OConnectEvent& event)
{
    return event.IsConnect() ? oSUCCESS : oFAIL;
}

void MovingLegs7::Ready(const OReadyEvent& event)
{
    if (event.IsDeassert()) return;
    if (movingLegsState == MLS_START) {
        SetJointGain();
        movingLegsState = MoveToBroadBase();
    }
}

void MovingLegs7::UpdatePowerStatus(void* msg)
{
    OPowerStatusMessage* pmsg = (OPowerStatusMessage*)msg;
    if (pmsg->powerStatus.robotStatus & (orsbPAUSE | orsbBATTERY_CAPACITY_LOW)) {
        OServiceEntry entry(myOID_, Extra_Entry[entryUpdatePowerStatus]);
        OPENR::UnobservePowerStatus(entry);
        OPENR::SetMotorPower(opowerOFF);
        OBootCondition bootCondition(obcbPAUSE_SW);
        OPENR::Shutdown(bootCondition);
    }
    pmsg->powerStatus.Print();
}

void MovingLegs7::OpenPrimitives()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d", "MovingLegs7::DoInit()",
                      "OPENR::OpenPrimitive() FAILED", result));
        }
    }
}

void MovingLegs7::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;
    OCommandInfo*       info;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        result = OPENR::NewCommandVectorData(NUM_JOINTS, &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d", "MovingLegs7::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
        }
        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);
        cmdVecData->SetNumData(NUM_JOINTS);
        for (int j = 0; j < NUM_JOINTS; j++) {
            info = cmdVecData->GetInfo(j);
            info->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
    }
}

void MovingLegs7::SetJointGain()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OPENR::EnableJointGain(jointID[i]);
        OPENR::SetJointGain(jointID[i], 0x10, 0x04, 0x01, 0x0e, 0x02, 0x0f);
    }
}

MovingLegs7State MovingLegs7::MoveToBroadBase()
{
    RCRegion* rgn = FindFreeRegion();
    if (rgn == 0) return movingLegsState;
    OCommandVectorData* cmdVecData = (OCommandVectorData*)rgn->Base();
    for (int i = 0; i < NUM_JOINTS; i++) {
        OJointValue current;
        OPENR::GetJointValue(jointID[i], &current);
        double start = degrees(current.value / 1000000.0);
        double delta = BROADBASE_ANGLE[i] - start;
        OCommandInfo* info = cmdVecData->GetInfo(i);
        info->Set(odataJOINT_COMMAND2, jointID[i], NUM_FRAMES);
        OCommandData* data = cmdVecData->GetData(i);
        OJointCommandValue2* jval = (OJointCommandValue2*)data->value;
        for (int j = 0; j < NUM_FRAMES; j++) {
            jval[j].value = oradians(start + delta * (j + 1) / NUM_FRAMES + TILT_INIT * 0);
        }
    }
    subject[sbjMove]->SetData(rgn);
    subject[sbjMove]->NotifyObservers();
    printf("phase %d numData %u\n", phase++, cmdVecData->vectorInfo.numData);
    return MLS_MOVING_TO_BROADBASE;
}

RCRegion* MovingLegs7::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i]->NumberOfReference() == 1) return region[i];
    }
    return 0;
}
EOF
compile_obj "$d" MovingLegs7 _hookstub0 _controlstub0 _readystub0 _connectstub0 _notifystub0 \
    _UpdatePowerStatusstub PrologueEntry _Init _Control0 _UpdatePowerStatus

# --- 3c. sensor / camera observer: Notify function, AddReference ------------
d="$S/SensorObserver7"
gen_stub "$d" SensorObserver7 DummySubject "" "" Sensor "" NotifySensor
cat > "$d/SensorObserver7.h" <<'EOF'
#ifndef SensorObserver7_h_DEFINED
#define SensorObserver7_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class SensorObserver7 : public OObject {
public:
    SensorObserver7();
    virtual ~SensorObserver7() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void NotifySensor(const ONotifyEvent& event);

private:
    void PrintJoint(OSensorFrameVectorData* sensorVec, int index);
    void LookAtImage(OFbkImageVectorData* imageVec);

    bool         initSensorIndex;
    OPrimitiveID headTilt;
    int          headTiltIdx;
    RCRegion*    kept;
    list<int>    history;      // unqualified list (Sony's global using-declaration)
};

#endif
EOF
cat > "$d/SensorObserver7.cc" <<'EOF'
#include <OPENR/OPENRAPI.h>
#include <OPENR/OFbkImage.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SensorObserver7.h"

SensorObserver7::SensorObserver7()
    : initSensorIndex(false), headTilt(oprimitiveID_UNDEF), headTiltIdx(-1), kept(0)
{
}

OStatus SensorObserver7::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    observer[obsSensor]->SetBufCtrlParam(0, 1, 8);
    OPENR::OpenPrimitive("PRM:/r1/c1-Joint2:11", &headTilt);
    return oSUCCESS;
}

OStatus SensorObserver7::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus SensorObserver7::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus SensorObserver7::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void SensorObserver7::NotifySensor(const ONotifyEvent& event)
{
    OSensorFrameVectorData* sensorVec = (OSensorFrameVectorData*)event.Data(0);
    if (!initSensorIndex) {
        for (int i = 0; i < (int)sensorVec->vectorInfo.numData; i++) {
            OSensorFrameInfo* info = sensorVec->GetInfo(i);
            if (info->primitiveID == headTilt) headTiltIdx = i;
        }
        initSensorIndex = true;
    }
    if (headTiltIdx >= 0) PrintJoint(sensorVec, headTiltIdx);

    OSensorFrameData* data = sensorVec->GetData(0);
    OSensorValue* values = data->frame;
    OJointValue* jvals = (OJointValue*)values;      // reinterpreted as in samples
    OJointValue copy[4];
    memcpy(copy, jvals, 4 * sizeof(OJointValue));
    if (copy[0].signal == osensorframeINVALID_SIGNAL) return;

    if (kept != 0) kept->RemoveReference();
    kept = event.RCData(0);
    if (kept != 0) kept->AddReference();
    history.push_back(event.NumOfData());

    observer[event.ObsIndex()]->AssertReady(event.SenderID());
}

void SensorObserver7::PrintJoint(OSensorFrameVectorData* sensorVec, int index)
{
    OSensorFrameInfo* info = sensorVec->GetInfo(index);
    OSensorFrameData* data = sensorVec->GetData(index);
    for (int i = 0; i < (int)info->numFrames; i++) {
        OJointValue* jv = (OJointValue*)&data->frame[i];
        OSYSPRINT(("[%2d] frame %d value %7.2f signal %d pwm %d ref %7.2f refsig %d\n",
                   index, (int)(info->frameNumber + i),
                   degrees(jv->value / 1000000.0), jv->signal, jv->pwmDuty,
                   degrees(jv->refValue / 1000000.0), jv->refSignal));
    }
}

void SensorObserver7::LookAtImage(OFbkImageVectorData* imageVec)
{
    OFbkImageInfo* info = imageVec->GetInfo(ofbkimageLAYER_H);
    byte* data = imageVec->GetData(ofbkimageLAYER_H);
    OFbkImage yImage(info, data, ofbkimageBAND_Y);
    OFbkImage cdtImage(imageVec->GetInfo(ofbkimageLAYER_C),
                       imageVec->GetData(ofbkimageLAYER_C), ofbkimageBAND_CDT);
    int sum = 0;
    for (int y = 0; y < yImage.Height() - 1; y++)
        for (int x = 0; x < yImage.Width(); x++) sum += yImage.Pixel(x, y);
    if (cdtImage.ColorFrequency(ocdtCHANNEL0) >= 10) sum++;
    OSYSPRINT(("fc %d sum %d frame %u\n", yImage.FieldCounter(), sum, info->frameNumber));
}
EOF
compile_obj "$d" SensorObserver7 _notifystub0 _Notify0 PrologueEntry

# --- 3d. network object (EchoServer-shaped) ---------------------------------
d="$S/EchoServer"
gen_stub "$d" EchoServer DummySubject "" "" DummyObserver "" "" ListenCont SendCont ReceiveCont CloseCont
cat > "$d/EchoServer.h" <<'EOF'
#ifndef EchoServer_h_DEFINED
#define EchoServer_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include "def.h"

#define ECHOSERVER_CONNECTION_MAX  1
#define ECHOSERVER_BUFFER_SIZE     512
#define ECHOSERVER_PORT            54321

enum ConnectionState { CONNECTION_CLOSED, CONNECTION_LISTENING, CONNECTION_CONNECTED,
                       CONNECTION_SENDING, CONNECTION_RECEIVING, CONNECTION_CLOSING };

struct Connection {
    antModuleRef    endpoint;
    ConnectionState state;
    antSharedBuffer sendBuffer;
    byte*           sendData;
    int             sendSize;
    antSharedBuffer recvBuffer;
    byte*           recvData;
    int             recvSize;
};

class EchoServer : public OObject {
public:
    EchoServer();
    virtual ~EchoServer() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void ListenCont (ANTENVMSG msg);
    void SendCont   (ANTENVMSG msg);
    void ReceiveCont(ANTENVMSG msg);
    void CloseCont  (ANTENVMSG msg);

private:
    OStatus Listen(int index);
    OStatus Send(int index);
    OStatus Receive(int index);
    OStatus Close(int index);
    OStatus InitTCPConnection(int index);
    void    Misc();

    antStackRef ipstackRef;
    Connection  connection[ECHOSERVER_CONNECTION_MAX];
};

#endif
EOF
cat > "$d/EchoServer.cc" <<'EOF'
#include <OPENR/OSyslog.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OCalendarTime.h>
#include <OPENR/OList.h>
#include <OPENR/ODataArchive.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <TCPEndpointMsg.h>
#include <UDPEndpointMsg.h>
#include <DNSEndpointMsg.h>
#include <ERA201D1.h>
#include "EchoServer.h"
#include "entry.h"

EchoServer::EchoServer()
{
    for (int i = 0; i < ECHOSERVER_CONNECTION_MAX; i++)
        connection[i].state = CONNECTION_CLOSED;
}

OStatus EchoServer::DoInit(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus EchoServer::DoStart(const OSystemEvent& event)
{
    ipstackRef = antStackRef("IPStack");
    for (int index = 0; index < ECHOSERVER_CONNECTION_MAX; index++) {
        OStatus result = InitTCPConnection(index);
        if (result != oSUCCESS) return oFAIL;
        Listen(index);
    }
    return oSUCCESS;
}

OStatus EchoServer::DoStop(const OSystemEvent& event)
{
    for (int index = 0; index < ECHOSERVER_CONNECTION_MAX; index++) {
        if (connection[index].state != CONNECTION_CLOSED) Close(index);
    }
    return oSUCCESS;
}

OStatus EchoServer::DoDestroy(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus EchoServer::Listen(int index)
{
    if (connection[index].state != CONNECTION_CLOSED) return oFAIL;

    antEnvCreateEndpointMsg tcpCreateMsg(EndpointType_TCP, ECHOSERVER_BUFFER_SIZE * 2);
    tcpCreateMsg.Call(ipstackRef, sizeof(tcpCreateMsg));
    if (tcpCreateMsg.error != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d", "EchoServer::Listen()",
                  "Can't create endpoint", tcpCreateMsg.error));
        return oFAIL;
    }
    connection[index].endpoint = tcpCreateMsg.moduleRef;

    TCPEndpointListenMsg listenMsg(connection[index].endpoint, IP_ADDR_ANY, ECHOSERVER_PORT);
    listenMsg.continuation = (void*)index;
    listenMsg.Send(ipstackRef, myOID_, Extra_Entry[entryListenCont], sizeof(listenMsg));
    connection[index].state = CONNECTION_LISTENING;
    return oSUCCESS;
}

void EchoServer::ListenCont(ANTENVMSG msg)
{
    TCPEndpointListenMsg* listenMsg = (TCPEndpointListenMsg*)antEnvMsg::Receive(msg);
    int index = (int)listenMsg->continuation;       // LP64: needs -fpermissive
    if (listenMsg->error != TCP_SUCCESS) {
        Close(index);
        return;
    }
    char addr[16];
    OSYSPRINT(("client %s:%d\n", listenMsg->fAddress.GetAsString(addr), listenMsg->fPort));
    connection[index].state = CONNECTION_CONNECTED;
    Receive(index);
}

OStatus EchoServer::Send(int index)
{
    TCPEndpointSendMsg sendMsg(connection[index].endpoint,
                               connection[index].sendData, connection[index].sendSize);
    sendMsg.continuation = (void*)index;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendCont], sizeof(TCPEndpointSendMsg));
    connection[index].state = CONNECTION_SENDING;
    return oSUCCESS;
}

void EchoServer::SendCont(ANTENVMSG msg)
{
    TCPEndpointSendMsg* sendMsg = (TCPEndpointSendMsg*)antEnvMsg::Receive(msg);
    int index = (int)(sendMsg->continuation);
    if (sendMsg->error != TCP_SUCCESS) { Close(index); return; }
    connection[index].state = CONNECTION_CONNECTED;
    Receive(index);
}

OStatus EchoServer::Receive(int index)
{
    TCPEndpointReceiveMsg receiveMsg(connection[index].endpoint,
                                     connection[index].recvData, 1, ECHOSERVER_BUFFER_SIZE);
    receiveMsg.continuation = (void*)index;
    receiveMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveCont], sizeof(receiveMsg));
    connection[index].state = CONNECTION_RECEIVING;
    return oSUCCESS;
}

void EchoServer::ReceiveCont(ANTENVMSG msg)
{
    TCPEndpointReceiveMsg* receiveMsg = (TCPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    int index = (int)(receiveMsg->continuation);
    if (receiveMsg->error != TCP_SUCCESS) { Close(index); return; }
    connection[index].sendSize = receiveMsg->sizeMin;
    memcpy(connection[index].sendData, connection[index].recvData, receiveMsg->sizeMin);
    OSYSPRINT(("%s", (char*)connection[index].recvData));
    Send(index);
}

OStatus EchoServer::Close(int index)
{
    TCPEndpointCloseMsg closeMsg(connection[index].endpoint);
    closeMsg.continuation = (void*)index;
    closeMsg.Send(ipstackRef, myOID_, Extra_Entry[entryCloseCont], sizeof(closeMsg));
    connection[index].state = CONNECTION_CLOSING;
    return oSUCCESS;
}

void EchoServer::CloseCont(ANTENVMSG msg)
{
    TCPEndpointCloseMsg* closeMsg = (TCPEndpointCloseMsg*)antEnvMsg::Receive(msg);
    int index = (int)(closeMsg->continuation);
    connection[index].state = CONNECTION_CLOSED;
    if (closeMsg->error == TCP_CONNECTION_CLOSED) Listen(index);
}

OStatus EchoServer::InitTCPConnection(int index)
{
    Connection* conn = &connection[index];

    antEnvCreateSharedBufferMsg sendBufferMsg(ECHOSERVER_BUFFER_SIZE);
    sendBufferMsg.Call(ipstackRef, sizeof(sendBufferMsg));
    if (sendBufferMsg.error != ANT_SUCCESS) return oFAIL;
    conn->sendBuffer = sendBufferMsg.buffer;
    conn->sendBuffer.Map();
    conn->sendData = (byte*)(conn->sendBuffer.GetAddress());

    antEnvCreateSharedBufferMsg recvBufferMsg(ECHOSERVER_BUFFER_SIZE);
    recvBufferMsg.Call(ipstackRef, sizeof(recvBufferMsg));
    if (recvBufferMsg.error != ANT_SUCCESS) return oFAIL;
    conn->recvBuffer = recvBufferMsg.buffer;
    conn->recvBuffer.Map();
    conn->recvData = (byte*)(conn->recvBuffer.GetAddress());
    return oSUCCESS;
}

struct Passwd { char user[16]; char pass[16]; };

// Other ANT / network / API shapes used by the network samples.
void EchoServer::Misc()
{
    // EchoClient: dotted string converted implicitly
    TCPEndpointConnectMsg connectMsg(connection[0].endpoint, IP_ADDR_ANY, IP_PORT_ANY,
                                     "10.0.1.2", ECHOSERVER_PORT);
    connectMsg.continuation = (void*)0;
    connectMsg.Send(ipstackRef, myOID_, Extra_Entry[entryListenCont], sizeof(connectMsg));

    // UDPEchoServer / NTP: bind via Call with the "wrong" size
    antEnvCreateEndpointMsg udpCreateMsg(EndpointType_UDP, 1024);
    udpCreateMsg.Call(ipstackRef, sizeof(udpCreateMsg));
    UDPEndpointBindMsg bindMsg(udpCreateMsg.moduleRef, IP_ADDR_ANY, 54321);
    bindMsg.Call(ipstackRef, sizeof(antEnvCreateEndpointMsg));
    UDPEndpointSendMsg udpSend(udpCreateMsg.moduleRef, IPAddress(10, 0, 1, 2), 123,
                               connection[0].sendData, 48);
    UDPEndpointReceiveMsg udpRecv(udpCreateMsg.moduleRef, connection[0].recvData, 48);
    UDPEndpointCloseMsg udpClose(udpCreateMsg.moduleRef);
    udpClose.Call(ipstackRef, sizeof(udpClose));
    if (udpRecv.error == UDP_SUCCESS && udpSend.error == UDP_FAIL) {
        char buf[16];
        OSYSPRINT(("%s %d\n", udpRecv.address.GetAsString(buf), udpRecv.port));
    }

    // NTP: IPAddress from a uint32 and OTime / OCalendarTime
    longword ntpSeconds = 3155673600U + 100;
    IPAddress server = (uint32)0x0a000102;
    OTime now(ntpSeconds - 3155673600U, 9);
    sbyte timeDif;
    OPENR::GetTimeDifference(&timeDif);
    OPENR::SetTime(now);
    OCalendarTime cal(now);
    char rfc[64];
    cal.RFC2822(rfc);
    OSYSPRINT(("%s %x\n", rfc, server.Address()));

    // DNSLookUp
    antEnvCreateEndpointMsg dnsCreateMsg(EndpointType_DNS, 16 * 1024);
    dnsCreateMsg.Call(ipstackRef, sizeof(dnsCreateMsg));
    DNSEndpointGetHostByNameMsg getHostMsg(dnsCreateMsg.moduleRef, "pool.ntp.org.");
    getHostMsg.continuation = (void*)0;
    getHostMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveCont], sizeof(getHostMsg));
    DNSEndpointGetServerAddressesMsg serverMsg(dnsCreateMsg.moduleRef);
    serverMsg.Call(ipstackRef, sizeof(serverMsg));
    if (serverMsg.error == DNS_SUCCESS && getHostMsg.n_address > 0) {
        char buf[16];
        OSYSPRINT(("%s\n", getHostMsg.host_address.GetAsString(buf)));
    }
    char line[128];
    gets(line);

    // ERA201D1Info
    antEnvInitGetParamMsg getParamMsg("ETHER_IP");
    getParamMsg.Call(ipstackRef, sizeof(getParamMsg));
    if (getParamMsg.error == ANT_SUCCESS && getParamMsg.paramType == antEnv_InitParam_String)
        OSYSPRINT(("ETHER_IP %s\n", getParamMsg.value.str));
    EtherDriverGetMACAddressMsg macMsg;
    if (ERA201D1_GetMACAddress(&macMsg) == ETHER_OK) cout << macMsg.address << endl;
    EtherDriverGetWLANSettingsMsg wlanMsg;
    if (ERA201D1_GetWLANSettings(&wlanMsg) == ETHER_OK && wlanMsg.rate == ETHER_WLAN_RATE_11MB)
        OSYSPRINT(("ESSID %s\n", wlanMsg.essid));
    EtherDriverGetWLANStatisticsMsg statMsg;
    ERA201D1_GetWLANStatistics(&statMsg);
    EtherDriverGetStatisticsMsg etherStat;
    ERA201D1_GetEtherStatistics(&etherStat);

    // shared buffer destruction
    antEnvDestroySharedBufferMsg destroyMsg(connection[0].sendBuffer);
    connection[0].sendBuffer.UnMap();
    destroyMsg.Call(ipstackRef, sizeof(destroyMsg));

    // TinyFTPD: OList of passwords, DeleteRegion of a malloc'ed block, isdigit
    OList<Passwd, 4> passwd;
    Passwd p;
    strcpy(p.user, "anonymous");
    while (passwd.PushBack(p) == otlSUCCESS) {}
    for (OList<Passwd, 4>::Iterator it = passwd.Begin(); it != passwd.End(); ++it)
        if (isdigit((*it).user[0])) break;
    char* block = (char*)malloc(16);
    DeleteRegion(block);
    OBootCondition reboot(obcbBOOT_TIMER, 0, obcbttRELATIVE);
    OPENR::Shutdown(reboot);
}
EOF
compile_obj "$d" EchoServer _ListenContstub _SendContstub _ReceiveContstub _CloseContstub PrologueEntry

# --- 3e. Crash-shaped: OObject.h + OSyslog.h only, kernel calls, MIPS asm ---
d="$S/Crash"; mkdir -p "$d"
cat > "$d/Crash.h" <<'EOF'
#ifndef Crash_h_DEFINED
#define Crash_h_DEFINED

#include <OPENR/OObject.h>

class Crash : public OObject {
public:
    Crash() {}
    virtual ~Crash() {}
    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);
private:
    void use_unusable_coprocessor();
    void write_readonly_region();
};

#endif
EOF
cat > "$d/Crash.cc" <<'EOF'
#include <OPENR/OSyslog.h>
#include <iostream>
#include "Crash.h"

using namespace std;

OStatus Crash::DoInit(const OSystemEvent& event)  { return oSUCCESS; }
OStatus Crash::DoStop(const OSystemEvent& event)  { return oSUCCESS; }
OStatus Crash::DoDestroy(const OSystemEvent& event) { return oSUCCESS; }

OStatus Crash::DoStart(const OSystemEvent& event)
{
    int n;
    cout << "select (0-5): ";
    cin >> n;
    printf("selected %d\n", n);
    if (n == 1) use_unusable_coprocessor();
    if (n == 2) write_readonly_region();
    return oSUCCESS;
}

void Crash::use_unusable_coprocessor()
{
    asm("mfc0 $2, $12");
}

void Crash::write_readonly_region()
{
    MemoryRegionID memID;
    void* baseAddr;
    sError result = NewSharedMemoryRegion(4096, MEMPROTINFO_R, &memID, &baseAddr);
    if (result != sSUCCESS) {
        OSYSLOG1((osyslogERROR, "NewSharedMemoryRegion() FAILED %d", result));
        return;
    }
    *(int*)baseAddr = 1;
    DeleteSharedMemoryRegion(memID);
}
EOF
cat > "$d/CrashStub.cc" <<'EOF'
#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <apsys.h>
#include "Crash.h"

Crash Self;

extern "C" void InitStub(OReasonMessage* msg)
{ OSystemEvent event(msg->reason, msg->param, msg->paramSize); Self.Init(event); Return(); }
extern "C" void StartStub(OReasonMessage* msg)
{ OSystemEvent event(msg->reason, msg->param, msg->paramSize); Self.Start(event); Return(); }
extern "C" void StopStub(OReasonMessage* msg)
{ OSystemEvent event(msg->reason, msg->param, msg->paramSize); Self.Stop(event); Return(); }
extern "C" void DestroyStub(OReasonMessage* msg)
{ OSystemEvent event(msg->reason, msg->param, msg->paramSize); Self.Destroy(event); Return(); }

GEN_ENTRY(InitEntry, InitStub);
GEN_ENTRY(StartEntry, StartStub);
GEN_ENTRY(StopEntry, StopStub);
GEN_ENTRY(DestroyEntry, DestroyStub);
GEN_ENTRY(PrologueEntry, Prologue);

ObjectEntry ObjectEntryTable[] = {
    {oentryINIT,    (Entry)InitEntry},
    {oentrySTART,   (Entry)StartEntry},
    {oentrySTOP,    (Entry)StopEntry},
    {oentryDESTROY, (Entry)DestroyEntry},
    {UNDEF,         (Entry) ENTRY_UNDEF}
};
EOF
compile_obj "$d" Crash InitEntry PrologueEntry

# --- 3f. legacy (real-world) code: pre-standard headers and gcc-3.3 habits --
d="$S/Legacy"; mkdir -p "$d"
cat > "$d/Legacy.cc" <<'EOF'
#include <iostream.h>
#include <fstream.h>
#include <iomanip.h>
#include <strstream.h>
#include <vector.h>
#include <list.h>
#include <map.h>
#include <set.h>
#include <hash_map.h>
#include <algo.h>
#include <function.h>
#include <stack.h>
#include <queue.h>
#include <new.h>
#include <dirent.h>
#include <sys/stat.h>
#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataArchive.h>
#include <OPENR/ObserverInfo.h>
#include <OPENR/OObserverVector.h>

using namespace std;

struct Header {            // file format overlay with longword fields
    longword magic;
    word     version;
    word     minor;
    longword n;
    slongword offset;
};

class Tuning {
public:
    static const double GAIN = 1.5;     // in-class static const double
    static const int    N = 4;
};

static byte table[256];

int legacy_main(int argc, char** argv)
{
    byte b = 1;                          // OPEN-R byte with using namespace std
    table[b] = b;
    vector<int> v;
    v.push_back(atoi("42"));
    list<byte> l;
    l.push_back(b);
    map<int, double> m;
    m[1] = Tuning::GAIN;
    set<int> s;
    s.insert(1);
    hash_map<int, int> hm;
    hm[3] = 4;
    sort(v.begin(), v.end(), less<int>());
    stack<int> st;
    st.push(1);
    queue<int> q;
    q.push(2);
    ostrstream os;
    os << setw(4) << hex << 255 << ends;
    ifstream in("/MS/OPEN-R/MW/CONF/NTP.CFG");
    ofstream out("/MS/OPEN-R/MW/DATA/P/LOG.TXT");
    out << "x" << endl;
    cerr << "err" << endl;

    char* p = (char*)malloc(10);
    strcpy(p, "9");
    if (isdigit(p[0]) && toupper('a') == 'A') printf("%s %d\n", p, (int)sizeof(Header));
    free(p);
    char line[80];
    gets(line);

    DIR* dir = opendir("/MS/OPEN-R");
    if (dir != 0) {
        struct dirent* e;
        while ((e = readdir(dir)) != 0) printf("%s\n", e->d_name);
        rewinddir(dir);
        closedir(dir);
    }
    struct stat sb;
    stat("/MS", &sb);

    for (int i = 0; i < 3; i++) {}
    asm("nop");
    return (int)sizeof(Header) + Tuning::N;
}
EOF
run "Legacy: compile Legacy.cc" "$CXX" "${CXXFLAGS[@]}" "${ASMFLAG[@]}" -c -I"$d" "${INCS[@]}" \
    "$d/Legacy.cc" -o "$d/Legacy.o"

# A hand-written stub (HelloWorld shape) under `using namespace std`, with a stub function
# called _Destroy like libstdc++'s std::_Destroy: GEN_ENTRY must still resolve it, and a
# C++ exception thrown by DoStart must stop at the entry (report, then abort), not unwind
# into the caller.
cat > "$WORK/throw_stub.cc" <<'EOF'
#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <apsys.h>
#include <OPENR/OObject.h>
#include <stdexcept>
#include <vector>
using namespace std;
class Thrower : public OObject {
public:
    virtual OStatus DoStart(const OSystemEvent&) { throw runtime_error("boom"); }
};
Thrower Self;
extern "C" void StartStub(OReasonMessage* msg)
{ OSystemEvent event(msg->reason, msg->param, msg->paramSize); Self.Start(event); Return(); }
extern "C" void _Destroy(OReasonMessage* msg)
{ OSystemEvent event(msg->reason, msg->param, msg->paramSize); Self.Destroy(event); Return(); }
GEN_ENTRY(StartEntry, StartStub);
GEN_ENTRY(DestroyEntry, _Destroy);
GEN_ENTRY(PrologueEntry, Prologue);
ObjectEntry ObjectEntryTable[] = {
    {oentrySTART, (Entry)StartEntry}, {oentryDESTROY, (Entry)DestroyEntry}, {UNDEF, (Entry) ENTRY_UNDEF}
};
int main()
{
    OReasonMessage m(oreasonBOOT);
    try { StartEntry(&m); } catch (...) { printf("exception escaped the entry\n"); }
    return 0;
}
EOF
if run "entry exceptions: hand-written stub with _Destroy under using namespace std" "$CXX" "${CXXFLAGS[@]}" \
        -I"$HERE/cxx" "${INCS[@]}" "$WORK/throw_stub.cc" "$HERE/cxx/mcoopstub/prologue.cc" \
        "$HERE/cxx/mcoopstub/host.cc" "$HERE/cxx/mcoopstub/mcoop.cc" "$HERE/cxx/OPENR/OObject.cc" \
        -ldl -o "$WORK/throw_stub"; then
    checks=$((checks + 1))
    "$WORK/throw_stub" > "$WORK/throw_stub.out" 2>&1
    rc=$?
    want='uncaught C++ exception std::runtime_error in StartStub: boom'
    if [ $rc -ne 134 ] || ! grep -qF "$want" "$WORK/throw_stub.out"; then
        failures=$((failures + 1))
        echo "FAIL: entry exceptions: exit $rc (want 134, SIGABRT), output:"
        sed 's/^/  | /' "$WORK/throw_stub.out"
    fi
fi

# --- 3g. the header-size facts that data files and samples depend on --------
d="$S/Layout"; mkdir -p "$d"
cat > "$d/layout.cc" <<'EOF'
#include <OPENR/OPENRAPI.h>
#include <OPENR/ObjcommMessages.h>
#include <ant.h>
#include <TCPEndpointMsg.h>
#include <OPENR/OList.h>
#include <stdio.h>
#define CHECK(c) do { if (!(c)) { printf("layout check failed: %s\n", #c); bad++; } } while (0)
int main()
{
    int bad = 0;
    CHECK(sizeof(longword) == 4 && sizeof(slongword) == 4 && sizeof(word) == 2);
    CHECK(sizeof(Selector) == 4 && sizeof(OStatus) == 4 && sizeof(MemoryRegionID) == 4);
    CHECK(sizeof(OID) == sizeof(void*));
    CHECK(OID().GetAddress() == (void*)0xffffffffUL);
    CHECK(sizeof(ODataVectorInfo) == 192);
    CHECK(offsetof(OCommandVectorData, info) == 192);
    CHECK(offsetof(OSensorFrameVectorData, info) == 192);
    CHECK(offsetof(OSoundVectorData, info) == 192);
    CHECK(offsetof(OFbkImageVectorData, info) == 192);
    CHECK(offsetof(OCdtVectorData, info) == 192);
    CHECK(sizeof(OCommandInfo) == 32 && sizeof(OSensorFrameInfo) == 32);
    CHECK(sizeof(OSoundInfo) == 64 && sizeof(OFbkImageInfo) == 32 && sizeof(OCdtInfo) == 144);
    CHECK(sizeof(OJointValue) == 16 && sizeof(OSensorValue) == 16);
    CHECK(sizeof(OJointCommandValue2) == 8 && sizeof(OCommandData) == 128);
    CHECK(sizeof(OPowerStatus) == 20);
    CHECK(sizeof(int32) == 4 && sizeof(uint32) == 4 && sizeof(int16) == 2);
    CHECK(oradians(120.0) == 2094395 && oradians(-119.0) == -2076941);
    CHECK(MAX_NUM_DATA == 13);
    CHECK(TCP_BUFFER_INVALID == 16 && TCP_CONNECTION_CLOSED == 2);
    CHECK(IPAddress(10, 0, 1, 100).Address() == 0x0A000164U);
    CHECK(omsgPOWER_STATUS == 1030 && omsgREADY_V22 == 261 && omsgNOTIFY_V22 == 262);
    CHECK(oDESIGNDATA_SIZE_ZERO == 4110 && oAGRUS_DIAG_NG == 275 && oBUSY == 33);
    OCdtInfo cdt;
    cdt.Init(1, ocdtCHANNEL0);
    cdt.Set(0, 0x22, 0x11, 0x44, 0x33);
    CHECK(cdt.table[0] == 0x44332211U && cdt.table[1] == ocdtINIT);
    OList<int, 2> ol;
    CHECK(ol.PushBack(1) == otlSUCCESS && ol.PushFront(0) == otlSUCCESS);
    CHECK(ol.PushBack(2) == otlOVERFLOW && ol.Front() == 0 && ol.Back() == 1);
    OList<int> ul;
    for (int i = 0; i < 100; i++) ul.PushBack(i);
    int sum = 0;
    for (OList<int>::Iterator it = ul.Begin(); it != ul.End(); it++) sum += *it;
    CHECK(sum == 4950 && ul.PopFront() == otlSUCCESS && ul.GetSize() == 99);
    return bad;
}
EOF
if run "layout: compile and link" "$CXX" "${CXXFLAGS[@]}" "${INCS[@]}" "$d/layout.cc" -o "$d/layout"; then
    run "layout: run" "$d/layout"
fi

# ---------------------------------------------------------------------------
echo
echo "headers checked: $nheaders"
echo "checks run: $checks"
if [ $failures -ne 0 ]; then
    echo "include-check: $failures failure(s)"
    exit 1
fi
echo "include-check: all checks passed"
exit 0
