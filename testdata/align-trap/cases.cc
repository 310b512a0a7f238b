// cases.cc - which accesses the alignment trap stops (cargo-openr/tests/cli/align_trap.rs).
//
// Built by mipsel-linux-g++ like an object's code, run as a plain program: `cases N` makes
// access N at an address the PC's type does not want. The handlers below stand in for
// libmcoopstub's: they say which one gcc's code called, for which type, and end the
// program (the "abort" one never returns) or count and let the access go ahead.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct TypeDescriptor {
    unsigned short kind;
    unsigned short info;
    char           name[1];
};
struct TypeMismatchData {
    const char*           file;
    unsigned int          line, column;
    const TypeDescriptor* type;
    unsigned char         logAlignment;
    unsigned char         typeCheckKind;
};

// gcc declares both handlers itself, as taking (void*, void*).
extern "C" void __ubsan_handle_type_mismatch_v1_abort(void* data, void* p)
{
    TypeMismatchData* d = (TypeMismatchData*)data;
    printf("stopped %s at %lu mod 8\n", d->type->name, (unsigned long)p % 8);
    exit(3);
}

static int wentOn;

extern "C" void __ubsan_handle_type_mismatch_v1(void* data, void* p)
{
    TypeMismatchData* d = (TypeMismatchData*)data;
    if (wentOn++ == 0) printf("went on after %s at %lu mod 8\n", d->type->name, (unsigned long)p % 8);
}

struct Pair {
    long a;
    int  b;
};

struct Pose {
    int    frame;
    double pan;
};

struct Packed {
    int    frame;
    double pan;
} __attribute__((packed, aligned(4)));

struct Track {
    int    count;
    double pan[4];
};

struct Counter {
    unsigned long sum;
    void add(const unsigned char* p, int n)
    {
        for (int i = 0; i < n; i++) sum += p[i];
    }
};

// 8-byte aligned storage; `at(k)` is k bytes into it.
static double store[8];
static char* at(int k) { return (char*)store + k; }

int main(int argc, char** argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 0;
    memset(store, 0, sizeof(store));
    switch (n) {
    case 1: *(volatile int*)at(2) = 1; break;             // robot: address error
    case 2: *(volatile short*)at(1) = 1; break;           // robot: address error
    case 3: *(volatile float*)at(2) = 1; break;           // robot: address error
    case 4: *(volatile double*)at(4) = 1; break;          // robot: ldc1/sdc1 want 8
    case 5: *(volatile long*)at(4) = 1; break;            // robot: a 4-byte word, fine
    case 6: *(volatile long*)at(2) = 1; break;            // robot: a word at 2, address error
    case 7: *(volatile long long*)at(4) = 1; break;       // robot: two words, fine
    case 8: *(void* volatile*)at(4) = 0; break;           // robot: a 4-byte pointer, fine
    case 9: ((Pair*)at(4))->b = 1; break;                 // robot: a struct of words at 4, fine
    case 11: ((Pose*)at(4))->pan = 1; break;               // robot: sdc1 at 12, address error
    case 12: ((Pose*)at(4))->frame = 1; break;             // robot: sw at 4, fine
    case 13: ((Packed*)at(4))->pan = 1; break;             // robot: known 4-aligned, lw/sw: fine
    case 14: ((Track*)at(4))->pan[n - 13] = 1; break;      // robot: sdc1 at 12 + 8i, address error
    case 15: *(volatile long double*)at(4) = 1; break;     // robot: a double, sdc1 wants 8
    case 17: {                                            // an empty template: no MIPS, kept
        int sum = 0;
        for (int i = 0; i < 10; i++) {
            sum += i;
            __asm__ __volatile__("" : "+r"(sum) : : "memory");
        }
        printf("sum %d\n", sum);
        break;
    }
    case 10: {                                            // a loop through a member at 4
        unsigned char pixels[64];
        memset(pixels, 1, sizeof(pixels));
        Counter* c = (Counter*)at(4);
        c->sum = 0;
        for (int j = 0; j < 100; j++) c->add(pixels, sizeof(pixels));
        printf("sum %lu\n", c->sum);
        break;
    }
    }
    printf("case %d went through, the handler returned %d times\n", n, wentOn);
    return 0;
}
