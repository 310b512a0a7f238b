// mips-asm.cc - MIPS inline assembly the SDK's gcc plugin leaves out
// (cargo-openr/tests/cli/align_trap.rs): an output becomes 0, an in-out operand keeps its
// value, a `sync` stays a compiler barrier.
#include <stdio.h>

int main()
{
    unsigned count = 7, kept = 5;
    __asm__ __volatile__("mfc0 %0, $9" : "=r"(count));
    __asm__ __volatile__("addiu %0, %0, 1" : "+r"(kept));
    __asm__ __volatile__("sync" : : : "memory");
    printf("count %u kept %u\n", count, kept);
    return 0;
}
