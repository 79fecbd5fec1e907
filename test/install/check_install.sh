#!/usr/bin/env bash
# Install check: configure a separate build dir with --prefix=<temp dir>, `meson install`,
# then build test/install/hello.f90 (a program outside the tree doing `use seispulse`)
# against the installed library through pkg-config, shared and static, and run it.
#
# usage: test/install/check_install.sh [BUILDDIR]   (default: build-install, relative to
#        the repository root). Environment: MESON (default meson), FC (default gfortran),
#        KEEP_PREFIX=1 to keep the temporary prefix.
# Prints one line per check: `ok   install/<name>` or `FAIL install/<name>: why`;
# exits 1 if any check failed.
set -uo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
cd "$root" || exit 1

bdir=${1:-build-install}
MESON=${MESON:-meson}
FC=${FC:-gfortran}

work=$(mktemp -d "${TMPDIR:-/tmp}/seispulse-install.XXXXXX") || exit 1
prefix=$work/prefix
if [ "${KEEP_PREFIX:-0}" = 1 ]; then
    echo "install: keeping $work"
else
    trap 'rm -rf "$work"' EXIT
fi

nfail=0
ok() { printf 'ok   install/%s\n' "$1"; }
fail() { printf 'FAIL install/%s: %s\n' "$1" "$2"; nfail=$((nfail + 1)); }
# show the tail of a log file, indented, after a failure
tail_log() { tail -n "${2:-30}" "$1" | sed 's/^/    | /'; }

finish() {
    [ "$nfail" -eq 0 ] && exit 0 || exit 1
}

# --- configure + install -------------------------------------------------------------
# A configured dir not made by this script (e.g. the main build/) is never reconfigured.
marker=$bdir/meson-private/seispulse-install-check
if [ -f "$bdir/meson-private/coredata.dat" ] && [ ! -f "$marker" ]; then
    fail setup "refusing to reconfigure $bdir (not made by this script); give another dir"
    finish
fi
opts=(--prefix="$prefix" -Dpython_ext=disabled -Dtests=false)
if [ -f "$bdir/meson-private/coredata.dat" ]; then
    "$MESON" setup --reconfigure "$bdir" "${opts[@]}" >"$work/setup.log" 2>&1 \
        || "$MESON" setup --wipe "$bdir" "${opts[@]}" >"$work/setup.log" 2>&1
else
    "$MESON" setup "$bdir" "${opts[@]}" >"$work/setup.log" 2>&1
fi
if [ $? -ne 0 ]; then
    tail_log "$work/setup.log"
    fail setup "meson setup $bdir failed"
    finish
fi
touch "$marker"
ok setup

if ! "$MESON" install -C "$bdir" >"$work/install.log" 2>&1; then
    tail_log "$work/install.log"
    fail meson-install "meson install -C $bdir failed"
    finish
fi
ok meson-install

# --- installed layout -------------------------------------------------------------------
pc=$(find "$prefix" -name seispulse.pc -path '*/pkgconfig/*' | head -n 1)
libdir=$(find "$prefix" -name 'libseispulse.a' -printf '%h\n' | head -n 1)
why=""
[ -n "$pc" ] || why="$why no seispulse.pc;"
[ -n "$libdir" ] || why="$why no libseispulse.a;"
[ -n "$libdir" ] && ! ls "$libdir"/libseispulse.so* >/dev/null 2>&1 && why="$why no libseispulse.so;"
[ -f "$prefix/include/seispulse/seispulse.mod" ] || why="$why no include/seispulse/seispulse.mod;"
if [ -n "$why" ]; then
    (cd "$prefix" && find . -type f | sort | sed 's/^/    | /')
    fail layout "${why% ;}"
    finish
fi
ok layout

export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
if ! pkg-config --exists --print-errors seispulse >"$work/pc.log" 2>&1; then
    tail_log "$work/pc.log"
    fail pkg-config "pkg-config cannot use $pc"
    finish
fi
ok pkg-config

mkdir -p "$work/hello"
cp "$here/hello.f90" "$work/hello/"
cd "$work/hello" || exit 1

# run_hello NAME EXE [ENV...]: run it, expect last line `ok` and exit 0
run_hello() {
    local name=$1 exe=$2 out rc
    shift 2
    out=$(env "$@" "./$exe" 2>&1)
    rc=$?
    if [ $rc -ne 0 ] || [ "$(printf '%s\n' "$out" | tail -n 1)" != ok ]; then
        printf '%s\n' "$out" | tail -n 20 | sed 's/^/    | /'
        fail "$name" "./$exe exited $rc, last line not 'ok'"
        return 1
    fi
    return 0
}

# --- shared library -------------------------------------------------------------------
# shellcheck disable=SC2046  # word splitting of pkg-config output is intended
if ! "$FC" hello.f90 -o hello_shared $(pkg-config --cflags --libs seispulse) >build.log 2>&1; then
    tail_log build.log
    fail shared "compile/link of hello.f90 failed: $FC hello.f90 $(pkg-config --cflags --libs seispulse)"
elif ! deps=$(env LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ldd ./hello_shared) \
        || ! grep -q "libseispulse\.so.* => $libdir/" <<<"$deps"; then
    sed 's/^/    | /' <<<"$deps"
    fail shared "hello_shared does not load libseispulse.so from $libdir"
elif run_hello shared hello_shared LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"; then
    ok shared
fi

# --- static library -------------------------------------------------------------------
# pkg-config --static adds the private dependencies (LAPACK); -lseispulse is replaced by
# the archive itself, since with both libseispulse.so and .a present the linker prefers .so.
static_flags=()
for f in $(pkg-config --static --cflags --libs seispulse); do
    if [ "$f" = -lseispulse ]; then
        static_flags+=("$libdir/libseispulse.a")
    else
        static_flags+=("$f")
    fi
done
if ! "$FC" hello.f90 -o hello_static "${static_flags[@]}" >build-static.log 2>&1; then
    tail_log build-static.log
    fail static "compile/link of hello.f90 failed: $FC hello.f90 ${static_flags[*]}"
elif ! deps=$(ldd ./hello_static) || grep -q libseispulse <<<"$deps"; then
    sed 's/^/    | /' <<<"$deps"
    fail static "hello_static still needs libseispulse.so"
elif run_hello static hello_static; then
    ok static
fi

finish
