#!/usr/bin/env bash
# Right-hand sides and steps of the contact inputs against CVODE's nonlinear
# convergence coefficient (CVodeSetNonlinConvCoef; CVODE's default 0.1), the
# scan behind contact_model's contact_convergence_coefficient (docs/contact.md,
# "Corrector"). Usage: bench/convergence_scan.sh BUILD [coefficient ...]
# 1. every contact input at P1 and P2, one line per coefficient: steps,
#    right-hand sides, error-test failures, the last order;
# 2. the egg at P1 with mu and its 5 + 5 nearest floating-point neighbours
#    (mu moved by 1..5 roundings): the right-hand sides of the 11, their
#    median and mean. Adams' step count at P1 is a lottery in such
#    neighbours; median and mean are the typical cost.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
profile=$(bench_program "$1" contact_profile)
shift
coefficients=("$@")
if ((${#coefficients[@]} == 0)); then
  coefficients=(0.005 0.0075 0.01 0.0125 0.015 0.0175 0.02 0.0225 0.025 0.0275 0.03 0.035 0.04 0.05 0.07 0.1)
fi
cd "$root"
count() {  # count NAME OUTPUT: the number after NAME in contact_profile's output
  sed -n "s/.*$1 \([0-9]*\).*/\1/p" <<<"$2" | head -1
}
printf '%-22s %-3s %7s %7s %7s %5s %5s\n' case tol coef steps rhs etf order
for case in "egg 0.3" "egg 0.8" "egg_long_axis_z 0" "paraboloids 0"; do
  read -r name mu <<<"$case"
  for tol in p1 p2; do
    for c in "${coefficients[@]}"; do
      out=$("$profile" "inputs/contact/$name.nml" "$tol" "$mu" 0 "$c")
      printf '%-22s %-3s %7s %7s %7s %5s %5s\n' "$name mu=$mu" "$tol" "$c" "$(count steps "$out")" \
        "$(count ' rhs' "$out")" "$(count 'error-test failures' "$out")" "$(count 'last order' "$out")"
    done
  done
done

echo
echo "egg at P1, right-hand sides at mu and its floating-point neighbours -5 .. +5, their median and mean:"
for mu in 0.3 0.8; do
  neighbours=$(python3 -c "
import math
below, above = [$mu], [$mu]
for _ in range(5):
    below.append(math.nextafter(below[-1], 0))
    above.append(math.nextafter(above[-1], 1))
print(' '.join(repr(v) for v in below[:0:-1] + above))")
  for c in "${coefficients[@]}"; do
    counts=()
    for m in $neighbours; do
      counts+=("$(count ' rhs' "$("$profile" inputs/contact/egg.nml p1 "$m" 0 "$c")")")
    done
    median=$(printf '%s\n' "${counts[@]}" | sort -n | sed -n 6p)
    mean=$(printf '%s\n' "${counts[@]}" | awk '{s += $1} END {printf "%.0f", s / NR}')
    printf 'mu %s coef %-7s rhs %s  median %s  mean %s\n' "$mu" "$c" "${counts[*]}" "$median" "$mean"
  done
done
