/*
 * Pixels.h : row helpers over image layers (C, callable from C++).
 */

#ifndef Pixels_h_DEFINED
#define Pixels_h_DEFINED

#ifdef __cplusplus
extern "C" {
#endif

int  SumRow(const void* row, int width);
void FillRow(void* row, int width, int step, unsigned char value);

#ifdef __cplusplus
}
#endif

#endif /* Pixels_h_DEFINED */
