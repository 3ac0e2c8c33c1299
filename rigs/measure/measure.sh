#!/usr/bin/env bash
# Instructions per step of a step interrupt's work on three cores, counted in
# QEMU's instruction trace (deterministic), with the players' flash:
#   Cortex-M0  (thumbv6m-none-eabi,     QEMU microbit)
#   Cortex-M3  (thumbv7m-none-eabi,     QEMU lm3s6965evb)
#   Cortex-M4F (thumbv7em-none-eabihf,  QEMU mps2-an386)
# Fails (exit 1) when, on any core, the player's mean in any phase of the
# per-step table is more than the bare load + 4, or the compressed player's
# (`Player::new(&RUNS)`) in any phase of the compressed ramp more than the
# bare load + 8, or either wrapped in `Buffered` (and the axis) more than
# the same; or when the step interrupt (SysTick's handler, from its vector
# to its return, the pin's toggle included, the pin pulsed before the step
# so that every edge is at its time to the tick) takes more than 20 on the
# M3 or the M4F, as written by hand or as an RTIC 2 task
# (src/bin/rtic.rs) with RTIC's source-masking backend; or, with RTIC's
# BASEPRI backend, more than the hand-rolled handler + 2.1 in a phase (its
# return writes BASEPRI back: 3 instructions, one of which the task's
# layout saves; a tenth for the refills); or when `Player::fill` takes more than 6 instructions per
# period filled in any phase of the per-step table, or more than 12 in any
# phase of the compressed ramp; or when three
# `Axes` (a lead and two followers) take more per step than the player in
# the same phase of the same table plus, per follower, 5 on the M3 and
# M4F (the goal) and 7 on the M0 (a bound against regressions above the
# 6.27 measured, which is the least this step takes there: no `ldrd`/`strd`
# and three free low registers; docs/performance.md counts it); or when
# `Player::next_period` takes more per step than `Player::step` + 1 in any
# phase of the same move (the per-step table and the compressed ramp, each
# step's period into the reload register). Prints the planning calls
# (start, set_cruise, set_cruise_period, a retarget farther, one nearer
# and one 300 steps past the stop, stop on a 1000-entry table and on a
# 7192-step compressed ramp, plain and indexed), and fails when one takes
# more than 1000 instructions on the table or on the indexed ramp (the
# goal), or 18 750 on the plain compressed ramp (a bound against
# regressions, about an eighth above the largest figure measured,
# 16 659; the goal is not met without the index) on the M3 or M4F; or, on
# any core, when the step after a call on a compressed ramp (which decodes
# the plan's first run) takes more than the largest step of the compressed
# player's move; or when a line queued on three axes (`Axes::queue`,
# joined at speed to the one playing) takes more than 2000 instructions to
# plan on the M3 or M4F (the goal: the line's figures and its junction in
# fixed point, the line playing extended as a retarget extends it and
# cut), or a target queued
# on an axis the same way as the move playing more than 2000 (the goal:
# the move extended as a retarget extends it), or a queued
# polyline's steps more than the player cruising + 2 followers as above.
# Needs: the three rustup targets, rustup component llvm-tools,
# qemu-system-arm. Usage: bash measure.sh   (KEEP_LOG=1 keeps the traces;
# CORES="M3" measures one core)
set -euo pipefail
cd "$(dirname "$0")"

host=$(rustc -vV | sed -n 's/^host: //p')
tools="$(rustc --print sysroot)/lib/rustlib/$host/bin"
[ -x "$tools/llvm-nm" ] || rustup component add llvm-tools
nm="$tools/llvm-nm"
out=target/measure
mkdir -p "$out"

# One translation block per instruction: -singlestep up to QEMU 8.0,
# -accel tcg,one-insn-per-tb=on from 8.1.
version=$(qemu-system-arm --version | sed -n 's/.*version \([0-9]*\)\.\([0-9]*\).*/\1 \2/p')
read -r major minor <<<"$version"
if [ "$major" -gt 8 ] || { [ "$major" -eq 8 ] && [ "$minor" -ge 1 ]; }; then
    one_insn=(-accel tcg,one-insn-per-tb=on)
else
    one_insn=(-singlestep)
fi

read -r -a cores <<<"${CORES:-M0 M3 M4F}"
declare -A target=([M0]=thumbv6m-none-eabi [M3]=thumbv7m-none-eabi [M4F]=thumbv7em-none-eabihf)
declare -A machine=([M0]="-cpu cortex-m0 -machine microbit" [M3]="-cpu cortex-m3 -machine lm3s6965evb"
    [M4F]="-cpu cortex-m4 -machine mps2-an386")

# One `Trace` line per instruction: `Trace 0: HOST [../PC/../..] SYMBOL`.
# Between the markers, a call runs from one entry of a measured function
# to the next; lines of the calling loop's own function are not counted.
# The first stretch is the bare load (or `bare`, given): a call above its
# cost + 8 is slow. Usage: count ENTRIES LOG [BARE]
count() {
    awk -v entries="$1" -v bare="${3:-0}" '
        function close_call() {
            if (cur >= 0) { if (cur < lo) lo = cur; if (cur > hi) hi = cur
                            if (bare && cur > bare + 8) slow++ }
            cur = -1
        }
        /^Trace/ {
            split($4, f, "/"); pc = f[2]; sym = $5
            if (sym ~ /^measure_begin/) { inside = 1; body = 0; calls = 0; caller = "";
                                          cur = -1; lo = 1e18; hi = 0; slow = 0; next }
            if (!inside) next
            if (sym ~ /^measure_end/) { close_call(); inside = 0; if (!bare) bare = hi
                                        print body, calls, lo, hi, slow; next }
            if (caller == "") caller = sym
            if (index(" " entries, " " pc " ")) { close_call(); cur = 0; calls++ }
            if (sym != caller) { body++; if (cur >= 0) cur++ }
        }' "$2"
}

# Runs ELF on CORE in QEMU with the instruction trace; its `measure:` lines
# (label|count|unit: a fill's figure is per period, not per call) to
# OUT.labels and its counts (BARE as for `count`) to OUT.counts.
# Usage: trace CORE ELF OUT [BARE]
trace() {
    local entries
    # Entry addresses of the measured functions, as the trace prints them.
    entries=$("$nm" "$2" | awk '$3 ~ /^(bare|iter|player|stepgen|axis|axes|buffered)_[a-z_]+$|^SysTick$/ { printf "%s ", $1 }')
    # shellcheck disable=SC2086
    timeout 600 qemu-system-arm ${machine[$1]} -nographic -semihosting-config enable=on,target=native \
        "${one_insn[@]}" -d exec,nochain -D "$3.log" -kernel "$2" >"$3.txt" 2>"$3.err"
    grep -q '^ok' "$3.txt" || { cat "$3.txt"; exit 1; }
    sed -n 's/^measure: \(.*\): \([0-9]*\) \(steps\|call\|periods\)$/\1|\2|\3/p' "$3.txt" >"$3.labels"
    count "$entries" "$3.log" "${4:-0}" >"$3.counts"
    [ "${KEEP_LOG:-0}" = 1 ] || rm -f "$3.log"
}

for core in "${cores[@]}"; do
    t=${target[$core]}
    cargo build --release --quiet --target "$t" --bin stepper-profiles-measure
    elf=target/$t/release/stepper-profiles-measure
    trace "$core" "$elf" "$out/$core"
    # The step interrupt as an RTIC task on the M3 and M4F, with each of
    # RTIC's backends there, its rows after the main binary's, slow against
    # the same bare load.
    if [ "$core" != M0 ]; then
        bare=$(awk 'NR == 1 { print $4 }' "$out/$core.counts")
        for backend in masking basepri; do
            cargo build --release --quiet --target "$t" --bin rtic --no-default-features \
                --features "rtic-$backend"
            cp "target/$t/release/rtic" "$out/$core.rtic-$backend.elf"
            trace "$core" "$out/$core.rtic-$backend.elf" "$out/$core.rtic-$backend" "$bare"
            cat "$out/$core.rtic-$backend.labels" >>"$out/$core.labels"
            cat "$out/$core.rtic-$backend.counts" >>"$out/$core.counts"
        done
    fi
    paste -d'|' "$out/$core.labels" "$out/$core.counts" >"$out/$core.rows"
    # The player's code: its functions and the step functions that call it.
    "$nm" -S -C --radix=d "$elf" | awk '$3 ~ /^[tT]$/ && /profile_core::player|player_(step|runs_step|start|stop|set_cruise)$/ { s += $2 }
        END { print s }' >"$out/$core.flash"
done

echo "instructions per step: mean (max) [steps above the bare load + 8], step function and callees;"
echo "Player::fill: instructions per period filled (the largest call) [calls]"
printf "%-58s" "step function"
for core in "${cores[@]}"; do printf " %20s" "$core"; done
echo
status=0
# The most instructions per step of the step interrupt on the M3 and M4F.
handler_most=20
while IFS='|' read -r label _; do
    printf "%-58s" "$label"
    for core in "${cores[@]}"; do
        awk -F'|' -v l="$label" '$1 == l { split($4, c, " "); found = 1
            if ($3 == "periods") printf " %20s", sprintf("%.2f (%d) [%d]", c[1] / $2, c[4], c[2])
            else printf " %20s", sprintf("%.2f (%d) [%d]", c[1] / c[2], c[4], c[5]) }
            END { if (!found) printf " %20s", "-" }' "$out/$core.rows"
    done
    echo
done <"$out/M3.rows"
echo
printf "%-58s" "flash of the player module in this firmware (every type measured), bytes"
for core in "${cores[@]}"; do printf " %20s" "$(cat "$out/$core.flash")"; done
echo

# The goals: the player's mean in every phase of the per-step table within
# the bare load + 4, the compressed player's on runs within the bare load + 8,
# Buffered alike, the step interrupt within 20 instructions a step.
for core in "${cores[@]}"; do
    awk -F'|' -v core="$core" -v handler="$handler_most" '
        { split($4, c, " "); mean[$1] = $3 == "periods" ? c[1] / $2 : c[1] / c[2]; largest[$1] = c[4] }
        END {
            bare = mean["bare load, PERIODS[i] (sigmoid_exact)"]
            for (l in mean) {
                limit = l ~ /^player, per-step table/ ? 4 : l ~ /^compressed Player/ ? 8 : -1
                if (limit >= 0 && mean[l] > bare + limit) {
                    printf "FAIL %s: %s %.2f instructions per step, more than the bare load %.2f + %d\n", core, l, mean[l], bare, limit
                    bad = 1
                }
                if (l ~ /^axes, 3 \(1 lead \+ 2 followers\)/) {
                    phase = l; sub(/.* /, "", phase)
                    base = mean["player, per-step table (sigmoid_exact) " phase]
                    per = core == "M0" ? 7 : 5
                    if (mean[l] > base + 2 * per) {
                        printf "FAIL %s: %s %.2f instructions per step, more than the player %.2f + 2 followers x %s\n", core, l, mean[l], base, per
                        bad = 1
                    }
                }
                # The lines of a queued polyline (joined at speed at each
                # vertex): the same step path, within the player cruising
                # + 2 followers, as three axes on one move.
                if (l ~ /^axes, 3, queued polyline \(per-step table\)/) {
                    base = mean["player, per-step table (sigmoid_exact) cruising"]
                    per = core == "M0" ? 7 : 5
                    if (mean[l] > base + 2 * per) {
                        printf "FAIL %s: %s %.2f instructions per step, more than the player %.2f + 2 followers x %s\n", core, l, mean[l], base, per
                        bad = 1
                    }
                }
                # next_period: the step path of the same player, the
                # period returned; within the mean of the step + 1, phase
                # by phase, on the same move.
                if (l ~ /^next_period, /) {
                    step = l; sub(/^next_period, /, "", step)
                    if (step ~ /^per-step table/) step = "player, " step
                    if (!(step in mean)) {
                        printf "FAIL %s: %s has no step row to compare with (%s)\n", core, l, step
                        bad = 1
                    } else if (mean[l] > mean[step] + 1 + 1e-6) {
                        printf "FAIL %s: %s %.2f instructions per step, more than the step %.2f + 1\n", core, l, mean[l], mean[step]
                        bad = 1
                    }
                }
                # Buffered: the step path of the player it wraps.
                limit = l ~ /^Buffered(,| axis,) per-step table/ ? 4 : l ~ /^Buffered compressed Player/ ? 8 : -1
                if (limit >= 0 && mean[l] > bare + limit) {
                    printf "FAIL %s: %s %.2f instructions per step, more than the bare load %.2f + %.1f\n", core, l, mean[l], bare, limit
                    bad = 1
                }
                # Planning, one call: the goal of 1000 on the table and on
                # the indexed ramp; on the plain compressed ramp a bound
                # against regressions at the figures measured (the goal is
                # not met without the index).
                if (l ~ /^planning, / && l !~ /the step after/ && core != "M0") {
                    most_plan = l ~ /indexed compressed/ ? 1000 : l ~ /compressed/ ? 18750 : l ~ /^planning, queue, ax/ ? 2000 : 1000
                    if (mean[l] > most_plan) {
                        printf "FAIL %s: %s %.0f instructions, more than %d\n", core, l, mean[l], most_plan
                        bad = 1
                    }
                }
                # The step after a call on a compressed ramp takes the
                # first run of the plan, as a step does at the end of every
                # run: no more than the largest step of the compressed
                # player on its move.
                if (l ~ /the step after/) {
                    refill = largest["compressed Player (microstep, compress = 1) accelerating"]
                    down = largest["compressed Player (microstep, compress = 1) decelerating"]
                    if (down > refill) refill = down
                    if (mean[l] > refill) {
                        printf "FAIL %s: %s %.0f instructions, more than the largest step of the compressed player, %d\n", core, l, mean[l], refill
                        bad = 1
                    }
                }
                # The step interrupt, from the SysTick vector to its return.
                if (l ~ /^handler/ && l !~ /BASEPRI/ && core != "M0" && mean[l] > handler) {
                    printf "FAIL %s: %s %.2f instructions per step, more than %d\n", core, l, mean[l], handler
                    bad = 1
                }
                # As an RTIC task with the BASEPRI backend: the same step and
                # RTIC'"'"'s return (BASEPRI written back: movs, msr, isb), less
                # the load the task'"'"'s layout saves: 2 a step over the
                # hand-rolled handler, and a few more at the rare refills (a
                # tenth at most over a phase). With source masking, within 20.
                if (l ~ /^handler, RTIC task \(BASEPRI/) {
                    phase = l; sub(/.* /, "", phase)
                    base = mean["handler, Buffered per-step table (SysTick vector to return) " phase]
                    if (mean[l] > base + 2.1) {
                        printf "FAIL %s: %s %.2f instructions per step, more than the hand-rolled handler %.2f + 2.1\n", core, l, mean[l], base
                        bad = 1
                    }
                }
                most = l ~ /^Player::fill, per-step table/ ? 6 : l ~ /^Player::fill, compressed/ ? 12 : -1
                if (most >= 0 && mean[l] > most) {
                    printf "FAIL %s: %s %.2f instructions per period filled, more than %s\n", core, l, mean[l], most
                    bad = 1
                }
            }
            exit bad
        }' "$out/$core.rows" || status=1
done
[ "$status" = 0 ] && echo "ok: on every core the player's per-step mean is within the bare load + 4, the compressed player's within the bare load + 8 (Buffered the same), the step interrupt within 20 on the M3 and M4F (as an RTIC task too, with source masking; with BASEPRI within the hand-rolled handler + 2.1), Player::next_period within Player::step + 1, Player::fill takes at most 6 instructions per period of the per-step table, 12 of compressed runs, three Axes within the player + 2 x 5 (M0: 2 x 7), planning within 1000 on the table and on the indexed ramp, 18750 on the plain compressed ramp, 2000 for a target queued on an axis and for a line queued on three axes (M3, M4F), a queued polyline's steps within the player + 2 followers, the step after a call on a compressed ramp within the compressed player's largest step"
exit "$status"
