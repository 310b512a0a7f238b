// gcvtf - newlib's float gcvt.
#include <Types.h>

extern "C" char* gcvtf(float value, int ndigit, char* buf)
{
    return gcvt((double)value, ndigit, buf);
}
