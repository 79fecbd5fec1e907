#!/usr/bin/env bash
# Build the AFL++-instrumented library, driver and record harness in $FUZZ_BUILDDIR
# (default build-fuzz/) for fuzz/run.sh. gfortran is instrumented in one of two ways
# (fuzz/README.md):
#   plugin   AFL++'s GCC plugin (-fplugin=/usr/lib/afl/afl-gcc-pass.so), when it loads
#            into this gfortran;
#   trace-pc GCC's -fsanitize-coverage=trace-pc with fuzz/afl_trace_pc.c turning the
#            calls into AFL edge coverage (Debian 12's afl++ 4.04c plugin refuses the
#            gcc 12.2.0-14+deb12u1 compilers: "GCC and plugin have incompatible versions").
# Both link /usr/lib/afl/afl-compiler-rt.o (shared map, fork server). The code is built
# with -O1 -g -fcheck=all and fuzz/abort_on_error.c, so an out-of-bounds index or a
# failed allocation aborts (a crash for AFL++; gfortran alone exits with status 2).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$ROOT"
B=${FUZZ_BUILDDIR:-build-fuzz}
AFL_LIB=${AFL_LIB:-/usr/lib/afl}
MESON=${MESON:-$ROOT/.venv/bin/meson}
RT=$AFL_LIB/afl-compiler-rt.o
[ -f "$RT" ] || { echo "fuzz/build.sh: $RT missing (apt-get install afl++)" >&2; exit 1; }
mkdir -p "$B"

probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf 'program p\nend program p\n' > "$probe/p.f90"
if gfortran -fplugin="$AFL_LIB/afl-gcc-pass.so" -c "$probe/p.f90" -o "$probe/p.o" \
        >"$probe/log" 2>&1; then
    mode=plugin
    COV="-fplugin=$AFL_LIB/afl-gcc-pass.so"
    EXTRA=""
else
    mode=trace-pc
    COV="-fsanitize-coverage=trace-pc"
    gcc -O2 -c fuzz/afl_trace_pc.c -o "$B/afl_trace_pc.o"
    EXTRA="$ROOT/$B/afl_trace_pc.o"
fi
# a gfortran run-time error aborts (a crash for AFL++) instead of exit status 2
gcc -O2 -c fuzz/abort_on_error.c -o "$B/abort_on_error.o"
EXTRA="$EXTRA $ROOT/$B/abort_on_error.o"
echo "fuzz/build.sh: instrumentation: $mode ($COV)"
echo "$mode" > "$B/instrumentation"

FLAGS="-O1 -g -fcheck=all $COV"
LINK="$EXTRA $RT"
if [ ! -f "$B/build.ninja" ]; then
    AFL_QUIET=1 FFLAGS="$FLAGS" CFLAGS="-O1 -g $COV" LDFLAGS="$LINK" \
        "$MESON" setup "$B" -Dtests=false -Dpython_ext=disabled \
        -Dopenmp=disabled -Dbuildtype=plain >"$B/setup.log" 2>&1 \
        || { cat "$B/setup.log"; exit 1; }
fi
AFL_QUIET=1 "$MESON" compile -C "$B" seispulse:executable >"$B/compile.log" 2>&1 \
    || { cat "$B/compile.log"; exit 1; }
# the record harness, against the instrumented static library (seispulse.mod lies in
# the private directory of one of the two libraries)
moddir=$(dirname "$(find "$B" -name seispulse.mod -print -quit)")
AFL_QUIET=1 gfortran $FLAGS -I"$moddir" fuzz/fuzz_record.f90 -o "$B/fuzz_record" \
    "$B/libseispulse.a" $(pkg-config --libs lapack) $LINK
echo "fuzz/build.sh: $B/driver/seispulse and $B/fuzz_record built"
