/* A stand-in for Windows' bcryptprimitives.dll, for Wine older than 9.0,
 * which lacks it: the Rust standard library draws its random numbers from
 * its ProcessPrng (Windows 10 and later). `cargo xtask test` builds it with
 * MinGW and puts it beside the Windows test executables it runs under Wine.
 * It is never part of a program a student runs on Windows. */
#include <windows.h>
#include <ntsecapi.h>

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    return RtlGenRandom(data, (ULONG)length);
}
