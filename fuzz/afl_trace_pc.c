/* Edge coverage for AFL++ from GCC's -fsanitize-coverage=trace-pc (any GCC front end,
 * gfortran included), for when AFL++'s GCC plugin cannot load (a plugin built against
 * another build of the same GCC version refuses to: "GCC and plugin have incompatible
 * versions"). GCC calls __sanitizer_cov_trace_pc() at the start of every basic block;
 * the block's address, hashed, is the AFL location and (previous >> 1) xor (current) the
 * edge, as in AFL's own instrumentation. Link with /usr/lib/afl/afl-compiler-rt.o, which
 * maps the shared coverage map (__afl_area_ptr) and runs the fork server. This file
 * itself must be compiled WITHOUT -fsanitize-coverage. See fuzz/README.md. */
#include <stdint.h>

extern uint8_t *__afl_area_ptr;

/* AFL's default map: 2^16 bytes (MAP_SIZE); the runtime maps at least that much. */
#define FUZZ_MAP_MASK 0xFFFFu

static __thread uint32_t fuzz_prev_loc;

void __sanitizer_cov_trace_pc(void)
{
    uintptr_t pc = (uintptr_t)__builtin_return_address(0);
    uint32_t cur = (uint32_t)((pc ^ (pc >> 17)) * 0x9E3779B1u);
    cur = (cur ^ (cur >> 16)) & FUZZ_MAP_MASK;
    __afl_area_ptr[cur ^ fuzz_prev_loc]++;
    fuzz_prev_loc = cur >> 1;
}
