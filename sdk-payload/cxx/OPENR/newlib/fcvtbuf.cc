// fcvtbuf - newlib's fcvt into the caller's buffer (which, as with newlib, must hold all
// digits before the point, ndigit after it and a NUL).
#include <Types.h>

extern "C" char* fcvtbuf(double value, int ndigit, int* decpt, int* sign, char* buf)
{
    strcpy(buf, fcvt(value, ndigit, decpt, sign));
    return buf;
}
