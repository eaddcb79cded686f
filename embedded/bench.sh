#!/usr/bin/env bash
# Instructions per call and flash bytes per operation, on an emulated
# Cortex-M4F (QEMU mps2-an386), for rigtform and its peers (glam and
# nalgebra built with libm, micromath): prints a Markdown table.
#
#   embedded/bench.sh            # both tables (about 10 minutes: 68 small builds)
#   embedded/bench.sh count      # instruction counts only (a minute)
#   embedded/bench.sh budget     # the counts, then fails unless slerp keeps
#                                # to issue 5's targets: 400 instructions
#                                # and 2 KiB of flash at opt-level "s"
#
# Instructions: src/bin/bench.rs brackets each call between two marker
# functions; QEMU logs every executed instruction (-singlestep -d
# exec,nochain), and the awk below counts those between the markers, less
# the same bracket around `ops::empty` on the same input. The mean over the
# bench's inputs is printed (counts differ by input where code branches).
#
# Flash: src/bin/size.rs calls one operation; its size (llvm-size: text +
# data) less that of the same firmware calling `ops::empty`, at opt-level
# "s" and 3 (LTO, one codegen unit), is what the operation costs with all it
# pulls in.
set -euo pipefail
cd "$(dirname "$0")"

TARGET=thumbv7em-none-eabihf
MODE=${1:-all}
case $MODE in
    all | count | budget) ;;
    *) echo "usage: $0 [all|count|budget]" >&2; exit 2 ;;
esac
rustup component add llvm-tools >/dev/null 2>&1 || true
TOOLS="$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin"
NM="$TOOLS/llvm-nm"
SIZE="$TOOLS/llvm-size"
[ -x "$SIZE" ] || { echo "error: llvm-size not found in $TOOLS (rustup component add llvm-tools)" >&2; exit 1; }
command -v qemu-system-arm >/dev/null || { echo "error: qemu-system-arm not found (apt-get install qemu-system-arm)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# --- instructions per call -------------------------------------------------
cargo build --quiet --release --target "$TARGET" --features peers --bin bench
elf="target/$TARGET/release/bench"
"$NM" "$elf" | grep -qE ' bench_start$' || { echo "error: no bench_start in $elf" >&2; exit 1; }
qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic -monitor none \
    -semihosting-config enable=on,target=native -singlestep -d exec,nochain \
    -D "$work/trace.log" -kernel "$elf" > "$work/stdout"
grep -q '^bench done' "$work/stdout" || { echo "error: the bench did not finish:" >&2; cat "$work/stdout" >&2; exit 1; }

# Counts of the instructions between the markers, one per bracket, in order.
awk '
    { sym = $NF }
    sym == "bench_start" { open = 1; n = 0; next }
    open && sym == "bench_end" { print n; open = 0; next }
    open { n++ }
' "$work/trace.log" > "$work/counts"

# Pair them with the operations the bench announced: per input, the empty
# bracket, then the operation's.
awk -v inputs="$(sed -n 's/^bench inputs //p' "$work/stdout")" '
    NR == FNR { if ($0 ~ /^bench op /) { sub(/^bench op /, ""); names[++ops] = $0 } next }
    { counts[++c] = $1 }
    END {
        if (c != 2 * inputs * ops) { print "error: " c " brackets for " ops " operations" > "/dev/stderr"; exit 1 }
        for (i = 1; i <= ops; i++) {
            sum = 0
            for (j = 0; j < inputs; j++) {
                k = 2 * (inputs * (i - 1) + j)
                sum += counts[k + 2] - counts[k + 1]
            }
            printf "%s|%.0f\n", names[i], sum / inputs
        }
    }
' "$work/stdout" "$work/counts" > "$work/instructions"

# --- flash bytes per operation ---------------------------------------------
size_of() { # opt-level, function of src/ops.rs
    local dir="target/size-$1"
    RIGTFORM_SIZE_OP="$2" CARGO_PROFILE_RELEASE_OPT_LEVEL="$1" CARGO_TARGET_DIR="$dir" \
        cargo build --quiet --release --target "$TARGET" --features peers --bin size
    "$SIZE" "$dir/$TARGET/release/size" | awk 'NR == 2 { print $1 + $2 }'
}

# (operation|library|function) from the table in src/ops.rs.
sed -n 's/^ *("\([^"]*\)", "\([^"]*\)", \([a-z_0-9]*\)),$/\1|\2|\3/p' src/ops.rs > "$work/ops"

: > "$work/flash"
if [ "$MODE" = all ]; then
    for level in s 3; do
        base=$(size_of "$level" empty)
        while IFS='|' read -r operation library function; do
            bytes=$(size_of "$level" "$function")
            echo "$operation|$library|$level|$((bytes - base))" >> "$work/flash"
        done < "$work/ops"
    done
fi

# --- the table ---------------------------------------------------------------
echo "| operation | library | instructions per call | flash bytes, opt-level \"s\" | flash bytes, opt-level 3 |"
echo "| --- | --- | --- | --- | --- |"
awk -F'|' '
    FILENAME == ARGV[1] { flash[$1 "|" $2 "|" $3] = $4; next }
    {
        s = flash[$1 "|" $2 "|s"]; o3 = flash[$1 "|" $2 "|3"]
        printf "| %s | %s | %s | %s | %s |\n", $1, $2, $3, (s == "" ? "-" : s), (o3 == "" ? "-" : o3)
    }
' "$work/flash" "$work/instructions"

# --- slerp's budget ------------------------------------------------------------
if [ "$MODE" = budget ]; then
    base=$(size_of s empty)
    bytes=$(( $(size_of s rigtform_slerp) - base ))
    calls=$(awk -F'|' '$1 == "slerp" && $2 == "rigtform" { print $3 }' "$work/instructions")
    echo "slerp on the Cortex-M4F: $calls instructions per call (budget 400), $bytes bytes of flash at opt-level \"s\" (budget 2048)"
    if [ -z "$calls" ] || [ "$calls" -gt 400 ] || [ "$bytes" -gt 2048 ]; then
        echo "error: slerp is over its budget" >&2
        exit 1
    fi
fi
