// fcvtf - newlib's float fcvt (same static buffer as fcvt).
#include <Types.h>

extern "C" char* fcvtf(float value, int ndigit, int* decpt, int* sign)
{
    return fcvt((double)value, ndigit, decpt, sign);
}
