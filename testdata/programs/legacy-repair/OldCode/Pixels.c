/*
 * Pixels.c : row helpers over image layers, in C.
 *
 * The pointer walks the row as "unsigned char*" while it is kept as a
 * "void*": gcc 3.3 accepted a cast as an lvalue (((unsigned char*)p)++),
 * gcc 4.0 removed that extension.
 */

#include "Pixels.h"

int
SumRow(const void* row, int width)
{
    void* p = (void*)row;
    int sum = 0;
    int x;
    for (x = 0; x < width; x++) {
        sum += *(unsigned char*)p;
        ((unsigned char*)p)++;
    }
    return sum;
}

void
FillRow(void* row, int width, int step, unsigned char value)
{
    while (width > 0) {
        *((unsigned char*)row)++ = value;
        ((unsigned char*)row) += step - 1;
        width -= step;
    }
}
