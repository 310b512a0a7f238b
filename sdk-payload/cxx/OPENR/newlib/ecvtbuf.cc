// ecvtbuf - newlib's ecvt into the caller's buffer (ndigit digits and a NUL).
#include <Types.h>

extern "C" char* ecvtbuf(double value, int ndigit, int* decpt, int* sign, char* buf)
{
    char digits[400];   // glibc's ecvt_r wants room beyond ndigit + 1
    if (ecvt_r(value, ndigit, decpt, sign, digits, sizeof digits) != 0) digits[0] = '\0';
    strcpy(buf, digits);
    return buf;
}
