#!/usr/bin/env bash
# The rhs of the programs `kane code` writes, timed per call at each model's INPUT state in its
# own runtime (C by gcc -O2, Fortran by gfortran -O2, Python 3 with NumPy, GNU Octave), beside the Rust rhs the simulator
# compiles (criterion's `rhs_call/*/compiled` of gyro-sim's engines bench), the runtimes taking
# turns, three rounds. Prints one line per model, language and round: nanoseconds per call.
# Usage: kane-model/benches/standalone/rhs_per_call.sh [WORK_DIR]   (needs gcc, gfortran, python3, octave-cli)
set -euo pipefail
cd "$(dirname "$0")/../../.."
work=${1:-$(mktemp -d)}
mkdir -p "$work"
cargo build --release -q -p kane-model --bin kane
kane=target/release/kane
models="gimbal=kane-model/models/gimbal_gyroscope.al bicycle=kane-model/models/whipple_bicycle.al four_bar=kane-model/models/four_bar.al chain40=gyro-sim/tests/data/chain40_rigid.al"

for entry in $models; do
  name=${entry%%=*}; file=${entry#*=}
  $kane code "$file" --lang c -o "$work/$name.c" >/dev/null
  $kane code "$file" --lang fortran -o "$work/${name}_f.f90" >/dev/null
  $kane code "$file" --lang python -o "$work/${name}_py.py" >/dev/null
  $kane code "$file" --lang matlab -o "$work/${name}_m.m" >/dev/null
  id=$(grep -o 'void [a-z0-9_]*_rhs' "$work/$name.c" | head -1 | sed 's/void //; s/_rhs$//')
  # The C rhs called from a loop that tells the compiler the state and result may change between
  # calls (as criterion's black_box does for the Rust rhs), so that no call is moved out of it.
  cat > "$work/${name}_time.c" <<C
#define main program_main
#include "$name.c"
#undef main
#include <time.h>
int main(void) {
    double k[NK], y[NY], dy[NY], sink = 0.0;
    ${id}_constants(P0, k);
    memcpy(y, Y0, sizeof y);
    long n = 2000000000L / (NY * 50 + 1000);
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long i = 0; i < n; i++) {
        ${id}_rhs(0.0, y, P0, k, dy);
        __asm__ volatile("" : : "r"(y), "r"(dy) : "memory");
        sink += dy[0];
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    printf("%.1f\n", ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / n + 0.0 * sink);
    return 0;
}
C
  gcc -O2 -o "$work/${name}_time" "$work/${name}_time.c" -lm
  cat > "$work/${name}_time.py" <<PY
import importlib.util, sys, timeit
spec = importlib.util.spec_from_file_location("m", "$work/${name}_py.py")
m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)
k = m.constants(m.P0)
n, t = timeit.Timer(lambda: m.rhs(0.0, m.Y0, m.P0, k)).autorange()
print(f"{t / n * 1e9:.1f}")
PY
  # Fortran: the program's declarations and its constants and rhs under a main program that
  # times rhs as the C loop does.
  python3 - "$work" "$name" <<'PY'
import sys
work, name = sys.argv[1], sys.argv[2]
text = open(f"{work}/{name}_f.f90").read()
head = text[:text.index("      real(8) :: p(max(np, 1))")]
procedures = text[text.index("! The parameter-only quantities of p"):text.index("! One written row after t")]
main = """      real(8) :: k(nk), y(ny), dy(ny), sink
      integer(8) :: n, i, c0, c1, rate
      call constants(p0, k)
      y = y0
      sink = 0d0
      n = 2000000000_8 / (ny * 50 + 1000)
      call system_clock(c0, rate)
      ! Every state moved and every result summed, so that no call
      ! (and no part of one) is moved out of the loop or left out.
      do i = 1, n
        y = y0 + 1d-300 * dble(i)
        call rhs(0d0, y, p0, k, dy)
        sink = sink + sum(dy)
      end do
      call system_clock(c1)
      write (*, '(f0.1)') dble(c1 - c0) / dble(rate) * 1d9 / dble(n)
     &  + 0d0 * sink
      contains
"""
open(f"{work}/{name}_ftime.f", "w").write(head + main + procedures + f"      end program {name}_f\n")
PY
  gfortran -O2 -o "$work/${name}_ftime" "$work/${name}_ftime.f"
  # Octave: the program's subfunctions under a main function that times rhs.
  python3 - "$work" "$name" <<'PY'
import re, sys
work, name = sys.argv[1], sys.argv[2]
text = open(f"{work}/{name}_m.m").read()
values = re.search(r"^p = .*?;$", text, re.M).group(0) + "\n" + re.search(r"^y0 = .*?;$", text, re.M).group(0)
subfunctions = text[text.index("\nfunction k = constants(p)"):]
main = f"""function ns = {name}_time()
{values}
k = constants(p);
n = 0; started = tic;
while toc(started) < 1
  for i = 1:100
    dy = rhs(0, y0, p, k);
  end
  n = n + 100;
end
ns = toc(started) / n * 1e9;
printf('%.1f\\n', ns);
end
"""
open(f"{work}/{name}_time.m", "w").write(main + subfunctions)
PY
done

for round in 1 2 3; do
  for entry in $models; do
    name=${entry%%=*}
    echo "$name C round $round: $("$work/${name}_time") ns"
    echo "$name Fortran round $round: $("$work/${name}_ftime") ns"
    echo "$name Python round $round: $(python3 "$work/${name}_time.py") ns"
    echo "$name Octave round $round: $(cd "$work" && octave-cli --quiet --norc --eval "${name}_time;" 2>/dev/null) ns"
    ns=$(cargo bench -q -p gyro-sim --bench engines -- "rhs_call/$name/compiled\$" --warm-up-time 1 --measurement-time 2 2>/dev/null \
      | grep -A1 "rhs_call/$name/compiled" | grep -o 'time: *\[[^]]*\]' | awk '{print $4, $5}')
    echo "$name Rust (compiled) round $round: $ns"
  done
done
