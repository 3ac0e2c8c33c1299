#!/usr/bin/env bash
# What include_profiles! costs at build time, against the same tables written
# as literal arrays. Prints the figures and their ratios.
#
#   bash scripts/build-cost.sh
#
# Two scratch crates in target/build-cost/: `with-macro` declares 20 profiles
# of 1000 entries through include_profiles!; `literal` holds the very source
# the macro expands to, pasted in. Each is built clean (debug, dependencies
# included, as a firmware build from scratch), then rebuilt after touching
# its source (the build a user waits for while editing). A third crate
# expands the largest table allowed (65 536 entries) with period_table!.
set -euo pipefail
command -v bc >/dev/null && [ -x /usr/bin/time ] || {
    echo "needs bc and GNU time: apt-get install -y bc time" >&2
    exit 1
}
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$root/target/build-cost"
rm -rf "$work"
mkdir -p "$work"

# 20 profiles: sigmoids, exponentials and linear ramps of 1000 entries.
toml="$work/profiles.toml"
{
    echo '[defaults]'
    echo 'timer_hz = 10_000_000'
    for i in $(seq 1 7); do
        printf '\n[profiles.sigmoid_%d]\ncurve = "sigmoid"\nlen = 1000\nfmin = %d\nfmax = 64000\nflexible = %d\n' "$i" $((400 + 10 * i)) $((2 + i))
    done
    for i in $(seq 1 7); do
        printf '\n[profiles.exponential_%d]\ncurve = "exponential"\nlen = 1000\nfmin = %d\nfmax = 20000\nf_inf = 25000\n' "$i" $((400 + 10 * i))
    done
    for i in $(seq 1 6); do
        printf '\n[profiles.linear_%d]\ncurve = "linear"\nlen = 1000\nfmin = %d\nfmax = 30000\n' "$i" $((400 + 10 * i))
    done
} > "$toml"

(cd "$root" && cargo run -q -p stepper-profiles-cli -- rust "$toml") > "$work/expanded.rs"

make_crate() { # name, main.rs body, dependency line
    mkdir -p "$work/$1/src"
    cat > "$work/$1/Cargo.toml" <<TOML
[package]
name = "$1"
version = "0.0.0"
edition = "2024"
publish = false

[workspace]

[dependencies]
$3
TOML
    printf '%s\n' "$2" > "$work/$1/src/main.rs"
}

dep="stepper-profiles = { path = \"$root\" }"
cp "$toml" "$work/profiles.toml.bak"
make_crate with-macro 'stepper_profiles::include_profiles!("../profiles.toml");
fn main() { println!("{}", sigmoid_1::PERIODS[0] as u64 + linear_6::TOTAL_TICKS); }' "$dep"
make_crate literal "$(cat "$work/expanded.rs")
fn main() { println!(\"{}\", sigmoid_1::PERIODS[0] as u64 + linear_6::TOTAL_TICKS); }" ""
make_crate largest 'static T: [u32; 65536] = stepper_profiles::period_table!(
    curve = sigmoid, len = 65536, fmin = 500, fmax = 64000, flexible = 8,
    timer_hz = 100_000_000, word = u32);
fn main() { println!("{}", T[0]); }' "$dep"
make_crate largest-literal "static T: [u32; 65536] = $(cd "$root" && printf '[defaults]\n[profiles.t]\ncurve = "sigmoid"\nlen = 65536\nfmin = 500\nfmax = 64000\nflexible = 8\ntimer_hz = 100_000_000\nword = "u32"\n' > "$work/largest.toml" && cargo run -q -p stepper-profiles-cli -- rust "$work/largest.toml" | sed -n 's/^    pub static PERIODS: \[u32; 65536\] = \(.*\);$/\1/p');
fn main() { println!(\"{}\", T[0]); }" ""

# Wall time of a command in a directory; its peak resident memory (of the
# largest process, rustc) goes to $work/peak-kb.
seconds() { # dir, command...
    local dir=$1; shift
    local start end
    start=$(date +%s.%N)
    (cd "$dir" && /usr/bin/time -f '%M' -o "$work/peak-kb" "$@" >/dev/null 2>&1)
    end=$(date +%s.%N)
    echo "$end - $start" | bc
}

export CARGO_TARGET_DIR
for c in with-macro literal largest largest-literal; do
    CARGO_TARGET_DIR="$work/$c/target"
    clean=$(seconds "$work/$c" cargo build)
    touch "$work/$c/src/main.rs" "$toml"
    rebuild=$(seconds "$work/$c" cargo build)
    printf -v "peak_${c//-/_}" '%s' "$(cat "$work/peak-kb")"
    printf -v "clean_${c//-/_}" '%s' "$clean"
    printf -v "rebuild_${c//-/_}" '%s' "$rebuild"
done

ratio() { echo "scale=2; $1 / $2" | bc; }
echo "Build cost of 20 profiles x 1000 entries (cargo build, debug):"
printf '  %-34s %8.2f s clean, %6.2f s rebuild\n' "include_profiles!" "$clean_with_macro" "$rebuild_with_macro"
printf '  %-34s %8.2f s clean, %6.2f s rebuild\n' "literal arrays" "$clean_literal" "$rebuild_literal"
printf '  ratio macro / literal: %s clean, %s rebuild\n' "$(ratio "$clean_with_macro" "$clean_literal")" "$(ratio "$rebuild_with_macro" "$rebuild_literal")"
echo "Largest table, 65536 entries (period_table!, unoptimised proc macro):"
printf '  %-34s %8.2f s clean, %6.2f s rebuild\n' "period_table!" "$clean_largest" "$rebuild_largest"
printf '  %-34s %8.2f s clean, %6.2f s rebuild\n' "literal array" "$clean_largest_literal" "$rebuild_largest_literal"
printf '  expansion adds %.2f s to a rebuild\n' "$(echo "$rebuild_largest - $rebuild_largest_literal" | bc)"
printf '  peak memory of the rebuild: %d MiB with the macro, %d MiB for the literal\n' $((peak_largest / 1024)) $((peak_largest_literal / 1024))
