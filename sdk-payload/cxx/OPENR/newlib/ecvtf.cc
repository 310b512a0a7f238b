// ecvtf - newlib's float ecvt (same static buffer as ecvt).
#include <Types.h>

extern "C" char* ecvtf(float value, int ndigit, int* decpt, int* sign)
{
    return ecvt((double)value, ndigit, decpt, sign);
}
