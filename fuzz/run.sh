#!/usr/bin/env bash
# `make fuzz`: time-bounded fuzzing campaigns, one target after the other (fuzz/README.md).
#
#   records  AFL++ on build-fuzz/fuzz_record (the record reader, every format)
#   driver   AFL++ on build-fuzz/driver/seispulse (the namelist driver on one .nml file,
#            run in a scratch directory that holds the sample records)
#   python   atheris on fuzz/fuzz_python.py (records.read, sdof, newmark, pulses)
#
# Variables: FUZZ_SECONDS (per target, default 600), FUZZ_TARGETS (default
# "records driver python"), FUZZ_BUILDDIR (build-fuzz), FUZZ_OUT ($FUZZ_BUILDDIR/out),
# PYTHON (.venv/bin/python), PYBUILD (build/python: the f2py package for atheris).
# Prints per target: executions, exec/s, run time, paths, edges, crashes, hangs (> 10 s).
# Exit status 1 when a target found a crash or a hang (the inputs are under FUZZ_OUT);
# a fuzzer that cannot run here (no afl-fuzz, no atheris, a refusal of the system) is
# reported and skipped, status 0.
set -uo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$ROOT"
SECONDS_PER=${FUZZ_SECONDS:-600}
TARGETS=${FUZZ_TARGETS:-records driver python}
B=${FUZZ_BUILDDIR:-build-fuzz}
OUT=${FUZZ_OUT:-$ROOT/$B/out}
PY=${PYTHON:-$ROOT/.venv/bin/python}
PYBUILD=${PYBUILD:-$ROOT/build/python}
HANG_MS=10000

# AFL++ in containers and CI: no core_pattern or CPU governor demands, no core binding,
# no curses screen
export AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_SKIP_CPUFREQ=1 AFL_NO_AFFINITY=1
export AFL_NO_UI=1 AFL_QUIET=1 GFORTRAN_ERROR_BACKTRACE=0

found=0
summary=()

# Seeds, gathered at each run (never copies kept in git): the record files of fuzz/corpus
# and input/records; the inputs of input/*.nml but the four that take over 0.3 s; for
# atheris, the record seeds behind each selector byte of fuzz_python.py
SEEDS=$OUT/seeds
rm -rf "$SEEDS"
mkdir -p "$SEEDS/records" "$SEEDS/driver" "$SEEDS/python"
cp fuzz/corpus/records/* input/records/* "$SEEDS/records/"
for f in input/*.nml; do
    case $(basename "$f") in
    winkler_history.nml|winkler_map.nml|spectra_suite.nml|cylinder_roll_harmonic.nml) ;;
    *) cp "$f" "$SEEDS/driver/" ;;
    esac
done
for f in "$SEEDS"/records/*; do
    for sel in 0 1 2 3; do
        { printf "\\x0$sel\\x01\\x02\\x00"; cat "$f"; } > "$SEEDS/python/$sel-$(basename "$f")"
    done
done

stat_of() {  # stat_of FILE KEY -> value in AFL's fuzzer_stats
    sed -n "s/^$2 *: *//p" "$1" 2>/dev/null | head -n1
}

afl_target() {  # afl_target NAME CORPUS DICT WORKDIR INPUTFILE -- cmd...
    local name=$1 corpus=$2 dict=$3 work=$4 infile=$5
    shift 6
    local o=$OUT/$name log=$OUT/$name.log
    rm -rf "$o"
    mkdir -p "$OUT"
    local fopt=()
    [ -z "$infile" ] || fopt=(-f "$infile")
    echo "fuzz: $name: afl-fuzz for $SECONDS_PER s (log: $log)"
    (cd "$work" && afl-fuzz -i "$corpus" -o "$o" -x "$dict" -t "$HANG_MS" -m 4096 \
        -V "$SECONDS_PER" "${fopt[@]}" -- "$@") >"$log" 2>&1
    local rc=$? st=$o/default/fuzzer_stats
    if [ ! -f "$st" ]; then
        echo "fuzz: $name: afl-fuzz did not run here (exit $rc); skipped. Its last lines:"
        tail -n 8 "$log" | sed 's/\x1b\[[0-9;?]*[A-Za-z]//g'
        summary+=("$name: not run (afl-fuzz exit $rc, see $log)")
        return 0
    fi
    local execs eps rt paths edges total crashes hangs
    execs=$(stat_of "$st" execs_done); eps=$(stat_of "$st" execs_per_sec)
    rt=$(( $(stat_of "$st" last_update) - $(stat_of "$st" start_time) ))
    paths=$(stat_of "$st" corpus_count); edges=$(stat_of "$st" edges_found)
    total=$(stat_of "$st" total_edges)
    crashes=$(stat_of "$st" saved_crashes); hangs=$(stat_of "$st" saved_hangs)
    summary+=("$name: $execs executions, $eps exec/s, $rt s, $paths paths, $edges edges (map $total), $crashes crashes, $hangs hangs")
    if [ "${crashes:-0}" != 0 ] || [ "${hangs:-0}" != 0 ]; then
        found=1
        summary+=("  -> inputs: $o/default/crashes $o/default/hangs")
    fi
}

for t in $TARGETS; do
    case $t in
    records|driver)
        if ! command -v afl-fuzz >/dev/null 2>&1; then
            summary+=("$t: not run (no afl-fuzz: apt-get install afl++)")
            continue
        fi
        if [ ! -x "$B/fuzz_record" ] || [ ! -x "$B/driver/seispulse" ]; then
            summary+=("$t: not run (no instrumented build: fuzz/build.sh failed)")
            continue
        fi
        if [ "$t" = records ]; then
            afl_target records "$SEEDS/records" "$ROOT/fuzz/records.dict" "$ROOT" "" \
                -- "$ROOT/$B/fuzz_record" @@
        else
            # a scratch directory: the tables land in it, the seeds' records/ next to
            # the input file
            scratch=$(mktemp -d "${TMPDIR:-/tmp}/seispulse-fuzz-driver.XXXXXX")
            cp -r input/records "$scratch/records"
            afl_target driver "$SEEDS/driver" "$ROOT/fuzz/driver.dict" "$scratch" \
                "$scratch/input.nml" -- "$ROOT/$B/driver/seispulse" "$scratch/input.nml"
            rm -rf "$scratch"
        fi
        ;;
    python)
        if ! "$PY" -c 'import atheris' >/dev/null 2>&1; then
            summary+=("python: not run (no atheris in $PY: pip install atheris)")
            continue
        fi
        o=$OUT/python log=$OUT/python.log
        rm -rf "$o"; mkdir -p "$o/corpus" "$o/findings"
        cp "$SEEDS"/python/* "$o/corpus/"
        echo "fuzz: python: atheris for $SECONDS_PER s (log: $log)"
        PYTHONPATH=$PYBUILD "$PY" fuzz/fuzz_python.py -max_total_time="$SECONDS_PER" \
            -timeout=$((HANG_MS / 1000)) -rss_limit_mb=4096 -artifact_prefix="$o/findings/" \
            -print_final_stats=1 "$o/corpus" >"$log" 2>&1
        rc=$?
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n1)
        eps=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n1)
        rt=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -n1)
        cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n1 | cut -d' ' -f2)
        ft=$(grep -o 'ft: [0-9]*' "$log" | tail -n1 | cut -d' ' -f2)
        corp=$(grep -o 'corp: [0-9]*' "$log" | tail -n1 | cut -d' ' -f2)
        nfind=$(find "$o/findings" -type f | wc -l)
        summary+=("python: ${runs:-?} executions, ${eps:-?} exec/s, ${rt:-?} s, ${corp:-?} corpus, ${cov:-?} edges (cov), ${ft:-?} features, $nfind findings (exit $rc)")
        if [ "$rc" != 0 ] || [ "$nfind" != 0 ]; then
            found=1
            summary+=("  -> see $log and $o/findings")
        fi
        ;;
    *)
        echo "fuzz: unknown target '$t' (records, driver, python)" >&2
        exit 2
        ;;
    esac
done

echo "fuzz: summary ($SECONDS_PER s per target)"
for line in "${summary[@]}"; do echo "  $line"; done
exit "$found"
