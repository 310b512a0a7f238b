//
// Cycles.cc : the CPU's cycle counter (CP0 register 9, "Count"), for profiling.
//
// MIPS inline assembly written the GNU way (__asm__ __volatile__ with an
// output): the PC cannot run it. The SDK's gcc plugin leaves it out and its
// output is 0 (a plain asm("...") is blanked by the wrapper's -Dasm(...)=).
//

unsigned int
ReadCycles()
{
    unsigned int count;
    __asm__ __volatile__("mfc0 %0, $9" : "=r"(count));
    return count;
}
