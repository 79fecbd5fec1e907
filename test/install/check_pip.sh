#!/usr/bin/env bash
# pip check: build the wheel with meson-python from the source tree and install it into a
# temp dir (pip --target), then import it from a directory outside the repository; and,
# when make has linked the build tree into the environment (seispulse-build.pth), import
# it from there without PYTHONPATH.
# --no-build-isolation: use the meson-python/numpy/meson/ninja of the environment (.venv);
# nothing is downloaded.
#
# usage: test/install/check_pip.sh   Environment: PYTHON (default: .venv/bin/python if
#        present, else python3), KEEP_TMP=1 to keep the temp dir.
# Prints one line per check: `ok   pip/<name>` or `FAIL pip/<name>: why`; exits 1 if any failed.
set -uo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
if [ -z "${PYTHON:-}" ]; then
    if [ -x "$root/.venv/bin/python" ]; then PYTHON=$root/.venv/bin/python; else PYTHON=python3; fi
fi
# ninja/meson of the same environment (meson-python looks for ninja on PATH)
PATH="$(dirname "$PYTHON"):$PATH"

work=$(mktemp -d "${TMPDIR:-/tmp}/seispulse-pip.XXXXXX") || exit 1
if [ "${KEEP_TMP:-0}" = 1 ]; then
    echo "pip: keeping $work"
else
    trap 'rm -rf "$work"' EXIT
fi
target=$work/site

nfail=0
ok() { printf 'ok   pip/%s\n' "$1"; }
fail() { printf 'FAIL pip/%s: %s\n' "$1" "$2"; nfail=$((nfail + 1)); }
tail_log() { tail -n "${2:-40}" "$1" | sed 's/^/    | /'; }
finish() { [ "$nfail" -eq 0 ] && exit 0 || exit 1; }

# build-dir outside the tree: nothing is left in the source directory
if ! (cd "$root" && "$PYTHON" -m pip install --no-build-isolation --no-deps \
        --disable-pip-version-check --no-cache-dir --target "$target" \
        --config-settings=build-dir="$work/build" .) >"$work/pip.log" 2>&1; then
    tail_log "$work/pip.log"
    fail install "pip install --no-build-isolation --target <tmp> . failed"
    finish
fi
ok install

# only the Python package (and its metadata) may be in the wheel: no lib/, include/, bin/
extra=$(cd "$target" && ls -A | grep -Ev '^(seispulse|seispulse-[^/]*\.dist-info|\.seispulse\.mesonpy\.libs)$')
if [ -n "$extra" ]; then
    (cd "$target" && find . -maxdepth 3 | sort | sed 's/^/    | /')
    fail contents "unexpected entries in the wheel: $(echo $extra)"
else
    ok contents
fi

cd "$work" || exit 1
out=$(PYTHONPATH="$target" PYTHONDONTWRITEBYTECODE=1 "$PYTHON" -c '
import sys
import seispulse, seispulse.pulse as p
assert seispulse.__file__.startswith(sys.argv[1]), seispulse.__file__
r = p.exp_pulse(0.25, 0.0)
assert abs(r.v - 0.0625) < 1e-15, r
print("ok", seispulse.__version__)
' "$target" 2>&1)
rc=$?
if [ $rc -ne 0 ] || [ "${out%% *}" != ok ]; then
    printf '%s\n' "$out" | tail -n 20 | sed 's/^/    | /'
    fail import "import from the installed wheel failed (exit $rc)"
else
    ok import
fi

# `make build|run|test` put seispulse-build.pth into the environment's site-packages
# (pylink): then its python imports seispulse from the build tree, from any directory.
site=$("$PYTHON" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
if [ -f "$site/seispulse-build.pth" ]; then
    built=$(head -n 1 "$site/seispulse-build.pth")
    out=$(cd "$work" && env -u PYTHONPATH PYTHONDONTWRITEBYTECODE=1 "$PYTHON" -c '
import sys
import seispulse, seispulse.pulse as p
assert seispulse.__file__.startswith(sys.argv[1]), seispulse.__file__
assert abs(p.exp_pulse(0.25, 0.0).v - 0.0625) < 1e-15
print("ok")
' "$built" 2>&1)
    rc=$?
    if [ $rc -ne 0 ] || [ "${out%% *}" != ok ]; then
        printf '%s\n' "$out" | tail -n 20 | sed 's/^/    | /'
        fail venv-import "the environment's python does not import seispulse from $built"
    else
        ok venv-import
    fi
fi

finish
