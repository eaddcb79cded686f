#!/usr/bin/env bash
# Executed instructions per call of the attitude updates on the emulated
# Cortex-M4F (mps2-an386): builds src/bin/filter_cost.rs, runs it in QEMU
# with every executed instruction traced, and counts the trace lines between
# the marker functions of each bracket, minus the empty bracket's.
set -euo pipefail
cd "$(dirname "$0")"
features=${1:-}
cargo build --quiet --release --target thumbv7em-none-eabihf --bin filter_cost ${features:+--features "$features"}
elf=target/thumbv7em-none-eabihf/release/filter_cost
trace=$(mktemp)
trap 'rm -f "$trace"' EXIT
timeout 300 qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic -monitor none \
    -semihosting-config enable=on,target=native -singlestep -d exec,nochain -D "$trace" -kernel "$elf"
address() { # the symbol's address, Thumb bit cleared, as QEMU prints it
    local value
    value=$(readelf -sW "$elf" | awk -v s="$1" '$8 == s { print $2; exit }')
    printf '%08x\n' $((0x$value & ~1))
}
open=$(address cost_open)
close=$(address cost_close)
awk -v open="$open" -v shut="$close" '
    # A trace line reads: Trace 0: 0x... [00000000/PC/...] ...
    match($0, /\[[0-9a-f]+\/[0-9a-f]+\//) {
        pc = substr($0, RSTART + 10, 8)
        if (pc == open) { inside = 1; n = 0; next }
        if (pc == shut && inside) { counts[k++] = n; inside = 0; next }
        if (inside) n++
    }
    END {
        split("empty bracket,OrientationFilter::update (6D),OrientationFilter::update_with_mag (9D),Quat::integrate,Smoother::update", names, ",")
        for (i = 0; i < k; i++) printf "%-42s %6d instructions\n", names[i + 1], counts[i] - (i ? counts[0] : 0)
    }' "$trace"
