/*
 * checksum.c : plain C, compiled with mipsel-linux-gcc
 */

#include <Types.h>
#include "checksum.h"

longword
mtn_checksum(const slongword* words, longword n)
{
    longword sum = 0;
    longword i;

    for (i = 0; i < n; i++) {
        sum += (longword)words[i];
    }
    return sum;
}

int
mtn_udeg(slongword urad)
{
    /* 1 degree = 17453.29 micro-radians */
    double deg = (double)urad / 17453.2925;
    return (deg >= 0.0) ? (int)(deg + 0.5) : -(int)(-deg + 0.5);
}
