/* cases.c - the alignment trap in C (mipsel-linux-gcc): an int at 2 stops, a long at 4 goes,
 * a struct's double member at 4 stops. */
#include <stdio.h>
#include <stdlib.h>

struct TypeDescriptor { unsigned short kind, info; char name[1]; };
struct TypeMismatchData {
    const char* file;
    unsigned int line, column;
    const struct TypeDescriptor* type;
    unsigned char logAlignment, typeCheckKind;
};

/* gcc declares both handlers itself, as taking (void*, void*). */
void __ubsan_handle_type_mismatch_v1_abort(void* data, void* p)
{
    struct TypeMismatchData* d = data;
    printf("stopped %s at %lu mod 8\n", d->type->name, (unsigned long)p % 8);
    exit(3);
}

void __ubsan_handle_type_mismatch_v1(void* data, void* p)
{
    struct TypeMismatchData* d = data;
    printf("went on after %s at %lu mod 8\n", d->type->name, (unsigned long)p % 8);
}

struct Pose { int frame; double pan; };

static double store[8];

int main(int argc, char** argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 0;
    char* base = (char*)store;
    if (n == 1) *(volatile int*)(base + 2) = 1;
    if (n == 5) *(volatile long*)(base + 4) = 1;
    if (n == 11) ((struct Pose*)(base + 4))->pan = 1;
    printf("case %d went through\n", n);
    return 0;
}
