/*
 * Test harness only (never part of the FMU): a stand-in for Windows'
 * bcryptprimitives.dll, which Rust's standard library imports for
 * ProcessPrng (Windows 10 and later have it) and Wine 8 lacks. Placed beside
 * the test master under Wine, it forwards to RtlGenRandom (advapi32's
 * SystemFunction036).
 */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        ULONG chunk = length > 0x10000000 ? 0x10000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
