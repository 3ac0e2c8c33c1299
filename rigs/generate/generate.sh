#!/usr/bin/env bash
# Instructions per table entry of run-time table generation (`Spec::generate`
# of five curves, the sigmoid in the article's mode, the edge solver alone)
# and of the S-curve article's C function (gcc -O2, newlib's expf), on three
# cores in QEMU:
#   Cortex-M0  (thumbv6m-none-eabi,     QEMU microbit)
#   Cortex-M3  (thumbv7m-none-eabi,     QEMU lm3s6965evb)
#   Cortex-M4F (thumbv7em-none-eabihf,  QEMU mps2-an386)
# QEMU runs with -icount shift=0,sleep=off (one instruction = one ns of
# virtual time, deterministic); the firmware times each case with SysTick,
# calibrated on a loop of known instruction count (src/main.rs says how).
# Prints one table (rows: cases; columns: cores) and, per core, how the C
# function's table compares with the Rust article mode's. Fails (exit 1)
# when a run fails, does not end with `ok`, prints a figure that does not
# parse, or one above its bound in `most` below.
# Needs: the three rustup targets, qemu-system-arm, arm-none-eabi-gcc with
# newlib. Usage: bash generate.sh   (CORES="M4F" measures one core)
set -euo pipefail
cd "$(dirname "$0")"

out=target/generate
mkdir -p "$out"

read -r -a cores <<<"${CORES:-M0 M3 M4F}"
declare -A target=([M0]=thumbv6m-none-eabi [M3]=thumbv7m-none-eabi [M4F]=thumbv7em-none-eabihf)
declare -A machine=([M0]="-cpu cortex-m0 -machine microbit" [M3]="-cpu cortex-m3 -machine lm3s6965evb"
    [M4F]="-cpu cortex-m4 -machine mps2-an386")

# Bounds: the most instructions per entry of a case (its number, as the
# firmware prints it first in the label: 1 .. 8, 7b) on a core, as
# most[case,core]; a case without a bound is only checked to parse.
# For example: declare -A most=([7,M4F]=300 [6,M3]=12000)
declare -A most=()

status=0
for core in "${cores[@]}"; do
    t=${target[$core]:?unknown core $core (M0, M3 or M4F)}
    rm -f "$out/$core.txt" "$out/$core.err" "$out/$core.rows"
    cargo build --release --quiet --target "$t" || { echo "FAIL $core: the build failed"; exit 1; }
    elf=target/$t/release/stepper-profiles-generate
    # shellcheck disable=SC2086
    if ! timeout 300 qemu-system-arm ${machine[$core]} -nographic -semihosting-config enable=on,target=native \
        -icount shift=0,sleep=off -kernel "$elf" >"$out/$core.txt" 2>"$out/$core.err"; then
        echo "FAIL $core: qemu failed or timed out"
        cat "$out/$core.txt" "$out/$core.err"
        status=1
        continue
    fi
    if ! grep -q '^ok' "$out/$core.txt"; then
        echo "FAIL $core: the run did not end with ok"
        cat "$out/$core.txt"
        status=1
    fi
    # case|label|figure
    sed -n 's/^generate: \([0-9a-z]*\) \(.*\): \([^:]*\)$/\1|\2|\3/p' "$out/$core.txt" >"$out/$core.rows"
done

# The rows in the order the first core printed them; a label that differs
# on another core (fewer entries there) is printed below the table.
rows=""
for core in "${cores[@]}"; do
    [ -s "$out/$core.rows" ] && { rows="$out/$core.rows"; break; }
done
[ -n "$rows" ] || { echo "FAIL: no figures"; exit 1; }

echo "instructions per table entry (the whole table, its check included, over its entries)"
printf "%-94s" "case"
for core in "${cores[@]}"; do printf " %10s" "$core"; done
echo
notes=""
while IFS='|' read -r case label _; do
    printf "%-94s" "$case $label"
    for core in "${cores[@]}"; do
        line=$(awk -F'|' -v c="$case" '$1 == c' "$out/$core.rows" 2>/dev/null || true)
        figure=${line##*|}
        other=$(cut -d'|' -f2 <<<"$line")
        if [ -z "$line" ]; then
            printf " %10s" "-"
            echo "FAIL $core: no figure for case $case" >&2
            status=1
            continue
        fi
        printf " %10s" "$figure"
        [ "$other" = "$label" ] || notes+="  $core, case $case: $other"$'\n'
        if ! [[ $figure =~ ^[0-9]+\.[0-9][0-9]$ ]]; then
            echo "FAIL $core: case $case: figure '$figure' does not parse" >&2
            status=1
        elif [ -n "${most[$case,$core]:-}" ] && awk -v f="$figure" -v m="${most[$case,$core]}" 'BEGIN { exit !(f > m) }'; then
            echo "FAIL $core: case $case: $figure instructions per entry, more than ${most[$case,$core]}" >&2
            status=1
        fi
    done
    echo
done <"$rows"
[ -z "$notes" ] || printf "labels on other cores:\n%s" "$notes"

echo
for core in "${cores[@]}"; do
    sed -n "s/^\(calibration\|compare\): /$core \1: /p" "$out/$core.txt" 2>/dev/null || true
done
[ "$status" = 0 ] && echo "ok: every core ran every case"
exit "$status"
