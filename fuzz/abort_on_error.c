/* For the fuzzing builds only (fuzz/build.sh): a gfortran run-time error (-fcheck=all:
 * an index out of bounds, a bad substring; a failed ALLOCATE without stat=) ends the
 * program with exit status 2, which AFL++ cannot tell from the driver's exit status 2
 * on an input error. These definitions take the place of libgfortran's (the executable
 * comes first in symbol lookup): they print the message as libgfortran does, then
 * abort() -- SIGABRT, a crash for AFL++. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

static void report(const char *where, const char *kind, const char *message, va_list ap)
{
    if (where)
        fprintf(stderr, "%s\n", where);
    fprintf(stderr, "Fortran %s: ", kind);
    vfprintf(stderr, message, ap);
    fputc('\n', stderr);
    fflush(stderr);
    abort();
}

void _gfortran_runtime_error_at(const char *where, const char *message, ...)
{
    va_list ap;
    va_start(ap, message);
    report(where, "runtime error", message, ap);
    va_end(ap);
}

void _gfortran_runtime_error(const char *message, ...)
{
    va_list ap;
    va_start(ap, message);
    report(NULL, "runtime error", message, ap);
    va_end(ap);
}

void _gfortran_os_error_at(const char *where, const char *message, ...)
{
    va_list ap;
    va_start(ap, message);
    report(where, "operating system error", message, ap);
    va_end(ap);
}
