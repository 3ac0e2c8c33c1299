#!/usr/bin/env bash
# Figures of the firmware on a Cortex-M3 (QEMU lm3s6965evb), all measured
# here and deterministic:
#   - flash and RAM of the firmware (llvm-size), its stack high-water mark
#     (the firmware paints its stack and reports), and the same for a build
#     that only plays tables (`--features measure`);
#   - the flash of each table (symbol sizes, llvm-nm);
#   - instructions per step of the step interrupt, Player::next_period against
#     a bare table load, counted in QEMU's instruction trace between the
#     firmware's `measure_begin` and `measure_end` markers.
# Needs: rustup target thumbv7m-none-eabi, rustup component llvm-tools,
# qemu-system-arm. Usage: bash measure.sh   (KEEP_LOG=1 keeps the trace)
set -euo pipefail
cd "$(dirname "$0")"

host=$(rustc -vV | sed -n 's/^host: //p')
tools="$(rustc --print sysroot)/lib/rustlib/$host/bin"
if [ ! -x "$tools/llvm-size" ]; then
    rustup component add llvm-tools
fi
size="$tools/llvm-size"
nm="$tools/llvm-nm"
elf=target/thumbv7m-none-eabi/release/stepper-profiles-firmware
out=target/measure
mkdir -p "$out"
qemu=(qemu-system-arm -cpu cortex-m3 -machine lm3s6965evb -nographic
    -semihosting-config enable=on,target=native)

# One translation block per instruction: -singlestep up to QEMU 8.0,
# -accel tcg,one-insn-per-tb=on from 8.1.
version=$(qemu-system-arm --version | sed -n 's/.*version \([0-9]*\)\.\([0-9]*\).*/\1 \2/p')
read -r major minor <<<"$version"
if [ "$major" -gt 8 ] || { [ "$major" -eq 8 ] && [ "$minor" -ge 1 ]; }; then
    one_insn=(-accel tcg,one-insn-per-tb=on)
else
    one_insn=(-singlestep)
fi

# flash = .vector_table + .text + .rodata + .data; static RAM = .data + .bss.
sizes() {
    "$size" "$elf" | awk 'NR == 2 { printf "flash %d bytes, static RAM %d bytes", $1 + $2, $2 + $3 }'
}

# --- The measured build: only the step loops, under the instruction trace.
echo "== instructions per step (cargo build --release --features measure; QEMU trace)"
cargo build --release --quiet --features measure
measure_sizes=$(sizes)
# Entry addresses of the interrupt functions (bare_interrupt, iter_interrupt,
# step_interrupt), as the trace prints program counters.
entries=$("$nm" "$elf" | awk '$3 ~ /^[a-z]+_interrupt$/ { printf "%s ", $1 }')
timeout 300 "${qemu[@]}" "${one_insn[@]}" -d exec,nochain -D "$out/exec.log" \
    -kernel "$elf" >"$out/measure.txt" 2>"$out/qemu.err"
grep -q '^ok:' "$out/measure.txt" || { cat "$out/measure.txt"; exit 1; }
mapfile -t labels < <(sed -n 's/^measure: //p' "$out/measure.txt")

# One `Trace` line per executed instruction: `Trace 0: HOST [../PC/../..] SYMBOL`.
# Between the markers, lines in the calling loop's function are the loop;
# the rest is the interrupt function and what it calls. A call runs from one
# entry of the interrupt function to the next.
awk -v entries="$entries" '
    function close_call() {
        if (cur >= 0) { if (cur < lo) lo = cur; if (cur > hi) hi = cur }
        cur = -1
    }
    /^Trace/ {
        split($4, f, "/"); pc = f[2]; sym = $5
        if (sym ~ /^measure_begin/) { inside = 1; all = 0; body = 0; calls = 0;
                                      caller = ""; cur = -1; lo = 1e18; hi = 0; next }
        if (!inside) next
        if (sym ~ /^measure_end/) { close_call(); inside = 0;
                                    print all, body, calls, lo, hi; next }
        all++
        if (caller == "") caller = sym
        if (index(" " entries, " " pc " ")) { close_call(); cur = 0; calls++ }
        if (sym != caller) { body++; if (cur >= 0) cur++ }
    }' "$out/exec.log" >"$out/counts.txt"
[ "${KEEP_LOG:-0}" = 1 ] || rm -f "$out/exec.log"

printf "%-62s %6s %10s %10s %9s\n" "step loop" "steps" "interrupt" "min..max" "with loop"
i=0
while read -r all body calls lo hi; do
    label=${labels[$i]%: *}
    awk -v l="$label" -v all="$all" -v body="$body" -v n="$calls" -v lo="$lo" -v hi="$hi" \
        'BEGIN { printf "%-62s %6d %10.2f %10s %9.2f\n", l, n, body / n, lo ".." hi, all / n }'
    i=$((i + 1))
done <"$out/counts.txt"
echo "(instructions per step: 'interrupt' counts the interrupt function and its callees,"
echo " 'with loop' adds the loop and call that stand in for the interrupt's entry)"

# --- The firmware itself.
echo
echo "== firmware (cargo run --release): sizes and run"
cargo build --release --quiet
timeout 300 cargo run --release --quiet >"$out/run.txt" 2>/dev/null || {
    cat "$out/run.txt"
    exit 1
}
echo "firmware:                $(sizes)"
echo "  $(grep '^stack:' "$out/run.txt")"
echo "  $(tail -n 1 "$out/run.txt")"
echo "player-only build:       $measure_sizes (--features measure: 3 tables, no run-time generation)"

echo
echo "== tables in flash (llvm-nm --size-sort, bytes)"
"$nm" --size-sort -S -C --radix=d "$elf" |
    awk '$4 ~ /(PERIODS|SEGMENTS)::h|DECEL::h|SEED::h/ {
        name = $4; sub(/::h[0-9a-f]+$/, "", name); sub(/^stepper_profiles_firmware::/, "", name)
        sub(/^profiles::/, "", name)
        printf "  %-36s %6d\n", name, $2; total += $2
    } END { printf "  %-36s %6d\n", "all tables", total }'

echo
echo "== firmware flash by symbol name (approximate: inlined code counts where it lands)"
flash=$("$size" "$elf" | awk 'NR == 2 { print $1 + $2 }')
"$nm" -S -C --radix=d "$elf" |
    awk -v flash="$flash" 'NF >= 4 && $3 ~ /^[tTrRdD]$/ {
        n = substr($0, index($0, $4)); c = 6
        if (n ~ /(PERIODS|SEGMENTS)::h|DECEL::h|SEED::h/) c = 1
        else if (n ~ /profile_core..player|profile_core::player|^step_interrupt$/) c = 2
        else if (n ~ /profile_core/) c = 3
        else if (n ~ /^libm::|compiler_builtins::float|^__aeabi_[dfi]|^__aeabi_ui2|^__aeabi_ul2|^__fix/) c = 4
        else if (n ~ /fmt|flt2dec|core::num|unicode|semihosting/) c = 5
        s[c] += $2
    } END {
        split("tables|Player (next_period, start, stop)|profile_core generation and validation (Spec::generate)|libm and soft float|core::fmt and semihosting|the rest (checks, runtime, constants)", name, "|")
        s[6] = flash - s[1] - s[2] - s[3] - s[4] - s[5]
        for (c = 1; c <= 6; c++) printf "  %-58s %6d\n", name[c], s[c]
        printf "  %-58s %6d\n", "flash", flash
    }'
